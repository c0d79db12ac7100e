// The tracker's parts, one at a time: the lock state, the steady-frame policy, the frame's budgets, the
// quality scale, the search's changes applied in one place, the lock verifier, the judgement and the
// reported pose's correction by the pass's landings.
#include <gtest/gtest.h>

#include "C12Scene.h"
#include "TestSupport.h"
#include "pm/core/Hue.h"
#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/BackgroundLearning.h"
#include "pm/tracker/FramePlan.h"
#include "pm/tracker/LandingCorrection.h"
#include "pm/tracker/Judgement.h"
#include "pm/tracker/LockState.h"
#include "pm/tracker/LockVerifier.h"
#include "pm/tracker/PoseSearch.h"
#include "pm/tracker/QualityScale.h"
#include "pm/tracker/RefinementChain.h"
#include "pm/tracker/SteadyFramePolicy.h"
#include "pm/tracker/TrackerParams.h"

using pm::tracker::RmGaUpdate;
using pm::tracker::TrackState;

namespace {

using Crab = pm::test::C12Scene;
const Crab &crab() { return pm::test::c12(); }

//! The crab's fitness on its pair, and its quality scale, as the tracker makes them.
struct Scored
{
  pm::core::StereoFitness fitness;
  pm::tracker::QualityScale scale;
  explicit Scored(const Crab &c)
      : fitness(c.rig, c.sm.build.model, pm::tracker::trackerFitnessDefaults()),
        scale(c.sm.build.model, pm::tracker::trackerFitnessDefaults())
  {
    fitness.setImages(c.im.left, c.im.right);
  }
};

} // namespace

TEST(LockState, LocksLosesAfterItsFramesAndSaysWhatRmGaMustDo)
{
  pm::tracker::LockParams p; // lock at 0.35, lost under 0.2 for 3 frames
  pm::tracker::LockState s(p);
  EXPECT_EQ(s.state(), TrackState::Searching);
  EXPECT_FALSE(s.wouldLock(0.3));
  EXPECT_EQ(s.update(0.3, false), RmGaUpdate::Restart::None); // under the lock: still searching
  EXPECT_EQ(s.state(), TrackState::Searching);
  EXPECT_TRUE(s.wouldLock(0.5));
  EXPECT_EQ(s.update(0.5, true), RmGaUpdate::Restart::AwayFromBest); // a lock refused: scatter, keep searching
  EXPECT_EQ(s.state(), TrackState::Searching);
  EXPECT_EQ(s.update(0.5, false), RmGaUpdate::Restart::None);
  EXPECT_EQ(s.state(), TrackState::Tracking);
  EXPECT_EQ(s.framesTracked(), 1);
  EXPECT_FALSE(s.wouldLock(0.9)); // already tracking: no new lock
  // Two frames under lostQuality, one over: the count starts again.
  s.update(0.1, false);
  s.update(0.1, false);
  s.update(0.25, false);
  EXPECT_EQ(s.state(), TrackState::Tracking);
  EXPECT_EQ(s.framesTracked(), 4);
  s.update(0.1, false);
  s.update(0.1, false);
  EXPECT_EQ(s.update(0.1, false), RmGaUpdate::Restart::AroundBest); // the third in a row: lost, search again around the best
  EXPECT_EQ(s.state(), TrackState::Lost);
  EXPECT_EQ(s.framesTracked(), 0);
  EXPECT_EQ(s.update(0.1, false), RmGaUpdate::Restart::None); // once, when it is lost
  EXPECT_EQ(s.state(), TrackState::Lost);
  s.reset(TrackState::Tracking);
  EXPECT_EQ(s.state(), TrackState::Tracking);
  pm::tracker::LockParams bad;
  bad.lostQuality = 0.5;
  EXPECT_THROW(bad.validate(), pm::core::Error);
}

TEST(LockState, ALockNeverTrustedAndPlainlyWrongForItsFramesIsDroppedAsIfRefused)
{
  pm::tracker::LockParams p; // confidence 0.05 at the lock; dropped after 10 such frames
  pm::tracker::LockState s(p);
  s.update(0.5, false);
  ASSERT_EQ(s.state(), TrackState::Tracking);
  for (int k = 0; k < 9; ++k) { // nine frames judged plainly wrong, then one a little better: the count starts again
    s.onJudged(0.01, false);
    EXPECT_EQ(s.update(0.5, false), RmGaUpdate::Restart::None);
  }
  s.onJudged(0.2, false);
  for (int k = 0; k < 9; ++k) {
    s.onJudged(0.01, false);
    s.update(0.5, false);
    EXPECT_EQ(s.state(), TrackState::Tracking) << k;
  }
  s.onJudged(0.01, false); // the tenth judged plainly wrong: dropped on the next frame, whatever its q, as if refused
  EXPECT_EQ(s.update(0.9, false), RmGaUpdate::Restart::AwayFromBest);
  EXPECT_EQ(s.state(), TrackState::Searching);
  // A lock trusted once is never dropped this way (an occlusion may take its confidence down).
  s.update(0.5, false);
  s.onJudged(0.97, true);
  for (int k = 0; k < 30; ++k) {
    s.onJudged(0.01, false);
    EXPECT_EQ(s.update(0.5, false), RmGaUpdate::Restart::None);
  }
  EXPECT_EQ(s.state(), TrackState::Tracking);
  p.dropAfterFrames = -1;
  EXPECT_THROW(p.validate(), pm::core::Error);
}

TEST(LockState, ALockNeverTrustedAndDoubtfulForItsFramesIsDroppedTooARightOneNearTrustIsNot)
{
  pm::tracker::LockParams p; // doubtful under 0.5 for 45 judged frames in a row
  pm::tracker::LockState s(p);
  s.update(0.5, false);
  for (int k = 0; k < 44; ++k) { // a wrong lock over the gate (0.05): the plainly wrong rule never fires
    s.onJudged(k % 2 ? 0.25 : 0.4, false);
    EXPECT_EQ(s.update(0.5, false), RmGaUpdate::Restart::None) << k;
  }
  s.onJudged(0.3, false); // the 45th: dropped on the next frame, as if refused
  EXPECT_EQ(s.update(0.9, false), RmGaUpdate::Restart::AwayFromBest);
  EXPECT_EQ(s.state(), TrackState::Searching);
  // A lock whose confidence rises over 0.5 now and then (a right pose not yet trusted) is kept.
  s.update(0.5, false);
  for (int k = 0; k < 200; ++k) {
    s.onJudged(k % 40 == 39 ? 0.6 : 0.45, false);
    EXPECT_EQ(s.update(0.5, false), RmGaUpdate::Restart::None) << k;
  }
  // Nor is one trusted once, however doubtful afterwards (an occluder may take its confidence down).
  s.onJudged(0.97, true);
  for (int k = 0; k < 100; ++k) {
    s.onJudged(0.3, false);
    EXPECT_EQ(s.update(0.5, false), RmGaUpdate::Restart::None);
  }
  EXPECT_EQ(s.state(), TrackState::Tracking);
  p.doubtFrames = 0; // off
  pm::tracker::LockState never(p);
  never.update(0.5, false);
  for (int k = 0; k < 100; ++k) {
    never.onJudged(0.3, false);
    EXPECT_EQ(never.update(0.5, false), RmGaUpdate::Restart::None);
  }
  p.doubtConfidence = 0.01; // under the lock's confidence
  EXPECT_THROW(p.validate(), pm::core::Error);
}

TEST(SteadyFramePolicy, SteadyAfterItsFramesNearTheRecentBestWhichIsRememberedThroughALoss)
{
  pm::tracker::SteadyParams p; // steady after 3 frames within 0.03 of the recent best
  pm::tracker::SteadyFramePolicy s(p);
  EXPECT_FALSE(s.plan(false).steady);
  for (int k = 0; k < 3; ++k)
    s.update(TrackState::Tracking, 0.6);
  const pm::tracker::FramePlan steady = s.plan(false);
  EXPECT_TRUE(steady.steady);
  EXPECT_TRUE(steady.windowed);
  EXPECT_FALSE(s.plan(true).windowed); // the challenger searches the whole images
  EXPECT_TRUE(s.plan(true).steady);
  EXPECT_DOUBLE_EQ(s.recentBestQ(), 0.6);
  EXPECT_FALSE(s.escalates(0.58));
  EXPECT_TRUE(s.escalates(0.56)); // more than 0.03 under the recent best
  s.update(TrackState::Tracking, 0.5); // a drop: not steady any more
  EXPECT_FALSE(s.plan(false).steady);
  EXPECT_NEAR(s.recentBestQ(), 0.599, 1e-12); // forgotten at 0.001 a frame
  s.update(TrackState::Lost, 0.1);
  EXPECT_NEAR(s.recentBestQ(), 0.598, 1e-12); // remembered through a loss
  s.reset();
  EXPECT_DOUBLE_EQ(s.recentBestQ(), 0.0);
  pm::tracker::SteadyParams off = p;
  off.escalation = false;
  pm::tracker::SteadyFramePolicy noEscalation(off);
  noEscalation.update(TrackState::Tracking, 0.6);
  EXPECT_FALSE(noEscalation.escalates(0.1));
}

TEST(SteadyFramePolicy, ItsWindowsHoldTheModelAtTheLastAndThePredictedPose)
{
  const Crab &c = crab();
  pm::core::StereoFitness fitness(c.rig, c.sm.build.model);
  pm::tracker::SteadyParams p;
  pm::tracker::SteadyFramePolicy s(p);
  pm::core::Phi before = c.truth, last = c.truth;
  before.x -= 30; // moving 30 mm a frame along x: the next pose is predicted 30 mm further
  pm::tracker::TrackResult frame;
  frame.state = TrackState::Tracking;
  pm::tracker::PoseHistory history;
  frame.phi = before;
  history.remember(frame);
  frame.phi = last;
  history.remember(frame);
  pm::core::Phi next = last;
  next.x += 30;
  const auto w = s.windows(fitness.scorer(), history);
  for (int cam = 0; cam < 2; ++cam) {
    for (const pm::core::Phi &q : {last, next}) {
      const pm::core::PixelRect f = fitness.footprint(q, cam);
      EXPECT_LE(w[static_cast<std::size_t>(cam)].u0, f.u0 - (f.u0 > 0 ? std::min(p.hueMarginPx, f.u0) : 0));
      EXPECT_GE(w[static_cast<std::size_t>(cam)].u1, f.u1);
      EXPECT_LE(w[static_cast<std::size_t>(cam)].v0, f.v0);
      EXPECT_GE(w[static_cast<std::size_t>(cam)].v1, f.v1);
    }
    EXPECT_LT(w[static_cast<std::size_t>(cam)].u1 - w[static_cast<std::size_t>(cam)].u0, 640); // a window, not the image
  }
}

TEST(FramePlan, TheBudgetsSplitTheWholeOneBetweenTheSearchAndTheChallenger)
{
  pm::tracker::TrackerParams tp; // 800 evaluations, 15 % on steady frames, half to the challenger
  pm::tracker::FramePlan f;
  f.setBudgets(tp.search, tp.steady, tp.verifier);
  EXPECT_EQ(f.main.evaluations, 800);
  EXPECT_EQ(f.challenger.evaluations, 400);
  f.steady = true;
  f.setBudgets(tp.search, tp.steady, tp.verifier);
  EXPECT_EQ(f.main.evaluations, 120);
  EXPECT_EQ(f.mainWhole.evaluations, 800);
  f.verifying = true;
  f.setBudgets(tp.search, tp.steady, tp.verifier);
  EXPECT_EQ(f.main.evaluations, 120);      // the steady budget, the challenger's share on top
  EXPECT_EQ(f.mainWhole.evaluations, 400); // an escalation gets the whole budget but the challenger's share
  tp.steady.budgetFraction = 0.01;
  f.setBudgets(tp.search, tp.steady, tp.verifier);
  EXPECT_EQ(f.main.evaluations, tp.search.ga.population); // never under one population
  // A wall-time budget: the hue planes' time is taken out of it.
  tp.search.budgetEvaluations = 0;
  tp.search.budgetMs = 10;
  pm::tracker::FramePlan t;
  t.hueMs = 2;
  t.setBudgets(tp.search, tp.steady, tp.verifier);
  EXPECT_DOUBLE_EQ(t.main.milliseconds, 8);
  EXPECT_DOUBLE_EQ(pm::tracker::budgetPart(pm::rmga::FrameBudget::ms(10), 0.25, 20).milliseconds, 2.5);
}

TEST(QualityScale, TheBackgroundScoresZeroAndAPerfectMatchOne)
{
  const Crab &c = crab();
  const pm::core::FitnessParams f = pm::tracker::trackerFitnessDefaults();
  const pm::tracker::QualityScale q(c.sm.build.model, f);
  const double n = static_cast<double>(c.sm.build.model.size()), nIn = static_cast<double>(c.sm.build.model.inner.size());
  const double nOut = n - nIn;
  EXPECT_NEAR(q.quality((f.inBackground * nIn + f.outBackground * nOut) / n), 0.0, 1e-12);
  EXPECT_NEAR(q.quality((f.inMatch * nIn + f.outBackground * nOut) / n), 1.0, 1e-12);
  EXPECT_NEAR(q.fitnessSpan(1.0), (f.inMatch - f.inBackground) * nIn / n, 1e-12);
  pm::core::FitnessParams flat = f;
  flat.inMatch = flat.inBackground; // a match scores no better than the background
  EXPECT_THROW(pm::tracker::QualityScale(c.sm.build.model, flat), pm::core::Error);
}

TEST(PoseSearch, TheFramesChangesAreAppliedInOnePlaceInTheirOrder)
{
  const Crab &c = crab();
  Scored scored(c);
  const pm::core::StereoFitness &fitness = scored.fitness;
  const pm::tracker::QualityScale &scale = scored.scale;
  pm::tracker::SearchParams p;
  pm::tracker::PoseSearch search(p, fitness.scorer(), scale);
  search.initialize();
  EXPECT_FALSE(search.ga().hasAnchor());
  search.evolve(fitness.frame(), pm::rmga::FrameBudget::evals(200), pm::tracker::PoseSearch::Scoring::Coarse);
  // A reseed, then an injected pose: the population is around the reseed, with the pose among it.
  RmGaUpdate u;
  u.reseed = RmGaUpdate::Reseed{c.truth, 0.0};
  pm::core::Phi found = c.truth;
  found.x += 1;
  u.inject = RmGaUpdate::Inject{found, 1.5};
  u.anchor = c.truth;
  search.apply(u);
  bool injected = false;
  for (const auto &ind : search.ga().population()) {
    EXPECT_LT(pm::core::translationDistanceMm(ind.phi, c.truth), 2.0);
    injected = injected || ind.fitness == 1.5;
  }
  EXPECT_TRUE(injected);
  ASSERT_TRUE(search.ga().hasAnchor());
  EXPECT_LT(pm::core::translationDistanceMm(search.ga().anchor(), c.truth), 1.0);
  // A scatter (a lock refused) keeps only the best in place: most of the population moves away.
  RmGaUpdate s;
  s.restart = RmGaUpdate::Restart::AwayFromBest;
  search.apply(s);
  int far = 0;
  for (const auto &ind : search.ga().population())
    far += pm::core::translationDistanceMm(ind.phi, c.truth) > 20;
  EXPECT_GT(far, p.ga.population / 2);
  // ... and the best is avoided: the next frames' best is elsewhere, for its frames.
  EXPECT_EQ(search.ga().avoidedCount(), 1u);
  const pm::rmga::FrameResult elsewhere = search.evolve(fitness.frame(), pm::rmga::FrameBudget::evals(400), pm::tracker::PoseSearch::Scoring::Exact);
  EXPECT_TRUE(pm::core::translationDistanceMm(elsewhere.best, c.truth) > p.avoidMm - 1 ||
              pm::core::rotationDistanceDeg(elsewhere.best, c.truth) > p.avoidDeg - 1);
}

TEST(LockVerifier, AWrongLockIsChallengedAndARightOneVerified)
{
  const Crab &c = crab();
  Scored scored(c);
  const pm::core::StereoFitness &fitness = scored.fitness;
  const pm::tracker::QualityScale &scale = scored.scale;
  pm::tracker::SearchParams sp;
  const pm::rmga::RmGa anchorless(sp.space, sp.ga);
  pm::tracker::VerifierParams vp;
  vp.evaluations = 1200;
  // The right pose: no objection, verified once its evaluations are spent.
  pm::tracker::LockVerifier right(vp, sp, fitness.scorer(), scale);
  EXPECT_FALSE(right.verifying(TrackState::Tracking));
  right.onState(TrackState::Searching, TrackState::Tracking, c.truth, anchorless);
  EXPECT_TRUE(right.verifying(TrackState::Tracking));
  EXPECT_FALSE(right.verified());
  pm::tracker::SearchWork work;
  const pm::tracker::ScoredPose truth{c.truth, fitness.evaluate(c.truth)};
  for (int k = 0; k < 6 && !right.verified(); ++k) {
    const pm::tracker::LockVerifier::Challenge ch = right.challenge(fitness.frame(), pm::rmga::FrameBudget::evals(400), truth, anchorless);
    EXPECT_FALSE(ch.better.has_value());
    EXPECT_GT(ch.run.evaluations, 0);
    work = work.plus(ch.run);
  }
  EXPECT_TRUE(right.verified());
  EXPECT_GE(work.evaluations, vp.evaluations); // verified once its evaluations are spent
  EXPECT_FALSE(right.verifying(TrackState::Tracking));
  // A lock far off the crab: the challenger finds the crab, clearly better, and the tracker must move there.
  pm::core::Phi wrong = c.truth;
  wrong.x += 90;
  wrong.y -= 60;
  pm::tracker::LockVerifier verifier(vp, sp, fitness.scorer(), scale);
  verifier.onState(TrackState::Searching, TrackState::Tracking, wrong, anchorless);
  std::optional<pm::tracker::ScoredPose> better;
  const pm::tracker::ScoredPose off{wrong, fitness.evaluate(wrong)};
  for (int k = 0; k < 20 && !better; ++k)
    better = verifier.challenge(fitness.frame(), pm::rmga::FrameBudget::evals(400), off, anchorless).better;
  ASSERT_TRUE(better.has_value());
  EXPECT_LT(pm::core::translationDistanceMm(better->phi, c.truth), 20.0);
  EXPECT_DOUBLE_EQ(better->fitness, fitness.evaluate(better->phi));
  EXPECT_FALSE(verifier.verified()); // the new pose is verified in turn
  EXPECT_FALSE(verifier.lookingAgain()); // a new lock, not an ambiguity
  // A target no longer tracked is no longer verified, nor verifying.
  verifier.onState(TrackState::Tracking, TrackState::Lost, better->phi, anchorless);
  EXPECT_FALSE(verifier.verifying(TrackState::Tracking));
  EXPECT_FALSE(verifier.verified());
}

TEST(LockVerifier, AnotherPoseOfTheSameObjectScoringAsWellStartsItAgainAndSaysSo)
{
  const Crab &c = crab();
  Scored scored(c);
  const pm::core::StereoFitness &fitness = scored.fitness;
  pm::tracker::SearchParams sp;
  const pm::rmga::RmGa anchorless(sp.space, sp.ga);
  pm::tracker::VerifierParams vp;
  vp.evaluations = 1200;
  vp.switchMargin = 1.0; // never moves: the right pose the challenger finds can only be as good, not better
  // A lock at the crab's place, turned 10 deg about its own z axis: the challenger finds the crab
  // within sameObjectMm and farther than farDeg, scoring over the lock's q: ambiguous.
  const vpHomogeneousMatrix turn(0, 0, 0, 0, 0, vpMath::rad(10));
  const pm::core::Phi turned = pm::core::fromHomogeneousMatrix(pm::core::toHomogeneousMatrix(c.truth) * turn);
  ASSERT_GT(pm::core::rotationDistanceDeg(turned, c.truth), vp.farDeg);
  const pm::tracker::ScoredPose lock{turned, fitness.evaluate(turned)};
  pm::tracker::LockVerifier verifier(vp, sp, fitness.scorer(), scored.scale);
  verifier.onState(TrackState::Searching, TrackState::Tracking, turned, anchorless);
  EXPECT_FALSE(verifier.lookingAgain());
  for (int k = 0; k < 12 && !verifier.lookingAgain(); ++k)
    EXPECT_FALSE(verifier.challenge(fitness.frame(), pm::rmga::FrameBudget::evals(400), lock, anchorless).better.has_value());
  EXPECT_TRUE(verifier.lookingAgain());
  EXPECT_FALSE(verifier.verified());
  EXPECT_TRUE(verifier.verifying(TrackState::Tracking)); // the whole verification again
  // The next lock is verified afresh: no longer looking again.
  verifier.onState(TrackState::Tracking, TrackState::Lost, turned, anchorless);
  EXPECT_FALSE(verifier.lookingAgain());
  verifier.onState(TrackState::Lost, TrackState::Tracking, c.truth, anchorless);
  EXPECT_FALSE(verifier.lookingAgain());
  // A second opinion that takes both poses to one peak (here: the truth) dissolves the ambiguity:
  // the verification goes on and ends; one that leaves them apart changes nothing.
  const auto verifyWith = [&](const pm::tracker::LockVerifier::Settle &settle, int &onePeaks) {
    pm::tracker::LockVerifier v(vp, sp, fitness.scorer(), scored.scale);
    v.onState(TrackState::Searching, TrackState::Tracking, turned, anchorless);
    onePeaks = 0;
    for (int k = 0; k < 12 && !v.lookingAgain() && !v.verified(); ++k)
      onePeaks += v.challenge(fitness.frame(), pm::rmga::FrameBudget::evals(400), lock, anchorless, settle).onePeak ? 1 : 0;
    return v.verified() && !v.lookingAgain();
  };
  int onePeaks = 0;
  int asked = 0;
  EXPECT_TRUE(verifyWith([&](const pm::core::Phi &) { return ++asked, std::optional<pm::core::Phi>(c.truth); }, onePeaks));
  EXPECT_GE(onePeaks, 1);
  EXPECT_EQ(asked, 2 * onePeaks); // asked only on an ambiguity, for both poses
  EXPECT_FALSE(verifyWith([](const pm::core::Phi &phi) { return std::optional<pm::core::Phi>(phi); }, onePeaks)); // the poses stay 10 deg apart
  EXPECT_EQ(onePeaks, 0);
  EXPECT_FALSE(verifyWith([](const pm::core::Phi &) { return std::optional<pm::core::Phi>(); }, onePeaks)); // no opinion: ambiguous
}

TEST(Judgement, TheFrameIsJudgedOnceFromItsEvidenceAndTheTrackersState)
{
  const Crab &c = crab();
  Scored scored(c);
  const pm::core::StereoFitness &fitness = scored.fitness;
  const pm::tracker::QualityScale &scale = scored.scale;
  const pm::tracker::JudgementParams params = pm::tracker::JudgementParams().forModel(c.sm.build.model);
  EXPECT_EQ(params.confidence.kind, pm::tracker::ConfidenceKind::Flat); // the coefficients of the model's kind
  const pm::tracker::Judgement judgement(params, 5.0, fitness.scorer(), scale, pm::precise::ModelErrorFloor({}, vpHomogeneousMatrix()));
  pm::core::Phi seen[8];
  EXPECT_EQ(judgement.competitors(c.truth, seen), 8u); // turned about its axis (7) and its tilt mirrored, all valid here
  pm::tracker::RefinedPose refined;
  refined.pose = pm::tracker::ScoredPose{c.truth, fitness.evaluate(c.truth)};
  const double q = scale.quality(refined.pose.fitness);
  const pm::tracker::Evidence e = judgement.measure(fitness.frame(), refined);
  // The cues' q is over the points not hidden (the stereo visibility): never under the frame's q.
  const pm::core::FitnessDetail d = fitness.evaluateDetail(c.truth);
  EXPECT_DOUBLE_EQ(e.cues.quality, scale.quality(d.meanVisible()));
  EXPECT_GE(e.cues.quality, q);
  EXPECT_GT(e.cues.competitorMargin, 0.0); // the right pose stands above its turned copies
  EXPECT_GT(e.cues.inMatchMin, 0.5);
  EXPECT_FALSE(e.cues.precise); // a flat model: no precise stage
  // The state is the tracker's: the same evidence judged as a long verified track, and unverified.
  pm::tracker::JudgedState s;
  s.state = TrackState::Tracking;
  s.recentBestQ = q;
  s.framesTracked = 30;
  s.verified = true;
  const pm::tracker::Verdict r = judgement.judge(refined, e, s);
  EXPECT_EQ(r.cues.framesTracked, 30);
  EXPECT_TRUE(r.verified);
  EXPECT_EQ(r.trusted, r.confidence >= params.confidence.threshold);
  EXPECT_EQ(r.heldBy == nullptr, r.trusted);
  s.verified = false;
  pm::tracker::Verdict u = judgement.judge(refined, e, s);
  EXPECT_FALSE(u.trusted); // never trusted unverified, whatever its confidence
  EXPECT_STREQ(u.heldBy, "verification");
  s.lookingAgain = true; // the challenger found another pose as good: the user is told so
  EXPECT_STREQ(judgement.judge(refined, e, s).heldBy, "verification_ambiguous");
  s.lookingAgain = false;
  EXPECT_LT(u.confidence, r.confidence);
  // The jump is measured from the last tracked pose, the drop from the recent best.
  pm::core::Phi last = c.truth;
  last.x -= 10;
  s.last = &last;
  s.recentBestQ = q + 0.1;
  u = judgement.judge(refined, e, s);
  EXPECT_NEAR(u.cues.jumpMm, 10.0, 1e-9);
  EXPECT_NEAR(u.cues.qualityDrop, 0.1, 1e-12);
  // Not tracking: never trusted, held by the state.
  s.state = TrackState::Lost;
  s.verified = true;
  u = judgement.judge(refined, e, s);
  EXPECT_FALSE(u.trusted);
  EXPECT_STREQ(u.heldBy, "lost");
  // As a first lock (one frame, unverified) it is less sure than as a long verified track.
  EXPECT_LT(judgement.firstLockConfidence(e, q, false), r.confidence);
}

TEST(BackgroundLearning, ABackgroundThatTurnedIsLearntOnTrustedFramesAndTheSameOneChangesNothing)
{
  const Crab &c = crab();
  // The renderer's own background: its hue stays within the switch of the model's, nothing changes.
  Scored same(c);
  pm::tracker::BackgroundLearning stays(pm::tracker::BackgroundParams(), same.fitness.scorer());
  const double model = stays.modelDeg();
  EXPECT_DOUBLE_EQ(model, same.fitness.backgroundHue());
  for (int k = 0; k < 100; ++k)
    EXPECT_FALSE(stays.learn(same.fitness.frame(), c.truth, true).has_value()) << k;
  EXPECT_LT(pm::core::hueDistance(static_cast<float>(stays.learntDeg()), static_cast<float>(model)), 5.0f);
  const double fSame = same.fitness.evaluate(c.truth);
  // The backdrop turned 20 deg (--backdrop-drift 1, 20 s into a run): the right pose scores lower ...
  pm::sim::SceneParams p = c.scene.params();
  p.backdropHueDriftDegPerS = 1;
  const pm::sim::StereoImages im = pm::sim::Scene(c.scene.target(), p).renderStereo(c.rig, c.hMo, 600);
  pm::core::StereoFitness turned(c.rig, c.sm.build.model, pm::tracker::trackerFitnessDefaults());
  turned.setImages(im.left, im.right);
  const double fTurned = turned.evaluate(c.truth);
  EXPECT_LT(fTurned, fSame - 0.05);
  // ... untrusted frames teach nothing; trusted ones move the learnt hue to the background's, and
  // the scoring takes it once it is 5 deg away.
  pm::tracker::BackgroundLearning learns(pm::tracker::BackgroundParams(), turned.scorer());
  for (int k = 0; k < 20; ++k)
    EXPECT_FALSE(learns.learn(turned.frame(), c.truth, false).has_value());
  EXPECT_DOUBLE_EQ(learns.learntDeg(), model);
  int switches = 0;
  for (int k = 0; k < 60; ++k)
    if (const std::optional<double> hue = learns.learn(turned.frame(), c.truth, true)) {
      turned.setBackgroundHue(*hue);
      ++switches;
    }
  EXPECT_GE(switches, 1);
  double moved = learns.learntDeg() - model;
  moved -= 360 * std::round(moved / 360);
  EXPECT_NEAR(moved, 20.0, 4.0);
  EXPECT_NEAR(turned.backgroundHue(), learns.usedDeg(), 0.05);
  EXPECT_LE(std::fabs(learns.learntDeg() - learns.usedDeg()), 5.0);
  // The right pose scores nearly as on the photos' background again.
  EXPECT_GT(turned.evaluate(c.truth), fTurned + 0.8 * (fSame - fTurned));
  EXPECT_DOUBLE_EQ(learns.reset(), model);
  EXPECT_DOUBLE_EQ(learns.usedDeg(), model);
  // Off: the model's hue for good; parameters out of range.
  pm::tracker::BackgroundParams off;
  off.learn = false;
  pm::tracker::BackgroundLearning never(off, turned.scorer());
  EXPECT_FALSE(never.learn(turned.frame(), c.truth, true).has_value());
  pm::tracker::BackgroundParams bad;
  bad.rate = 0;
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::BackgroundLearning b(bad, turned.scorer()); }).find("learning rate"), std::string::npos);
  bad = pm::tracker::BackgroundParams();
  bad.switchDeg = 40;
  EXPECT_NE(pm::test::errorOf([&] { bad.validate(); }).find("switch"), std::string::npos);
  EXPECT_NE(pm::test::errorOf([&] { turned.setBackgroundHue(360); }).find("[0, 360)"), std::string::npos);
}

TEST(LandingCorrection, AtAViewOfThePassItTakesTheLandingOffAndFarFromEveryViewNothing)
{
  // One landing: the stage, at the crab's rest pose seen from the left camera, put the model 0.3 mm,
  // -0.2, 0.1 off and turned it 0.4, -0.5, 0.1 deg (model frame's axes, as measurePassLandings keeps
  // them). A pose so landed is brought back to the truth within a twentieth of the offset (the
  // weight read at the landed pose's own direction, 0.6 deg off the view's); a pose seen from 40 deg
  // away is left as it is; without landings, or with a width that is not an angle, nothing or an error.
  const vpHomogeneousMatrix hMc(-0.1615, 0, 0, 0, 0, 0);
  const pm::core::Phi truth = pm::core::fromHomogeneousMatrix(vpHomogeneousMatrix(0.01, -0.02, 0.5, 0.1, -0.2, 0.05));
  const vpHomogeneousMatrix hMm = pm::core::toHomogeneousMatrix(truth);
  const vpHomogeneousMatrix mMc = hMm.inverse() * hMc;
  pm::core::PassLanding l;
  const double mt[3] = {0.3, -0.2, 0.1}, mw[3] = {0.4, -0.5, 0.1};
  for (unsigned i = 0; i < 3; ++i) {
    l.cameraMm[i] = 1e3 * mMc[i][3];
    l.offsetMm[i] = mt[i];
    l.offsetDeg[i] = mw[i];
  }
  const pm::tracker::LandingCorrection landing({l}, hMc, 4);
  ASSERT_TRUE(landing.active());
  // At the view itself: the landing's offsets, turned into the hand frame (hRm m).
  const std::array<double, 6> e = landing.at(truth);
  const vpRotationMatrix hRm = hMm.getRotationMatrix();
  for (unsigned i = 0; i < 3; ++i) {
    double t = 0, w = 0;
    for (unsigned j = 0; j < 3; ++j)
      t += hRm[i][j] * mt[j], w += hRm[i][j] * mw[j];
    EXPECT_NEAR(e[i], t, 1e-9);
    EXPECT_NEAR(e[3 + i], w, 1e-9);
  }
  const double tw[6] = {e[0], e[1], e[2], vpMath::rad(e[3]), vpMath::rad(e[4]), vpMath::rad(e[5])};
  const pm::core::Phi landed = pm::core::applyTwist(truth, tw);
  const pm::core::Phi back = landing.corrected(landed);
  EXPECT_GT(pm::core::rotationDistanceDeg(landed, truth), 0.6);
  EXPECT_LT(pm::core::rotationDistanceDeg(back, truth), 0.05 * pm::core::rotationDistanceDeg(landed, truth));
  EXPECT_LT(pm::core::translationDistanceMm(back, truth), 0.05 * pm::core::translationDistanceMm(landed, truth));
  // Seen from 40 deg away (the model turned about the hand's y): no view near, nothing taken off.
  const double turn[6] = {0, 0, 0, 0, vpMath::rad(40), 0};
  const pm::core::Phi away = pm::core::applyTwist(truth, turn);
  const pm::core::Phi kept = landing.corrected(away);
  EXPECT_LT(pm::core::rotationDistanceDeg(kept, away), 1e-3);
  EXPECT_LT(pm::core::translationDistanceMm(kept, away), 1e-3);
  // No landings (a flat or stereo model, an older file): the pose as it is.
  const pm::tracker::LandingCorrection none({}, hMc, 4);
  EXPECT_FALSE(none.active());
  const pm::core::Phi same = none.corrected(landed);
  EXPECT_TRUE(same.x == landed.x && same.y == landed.y && same.z == landed.z && same.e1 == landed.e1 && same.e2 == landed.e2 &&
              same.e3 == landed.e3);
  EXPECT_THROW(pm::tracker::LandingCorrection({l}, hMc, 0), pm::core::Error);
  EXPECT_THROW(pm::tracker::LandingCorrection({l}, hMc, std::nan("")), pm::core::Error);
}
