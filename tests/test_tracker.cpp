// The photo-model tracker: detection from scratch, static detection (Table 1), initFromPose, the states (lost and found
// again), configuration files, bad input. Budgets in evaluations, so every run is deterministic.
#include <algorithm>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "C12Scene.h"
#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/tracker/TrackerConfigFile.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/StaticDetection.h"
#include "pm/tracker/MotionPrediction.h"
#include "pm/tracker/PoseHistory.h"
#include "pm/tracker/TiltFilter.h"

#include <visp3/core/vpThetaUVector.h>

namespace {

using pm::test::C12Scene;
using pm::test::c12;

pm::tracker::TrackerParams evalBudget(long evals)
{
  pm::tracker::TrackerParams p;
  p.search.budgetEvaluations = evals;
  return p;
}

} // namespace

TEST(Tracker, DetectsFromScratch)
{
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(3000);
  p.search.ga.population = 100;
  p.search.ga.restartGenerations = 30;
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, p);
  t.initialize();
  EXPECT_EQ(t.getState(), pm::tracker::TrackState::Searching);
  pm::tracker::TrackResult r;
  for (int k = 0; k < 40; ++k)
    r = t.track(S.im.left, S.im.right);
  EXPECT_EQ(r.state, pm::tracker::TrackState::Tracking);
  EXPECT_NEAR(r.phi.x, S.truth.x, 2.0);
  EXPECT_NEAR(r.phi.y, S.truth.y, 2.0);
  EXPECT_NEAR(r.phi.e3, S.truth.e3, 0.02);
  // Depth and tilt: within the fitness's own bias for a planar model of a 40 mm deep toy.
  EXPECT_NEAR(r.phi.z, S.truth.z, 10.0);
  EXPECT_NEAR(r.phi.e1, S.truth.e1, 0.06);
  EXPECT_NEAR(r.phi.e2, S.truth.e2, 0.06);
  EXPECT_GE(r.fitness, t.fitness().evaluate(S.truth)); // RM-GA finds at least what the truth scores
  EXPECT_GT(r.quality, 0.8);
  // The returned hMo is phi's matrix.
  const pm::core::Phi back = pm::core::fromHomogeneousMatrix(r.hMo);
  EXPECT_NEAR(back.x, r.phi.x, 1e-9);
}

TEST(Tracker, OneCameraDetectsFromScratchWhereThePairDoes)
{
  // The same still crab seen by the left camera alone (a one-camera rig): the tracker finds it from
  // scratch, across the view as near as the pair does; its depth from the outline's size alone.
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(3000);
  p.search.ga.population = 100;
  p.search.ga.restartGenerations = 30;
  const pm::core::CameraRig one(std::vector<pm::core::PinholeCamera>{S.rig.left});
  pm::tracker::PhotoModelTracker t(one, S.sm.build.model, p);
  EXPECT_EQ(t.cameraCount(), 1);
  t.initialize();
  pm::tracker::TrackResult r;
  for (int k = 0; k < 40; ++k)
    r = t.track(pm::core::CameraImages(S.im.left));
  EXPECT_EQ(r.state, pm::tracker::TrackState::Tracking);
  // In the camera's frame (toed in: the hand's x and z mix), beside the pair's estimate on the same
  // images: the target's centre where the truth's projects, as near as the pair's within 1.5 px (this
  // planar model puts both 2-3 px off); along the camera's axis within the planar model's bias.
  pm::tracker::PhotoModelTracker both(S.rig, S.sm.build.model, p);
  both.initialize();
  pm::tracker::TrackResult rp;
  for (int k = 0; k < 40; ++k)
    rp = both.track(S.im.left, S.im.right);
  const vpHomogeneousMatrix cMh = S.rig.left.cMh();
  const vpTranslationVector found = (cMh * r.hMo).getTranslationVector(), pair = (cMh * rp.hMo).getTranslationVector(),
                            truth = (cMh * pm::core::toHomogeneousMatrix(S.truth)).getTranslationVector();
  const double px = S.rig.left.cam.get_px();
  for (unsigned i = 0; i < 2; ++i) {
    const double offOne = std::fabs(px * (found[i] / found[2] - truth[i] / truth[2]));
    const double offPair = std::fabs(px * (pair[i] / pair[2] - truth[i] / truth[2]));
    std::cout << "image axis " << i << ": one camera " << offOne << " px off, the pair " << offPair << " px\n";
    EXPECT_LT(offOne, offPair + 1.5);
  }
  EXPECT_NEAR(1e3 * found[2], 1e3 * truth[2], 10.0);
  EXPECT_NEAR(r.phi.e3, S.truth.e3, 0.02);
  EXPECT_GE(r.fitness, t.fitness().evaluate(S.truth));
  // The pair given to one camera: a clear error, nothing tracked.
  EXPECT_EQ(pm::test::errorOf([&] { t.track(S.im.left, S.im.right); }), "tracker: 2 images for a rig of 1 camera (one image per camera)");
}

TEST(Tracker, InitFromPoseStaysOnTheTarget)
{
  const C12Scene &S = c12();
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, evalBudget(1000));
  t.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  EXPECT_EQ(t.getState(), pm::tracker::TrackState::Tracking);
  const pm::tracker::TrackResult r = t.track(S.im.left, S.im.right);
  EXPECT_EQ(r.state, pm::tracker::TrackState::Tracking);
  EXPECT_NEAR(r.phi.x, S.truth.x, 2.0);
  EXPECT_NEAR(r.phi.y, S.truth.y, 2.0);
  EXPECT_NEAR(r.phi.z, S.truth.z, 10.0);
}

TEST(Tracker, BlankFramesAreLostThenTheTargetIsFoundAgain)
{
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(2000);
  p.search.ga.population = 60;
  p.search.ga.restartGenerations = 30;
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, p);
  t.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  t.track(S.im.left, S.im.right);
  const vpImage<vpRGBa> blank(480, 640, vpRGBa(90, 90, 90));
  std::vector<pm::tracker::TrackState> states;
  for (int k = 0; k < p.lock.lostFrames + 1; ++k)
    states.push_back(t.track(blank, blank).state);
  EXPECT_EQ(states.front(), pm::tracker::TrackState::Tracking); // one bad frame is not yet a loss
  EXPECT_EQ(states.back(), pm::tracker::TrackState::Lost);
  int found = -1;
  for (int k = 0; k < 60 && found < 0; ++k)
    if (t.track(S.im.left, S.im.right).state == pm::tracker::TrackState::Tracking)
      found = k;
  ASSERT_GE(found, 0);
  for (int k = 0; k < 10; ++k) // let it settle
    t.track(S.im.left, S.im.right);
  EXPECT_NEAR(t.lastResult().phi.x, S.truth.x, 2.0);
  EXPECT_NEAR(t.lastResult().phi.y, S.truth.y, 2.0);
}

TEST(Tracker, SteadyFramesGetTheSmallerBudgetAndADropGetsTheWholeOne)
{
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(1000);
  p.steady.budgetFraction = 0.3;
  p.steady.afterFrames = 5;
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, p);
  t.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  std::vector<pm::tracker::TrackResult> r;
  for (int k = 0; k < 10; ++k)
    r.push_back(t.track(S.im.left, S.im.right));
  for (int k = 0; k < 10; ++k) {
    ASSERT_EQ(r[static_cast<std::size_t>(k)].state, pm::tracker::TrackState::Tracking) << "frame " << k;
    // The first frames of a lock have the whole budget; from the sixth on, the steady one.
    EXPECT_EQ(r[static_cast<std::size_t>(k)].steady, k >= 5) << "frame " << k;
    if (k < 5)
      EXPECT_GT(r[static_cast<std::size_t>(k)].evaluations, 900) << "frame " << k;
    else
      EXPECT_LE(r[static_cast<std::size_t>(k)].evaluations, 300) << "frame " << k;
  }
  EXPECT_NEAR(r.back().phi.x, S.truth.x, 2.0);
  EXPECT_NEAR(r.back().phi.y, S.truth.y, 2.0);
  // A blank frame: it starts with the steady budget (it was not known), q falls, so it gets the
  // rest of the whole budget at once (escalated), and the next frame has all of it.
  const vpImage<vpRGBa> blank(480, 640, vpRGBa(90, 90, 90));
  const pm::tracker::TrackResult b = t.track(blank, blank);
  EXPECT_FALSE(b.steady);
  EXPECT_TRUE(b.escalated);
  EXPECT_GT(b.evaluations, 900);
  EXPECT_LE(b.evaluations, 1000 + p.search.ga.population); // the steady part, the rest, and the population scored again
  EXPECT_LT(b.quality, 0.2);
  const pm::tracker::TrackResult next = t.track(S.im.left, S.im.right);
  EXPECT_FALSE(next.steady);
  EXPECT_FALSE(next.escalated);
  EXPECT_GT(next.evaluations, 900);
  // Without the escalation the blank frame keeps the steady budget.
  pm::tracker::TrackerParams q = p;
  q.steady.escalation = false;
  pm::tracker::PhotoModelTracker u(S.rig, S.sm.build.model, q);
  u.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  for (int k = 0; k < 6; ++k)
    u.track(S.im.left, S.im.right);
  const pm::tracker::TrackResult ub = u.track(blank, blank);
  EXPECT_TRUE(ub.steady);
  EXPECT_FALSE(ub.escalated);
  EXPECT_LE(ub.evaluations, 300);
  // Out of range: refused.
  p.steady.budgetFraction = 0;
  EXPECT_THROW(pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, p), pm::core::Error);
}

TEST(Tracker, SteadyFramesSeeTheHueOnlyAroundTheTargetAndScoreTheSame)
{
  // Two trackers on the same frames, one with hue windows on steady frames, one on the whole
  // images: the windows are smaller than the images and hold the model, and every frame's
  // fitness and cues are those of the whole images (the confidence's competitors included).
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(600);
  p.steady.afterFrames = 3;
  pm::tracker::TrackerParams whole = p;
  whole.steady.hueMarginPx = 0;
  pm::tracker::PhotoModelTracker a(S.rig, S.sm.build.model, p), b(S.rig, S.sm.build.model, whole);
  a.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  b.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  int steady = 0;
  for (int k = 0; k < 8; ++k) {
    const pm::tracker::TrackResult ra = a.track(S.im.left, S.im.right), rb = b.track(S.im.left, S.im.right);
    ASSERT_EQ(ra.steady, rb.steady) << "frame " << k;
    steady += ra.steady;
    // The same search on the same fitness values: the same pose, fitness and confidence.
    EXPECT_EQ(ra.phi.toString(), rb.phi.toString()) << "frame " << k;
    EXPECT_DOUBLE_EQ(ra.fitness, rb.fitness) << "frame " << k;
    EXPECT_DOUBLE_EQ(ra.cues.competitorMargin, rb.cues.competitorMargin) << "frame " << k;
    EXPECT_DOUBLE_EQ(ra.confidence, rb.confidence) << "frame " << k;
    if (ra.steady)
      for (int cam = 0; cam < 2; ++cam) {
        const pm::core::PixelRect w = a.fitness().huePlane(cam).window(), fp = a.fitness().footprint(ra.phi, cam);
        EXPECT_LT((w.u1 - w.u0) * (w.v1 - w.v0), 640 * 480 / 2) << "frame " << k << " camera " << cam;
        EXPECT_TRUE(fp.u0 >= w.u0 && fp.v0 >= w.v0 && fp.u1 <= w.u1 && fp.v1 <= w.v1) << "frame " << k;
      }
  }
  EXPECT_GE(steady, 4);
  p.steady.hueMarginPx = -1;
  EXPECT_THROW(pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, p), pm::core::Error);
}

TEST(Tracker, SameSeedSameEstimates)
{
  const C12Scene &S = c12();
  auto run = [&] {
    pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, evalBudget(800));
    std::vector<double> xs;
    for (int k = 0; k < 5; ++k)
      xs.push_back(t.track(S.im.left, S.im.right).phi.x);
    return xs;
  };
  EXPECT_EQ(run(), run());
}

namespace {

//! C12 still at the rig's centre, rendered without anti-aliasing: with 600 evaluations per frame
//! and seed 1 the tracker's first lock is the toy tilted by about 45 degrees at 550 mm (the case
//! issue 17 reports from pm-servo). Per frame: whether the result was trusted, and whether it was right.
struct TrustRun
{
  std::vector<bool> trusted, right, tracking;
  std::vector<double> confidence;
  std::vector<double> errorMm, errorDeg; //!< the estimate's distance from the truth
  int firstTrusted = -1;
};

TrustRun runStill(long verifyEvaluations, int frames, double threshold = 0.95, double lockConfidence = 0)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::sim::SceneParams sp;
  sp.supersampling = 1;
  pm::sim::Scene scene(pm::sim::makeTarget("C12"), sp);
  const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500);
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
  const pm::core::Phi truth = sm.truth(hMo);
  pm::tracker::TrackerParams p = evalBudget(600);
  p.search.ga.predictMotion = true;
  p.search.ga.restartGenerations = 30;
  p.lock.confidence = lockConfidence; // 0: the wrong first lock of this case is taken, for the verification to undo
  p.verifier.evaluations = verifyEvaluations;
  p.judgement.confidence.threshold = threshold;
  // The paper's fitness, each camera alone: the case is its wrong first lock (with the stereo
  // visibility the same GA path locks right at once: nothing for the verification to undo).
  p.fitness.stereoVisibility = false;
  pm::tracker::PhotoModelTracker t(rig, sm.build.model, p);
  TrustRun run;
  for (int k = 0; k < frames; ++k) {
    const pm::sim::StereoImages im = scene.renderStereo(rig, hMo, static_cast<std::uint64_t>(k));
    const pm::tracker::TrackResult r = t.track(im.left, im.right);
    run.trusted.push_back(r.trusted);
    run.tracking.push_back(r.state == pm::tracker::TrackState::Tracking);
    run.right.push_back(pm::core::translationDistanceMm(r.phi, truth) <= 20 && pm::core::rotationDistanceDeg(r.phi, truth) <= 5);
    run.confidence.push_back(r.confidence);
    run.errorMm.push_back(pm::core::translationDistanceMm(r.phi, truth));
    run.errorDeg.push_back(pm::core::rotationDistanceDeg(r.phi, truth));
    if (r.trusted && run.firstTrusted < 0)
      run.firstTrusted = k;
  }
  return run;
}

} // namespace

TEST(Tracker, AWrongFirstLockIsNotTrustedTheChallengerFindsTheTarget)
{
  const TrustRun v = runStill(6000, 70);
  // The case: the tracker locks at once on a wrong pose.
  ASSERT_TRUE(v.tracking[0]);
  ASSERT_FALSE(v.right[0]);
  // Verified, it never trusts a wrong pose, and trusts the right one within 70 frames (here the
  // challenger finds the crab at frame 35 and it is trusted from frame 55; with the flat model of
  // before issue 42's one background subtraction, within 40: the GA's path, not a property).
  for (std::size_t k = 0; k < v.trusted.size(); ++k)
    EXPECT_FALSE(v.trusted[k] && !v.right[k]) << "frame " << k;
  ASSERT_GE(v.firstTrusted, 0);
  EXPECT_TRUE(v.right.back());
  // The confidence alone sees the wrong lock too (the crab 45 deg tilted, turned about its axis
  // it scores as well) ...
  EXPECT_LT(v.confidence[0], 0.5);
  // ... and what protects is the gate: without the verification and with any confidence taken,
  // the same run trusts the wrong lock (its confidence is about 0.0002: the threshold is under it).
  const TrustRun n = runStill(0, 5, 1e-6);
  bool trustedWrong = false;
  for (std::size_t k = 0; k < n.trusted.size(); ++k)
    trustedWrong = trustedWrong || (n.trusted[k] && !n.right[k]);
  EXPECT_TRUE(trustedWrong);
}

TEST(Tracker, APlainlyWrongPoseIsNotLockedTheSearchGoesOn)
{
  // The same case with the lock gated by its confidence (the default): the pose that locked
  // above (45 deg off, confidence about 0.0002) is not taken; the search goes on. The first lock
  // may still be short of right (here 7 mm and 11 deg off at confidence 0.84, not trusted): the
  // frames after it close in, as tracking does, and no frame is trusted before it is right.
  const TrustRun g = runStill(6000, 40, 0.95, 0.05);
  ASSERT_FALSE(g.tracking[0]);
  int firstLock = -1;
  for (std::size_t k = 0; k < g.tracking.size() && firstLock < 0; ++k)
    if (g.tracking[k])
      firstLock = static_cast<int>(k);
  ASSERT_GE(firstLock, 0) << "never locked";
  const std::size_t settled = static_cast<std::size_t>(firstLock) + 3;
  for (std::size_t k = static_cast<std::size_t>(firstLock); k < g.tracking.size(); ++k) {
    EXPECT_TRUE(g.tracking[k]) << "frame " << k << ": lost";
    EXPECT_LT(g.errorDeg[k], 20) << "frame " << k << ": a plainly wrong pose tracked"; // the wrong lock is 45 deg off
    EXPECT_FALSE(g.trusted[k] && !g.right[k]) << "frame " << k << ": trusted " << g.errorMm[k] << " mm, " << g.errorDeg[k] << " deg off";
    if (k >= settled) {
      EXPECT_TRUE(g.right[k]) << "frame " << k << ": " << g.errorMm[k] << " mm, " << g.errorDeg[k] << " deg off, confidence " << g.confidence[k];
    }
  }
  EXPECT_GE(g.firstTrusted, 0);
}

TEST(Tracker, BadInputIsRefused)
{
  const C12Scene &S = c12();
  EXPECT_THROW(pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, evalBudget(5)), pm::core::Error); // under the population
  pm::tracker::TrackerParams zero;
  zero.search.budgetMs = 0;
  EXPECT_THROW(pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, zero), pm::core::Error);
  // A model twenty times too large does not fit the rig.
  pm::core::PhotoModel huge = S.sm.build.model;
  for (auto *set : {&huge.inner, &huge.outer})
    for (auto &q : *set) {
      q.x *= 20;
      q.y *= 20;
    }
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::PhotoModelTracker(S.rig, huge); }).find("does not fit the rig"), std::string::npos);
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, evalBudget(100));
  EXPECT_DOUBLE_EQ(t.tiltFilter().alpha, t.params().refinement.tiltFilter.alpha); // a one-view model: the one-view tilt filter
  EXPECT_DOUBLE_EQ(t.tiltFilter().beta, t.params().refinement.tiltFilter.beta);
  EXPECT_THROW(t.track(vpImage<vpRGBa>(240, 320), S.im.right), pm::core::Error);
  pm::tracker::TrackerParams v = evalBudget(100);
  v.verifier.budgetFraction = 1.0;
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, v); }).find("verification"), std::string::npos);
  pm::tracker::TrackerParams c = evalBudget(100);
  c.judgement.confidence.threshold = 1.5;
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, c); }).find("threshold"), std::string::npos);
  pm::tracker::TrackerParams u = evalBudget(100);
  u.judgement.uncertainty.floor[1] = -1;
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::PhotoModelTracker(S.rig, S.sm.build.model, u); }).find("uncertainty"), std::string::npos);
}

TEST(Tracker, WeighsTheCuesWithTheCoefficientsOfItsModelsKindUnlessGivenItsOwn)
{
  const C12Scene &S = c12(); // a flat model
  pm::tracker::TrackerParams p = evalBudget(100);
  p.judgement.confidence.threshold = 0.9;
  const pm::tracker::PhotoModelTracker flat(S.rig, S.sm.build.model, p);
  EXPECT_EQ(flat.params().judgement.confidence.kind, pm::tracker::ConfidenceKind::Flat);
  EXPECT_EQ(flat.params().judgement.confidence.weights, pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::Flat).weights);
  EXPECT_NE(flat.params().judgement.confidence.weights[4], 0.0); // the flat model weighs the tilt
  EXPECT_DOUBLE_EQ(flat.params().judgement.confidence.threshold, 0.9); // the threshold as given
  p.judgement.confidence.kind = pm::tracker::ConfidenceKind::Custom;
  p.judgement.confidence.weights.fill(0.25);
  const pm::tracker::PhotoModelTracker custom(S.rig, S.sm.build.model, p);
  EXPECT_EQ(custom.params().judgement.confidence.weights[4], 0.25);
  // The kinds that see the relief do not weigh the tilt; only the all-around one weighs the precise stage's cues.
  for (pm::tracker::ConfidenceKind k : {pm::tracker::ConfidenceKind::Stereo, pm::tracker::ConfidenceKind::AllAround}) {
    const pm::tracker::ConfidenceModel m = pm::tracker::ConfidenceModel::shipped(k);
    EXPECT_EQ(m.weights[4], 0.0) << pm::tracker::toString(k);
    EXPECT_FALSE(pm::tracker::ConfidenceModel::featuresUsed(k)[4]);
  }
  for (std::size_t i = 12; i < pm::tracker::ConfidenceCues::kFeatures; ++i) {
    EXPECT_EQ(pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::Stereo).weights[i], 0.0) << i;
    EXPECT_EQ(pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::Flat).weights[i], 0.0) << i;
    EXPECT_TRUE(pm::tracker::ConfidenceModel::featuresUsed(pm::tracker::ConfidenceKind::AllAround)[i]) << i;
  }
  EXPECT_THROW(pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::Auto), pm::core::Error);
  EXPECT_THROW(pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::Custom), pm::core::Error);
}

TEST(TrackerConfig, KeysGivenAsTextAreTheFilesKeysTheHeaderLeftOut)
{
  pm::tracker::TrackerParams p;
  p.search.budgetEvaluations = 777;
  p.refinement.tiltFilter.alpha = 0.3;
  p.judgement.uncertainty.floor[1] = 0.25;
  // The whole configuration as a file writes it, header and all, and its keys alone: the same parameters.
  const std::string file = pm::tracker::trackerConfigToJson(p);
  nlohmann::json keys = nlohmann::json::parse(file);
  keys.erase("format");
  keys.erase("version");
  for (const std::string &text : {file, keys.dump()}) {
    const pm::tracker::TrackerParams q = pm::tracker::trackerParamsFromJson(text);
    EXPECT_EQ(q.search.budgetEvaluations, 777);
    EXPECT_DOUBLE_EQ(q.refinement.tiltFilter.alpha, 0.3);
    EXPECT_DOUBLE_EQ(q.judgement.uncertainty.floor[1], 0.25);
    EXPECT_EQ(pm::tracker::trackerConfigToJson(q), file);
  }
  // A few keys over the caller's defaults; the rest kept.
  const pm::tracker::TrackerParams r = pm::tracker::trackerParamsFromJson(R"({"search": {"budget_evaluations": 400}})", p);
  EXPECT_EQ(r.search.budgetEvaluations, 400);
  EXPECT_DOUBLE_EQ(r.refinement.tiltFilter.alpha, 0.3);
  // An unknown key, a value out of range, not JSON, not an object: refused, naming what is wrong.
  EXPECT_NE(pm::test::errorOf([] { pm::tracker::trackerParamsFromJson(R"({"search": {"budget_evalutions": 400}})"); }).find("budget_evalutions"),
            std::string::npos);
  EXPECT_NE(pm::test::errorOf([] { pm::tracker::trackerParamsFromJson(R"({"search": {"budget_evaluations": -4}})"); }), "");
  EXPECT_NE(pm::test::errorOf([] { pm::tracker::trackerParamsFromJson("{"); }).find("not valid JSON"), std::string::npos);
  EXPECT_NE(pm::test::errorOf([] { pm::tracker::trackerParamsFromJson("[1, 2]"); }).find("object"), std::string::npos);
}

TEST(TrackerConfig, FileRoundTripAndErrors)
{
  pm::test::TempDir d("config");
  pm::tracker::TrackerParams p;
  p.search.budgetEvaluations = 1234;
  p.search.ga.population = 33;
  p.search.ga.predictMotion = true;
  p.fitness.inTolDeg = 25;
  p.steady.budgetFraction = 0.4;
  p.steady.hueMarginPx = 17;
  p.verifier.evaluations = 4321;
  p.verifier.sameObjectMm = 45;
  p.judgement.confidence.weights[2] = -3.25;
  p.judgement.confidence.threshold = 0.7;
  p.refinement.ascent.climb.maxEvaluations = 31;
  p.refinement.ascent.climb.minStepPx = 0.03;
  p.refinement.ascent.maxDrop = 0.04;
  p.refinement.tiltFilter.alpha = 0.35;
  p.refinement.tiltFilter.gateDeg = 7;
  p.refinement.tiltFilterAllAround.beta = 0.03;
  p.search.rejectMarginQ = 0.25;
  p.search.coarse = false;
  p.steady.escalation = false;
  p.judgement.confidence.kind = pm::tracker::ConfidenceKind::Custom;
  p.judgement.uncertainty.scale[3] = 2.5;
  p.judgement.uncertainty.floor[0] = 0.125;
  pm::test::writeText(d.file("t.json"), pm::tracker::trackerConfigToJson(p));
  const pm::tracker::TrackerParams q = pm::tracker::loadTrackerConfig(d.file("t.json"));
  EXPECT_EQ(q.search.budgetEvaluations, 1234);
  EXPECT_EQ(q.search.ga.population, 33);
  EXPECT_TRUE(q.search.ga.predictMotion);
  EXPECT_DOUBLE_EQ(q.fitness.inTolDeg, 25);
  EXPECT_DOUBLE_EQ(q.steady.budgetFraction, 0.4);
  EXPECT_EQ(q.steady.hueMarginPx, 17);
  EXPECT_EQ(q.verifier.evaluations, 4321);
  EXPECT_DOUBLE_EQ(q.verifier.sameObjectMm, 45);
  EXPECT_DOUBLE_EQ(q.judgement.confidence.weights[2], -3.25);
  EXPECT_DOUBLE_EQ(q.judgement.confidence.threshold, 0.7);
  EXPECT_EQ(q.judgement.confidence.kind, pm::tracker::ConfidenceKind::Custom);
  EXPECT_DOUBLE_EQ(q.judgement.uncertainty.scale[3], 2.5);
  EXPECT_DOUBLE_EQ(q.judgement.uncertainty.floor[0], 0.125);
  EXPECT_EQ(q.refinement.ascent.climb.maxEvaluations, 31);
  EXPECT_DOUBLE_EQ(q.refinement.ascent.climb.minStepPx, 0.03);
  EXPECT_DOUBLE_EQ(q.refinement.ascent.maxDrop, 0.04);
  EXPECT_DOUBLE_EQ(q.refinement.tiltFilter.alpha, 0.35);
  EXPECT_DOUBLE_EQ(q.refinement.tiltFilter.gateDeg, 7);
  EXPECT_DOUBLE_EQ(q.refinement.tiltFilterAllAround.beta, 0.03);
  EXPECT_DOUBLE_EQ(q.refinement.tiltFilterAllAround.alpha, pm::tracker::TrackerParams().refinement.tiltFilterAllAround.alpha);
  EXPECT_DOUBLE_EQ(q.search.rejectMarginQ, 0.25);
  EXPECT_FALSE(q.search.coarse);
  EXPECT_FALSE(q.steady.escalation);
  // The file is written in sections, one per part of the tracker (version 2).
  const nlohmann::json written = nlohmann::json::parse(pm::tracker::trackerConfigToJson(p));
  EXPECT_EQ(written.at("version"), 2);
  for (const char *part : {"fitness", "search", "lock", "steady", "verifier", "refinement", "judgement"})
    EXPECT_TRUE(written.at(part).is_object()) << part;
  EXPECT_EQ(written.at("search").at("rmga").at("population"), 33);
  EXPECT_EQ(written.at("refinement").at("ascent").at("max_evaluations"), 31);
  // A file with no keys gives the library's defaults, or the caller's.
  const std::string v2 = R"({"format":"visp-photomodel-tracker","version":2)";
  pm::test::writeText(d.file("empty.json"), v2 + "}");
  std::string notice = "x";
  EXPECT_EQ(pm::tracker::trackerConfigToJson(pm::tracker::loadTrackerConfig(d.file("empty.json"), pm::tracker::TrackerParams(), &notice)),
            pm::tracker::trackerConfigToJson(pm::tracker::TrackerParams()));
  EXPECT_EQ(notice, ""); // no notice for the current version
  EXPECT_EQ(pm::tracker::loadTrackerConfig(d.file("empty.json"), evalBudget(1234)).search.budgetEvaluations, 1234);
  // Partial files keep the defaults.
  pm::test::writeText(d.file("partial.json"), v2 + R"(,"search":{"rmga":{"seed":9}}})");
  EXPECT_EQ(pm::tracker::loadTrackerConfig(d.file("partial.json")).search.ga.seed, 9u);
  EXPECT_EQ(pm::tracker::loadTrackerConfig(d.file("partial.json")).search.ga.population, 20);
  // Weights written without a kind are meant to be used: the kind is then custom.
  pm::test::writeText(d.file("weights.json"), v2 + R"(,"judgement":{"confidence":{"weights":[1,1,1,1,1,1,1,1,1,1,1,1,0,0,0,0,0,0]}}})");
  EXPECT_EQ(pm::tracker::loadTrackerConfig(d.file("weights.json")).judgement.confidence.kind, pm::tracker::ConfidenceKind::Custom);
  pm::test::writeText(d.file("kind.json"), v2 + R"(,"judgement":{"confidence":{"kind":"all-around"}}})");
  EXPECT_EQ(pm::tracker::loadTrackerConfig(d.file("kind.json")).judgement.confidence.kind, pm::tracker::ConfidenceKind::AllAround);
  const std::vector<std::pair<std::string, std::string>> bad = {
      {v2 + R"(,"search":{"budget_ms":0}})", "budget"},
      {v2 + R"(,"search":{"rmga":{"populaton":10}}})", "populaton"},
      {v2 + R"(,"search":{"rmga":{"population":"many"}}})", "not valid"},
      {v2 + R"(,"lock":{"quality":0.1,"lost_quality":0.5}})", "lost < lock"},
      {v2 + R"(,"steady":{"budget_fraction":1.5}})", "steady"},
      {v2 + R"(,"verifier":{"budget_fraction":1}})", "verification"},
      {v2 + R"(,"refinement":{"ascent":{"shrink":1}}})", "smooth ascent"},
      {v2 + R"(,"refinement":{"ascent":{"steps":3}}})", "steps"},
      {v2 + R"(,"refinement":{"tilt_filter":{"alpha":0}}})", "tilt filter"},
      {v2 + R"(,"refinement":{"tilt_filter_all_around":{"beta":1}}})", "tilt filter"},
      {v2 + R"(,"refinement":{"precise":{"max_move_mm":0}}})", "precise stage"},
      {v2 + R"(,"judgement":{"confidence":{"threshold":0}}})", "threshold"},
      {v2 + R"(,"judgement":{"confidence":{"wieghts":[1]}}})", "wieghts"},
      {v2 + R"(,"judgement":{"confidence":{"kind":"round"}}})", "unknown kind"},
      {v2 + R"(,"judgement":{"uncertainty":{"scale":[1,1,0,1,1,1]}}})", "uncertainty"},
      {v2 + R"(,"budget_ms":24})", "unknown key \"budget_ms\""},                        // version 1's keys are not version 2's
      {v2 + R"(,"search":{"rmga":{"refine_evaluations":0}}})", "refine_evaluations"}, // a key of a refiner that is gone
      {R"({"format":"visp-photomodel-tracker","version":3})", "versions 1 and 2"},
      {"{ not json", "not valid"},
      {R"({"format":"x"})", "format"}};
  for (const auto &[text, expect] : bad) {
    pm::test::writeText(d.file("bad.json"), text);
    const std::string e = pm::test::errorOf([&] { pm::tracker::loadTrackerConfig(d.file("bad.json")); });
    EXPECT_NE(e.find(expect), std::string::npos) << text << " -> " << e;
  }
}

TEST(TrackerConfig, AFileOfVersionOneLoadsWithANoticeItsGoneRefinersIgnored)
{
  pm::test::TempDir d("config1");
  // Every flat key of version 1 lands in its part's section.
  pm::test::writeText(d.file("v1.json"), R"({"format":"visp-photomodel-tracker","version":1,
    "budget_ms":30,"budget_evaluations":900,"lock_quality":0.4,"lock_confidence":0.1,"lost_quality":0.25,"lost_frames":4,
    "init_spread":0.03,"steady_budget_fraction":0.2,"steady_after_frames":5,"steady_quality_drop":0.04,
    "steady_hue_margin_px":30,"steady_escalation":false,"smooth_refine_evaluations":77,"smooth_refine_max_drop":0.5,
    "smooth_ascent":{"max_evaluations":30,"grow":1.25},"smooth_ascent_max_drop":0.05,"reject_margin_q":0.2,
    "coarse_search":false,"precise_stage":false,"precise_max_drop_q":0.03,"precise_max_move_mm":10,
    "precise_max_move_deg":6,"precise_restart_mm":7,"precise_restart_deg":3,"precise":{"lines":120},
    "tilt_filter":{"alpha":0.3},"tilt_filter_all_around":{"gate_deg":6},"verify_evaluations":2500,
    "verify_budget_fraction":0.4,"verify_margin":0.03,"verify_switch_margin":0.04,"verify_far_mm":25,"verify_far_deg":6,
    "verify_same_object_mm":50,"reverify_after_frames":12,"reverify_below_confidence":0.4,
    "confidence":{"threshold":0.9},"uncertainty":{"floor":[0.1,0.1,0.1,0.1,0.1,0.1]},
    "search_space":{"lo":[-100,-100,400,-0.6,-0.6,-0.6]},"rmga":{"population":24,"refine_evaluations":100,"seed":5},
    "fitness":{"in_tol_deg":28}})");
  std::string notice;
  const pm::tracker::TrackerParams p = pm::tracker::loadTrackerConfig(d.file("v1.json"), pm::tracker::TrackerParams(), &notice);
  EXPECT_EQ(std::count(notice.begin(), notice.end(), '\n'), 0); // one line
  EXPECT_NE(notice.find("version 1"), std::string::npos) << notice;
  for (const char *gone : {"smooth_refine_evaluations", "smooth_refine_max_drop", "rmga.refine_evaluations"})
    EXPECT_NE(notice.find(gone), std::string::npos) << notice;
  EXPECT_DOUBLE_EQ(p.search.budgetMs, 30);
  EXPECT_EQ(p.search.budgetEvaluations, 900);
  EXPECT_DOUBLE_EQ(p.lock.quality, 0.4);
  EXPECT_DOUBLE_EQ(p.lock.confidence, 0.1);
  EXPECT_DOUBLE_EQ(p.lock.lostQuality, 0.25);
  EXPECT_EQ(p.lock.lostFrames, 4);
  EXPECT_DOUBLE_EQ(p.search.initSpread, 0.03);
  EXPECT_DOUBLE_EQ(p.steady.budgetFraction, 0.2);
  EXPECT_EQ(p.steady.afterFrames, 5);
  EXPECT_DOUBLE_EQ(p.steady.qualityDrop, 0.04);
  EXPECT_EQ(p.steady.hueMarginPx, 30);
  EXPECT_FALSE(p.steady.escalation);
  EXPECT_EQ(p.refinement.ascent.climb.maxEvaluations, 30);
  EXPECT_DOUBLE_EQ(p.refinement.ascent.climb.grow, 1.25);
  EXPECT_DOUBLE_EQ(p.refinement.ascent.maxDrop, 0.05);
  EXPECT_DOUBLE_EQ(p.search.rejectMarginQ, 0.2);
  EXPECT_FALSE(p.search.coarse);
  EXPECT_FALSE(p.refinement.precise.enabled);
  EXPECT_DOUBLE_EQ(p.refinement.precise.maxDropQ, 0.03);
  EXPECT_DOUBLE_EQ(p.refinement.precise.maxMoveMm, 10);
  EXPECT_DOUBLE_EQ(p.refinement.precise.maxMoveDeg, 6);
  EXPECT_DOUBLE_EQ(p.refinement.precise.restartMm, 7);
  EXPECT_DOUBLE_EQ(p.refinement.precise.restartDeg, 3);
  EXPECT_EQ(p.refinement.precise.stage.lines, 120u);
  EXPECT_DOUBLE_EQ(p.refinement.tiltFilter.alpha, 0.3);
  EXPECT_DOUBLE_EQ(p.refinement.tiltFilterAllAround.gateDeg, 6);
  EXPECT_EQ(p.verifier.evaluations, 2500);
  EXPECT_DOUBLE_EQ(p.verifier.budgetFraction, 0.4);
  EXPECT_DOUBLE_EQ(p.verifier.margin, 0.03);
  EXPECT_DOUBLE_EQ(p.verifier.switchMargin, 0.04);
  EXPECT_DOUBLE_EQ(p.verifier.farMm, 25);
  EXPECT_DOUBLE_EQ(p.verifier.farDeg, 6);
  EXPECT_DOUBLE_EQ(p.verifier.sameObjectMm, 50);
  EXPECT_EQ(p.verifier.reverifyAfterFrames, 12);
  EXPECT_DOUBLE_EQ(p.verifier.reverifyBelowConfidence, 0.4);
  EXPECT_DOUBLE_EQ(p.judgement.confidence.threshold, 0.9);
  EXPECT_DOUBLE_EQ(p.judgement.uncertainty.floor[3], 0.1);
  EXPECT_DOUBLE_EQ(p.search.space.lo[2], 400);
  EXPECT_EQ(p.search.ga.population, 24);
  EXPECT_EQ(p.search.ga.seed, 5u);
  EXPECT_DOUBLE_EQ(p.fitness.inTolDeg, 28);
  // Written again, it is a file of version 2 with the same parameters and no notice.
  pm::test::writeText(d.file("v2.json"), pm::tracker::trackerConfigToJson(p));
  EXPECT_EQ(pm::tracker::trackerConfigToJson(pm::tracker::loadTrackerConfig(d.file("v2.json"), pm::tracker::TrackerParams(), &notice)),
            pm::tracker::trackerConfigToJson(p));
  EXPECT_EQ(notice, "");
  // Version 1's rules hold: an unknown key is refused, weights without a kind are custom.
  const std::string v1 = R"({"format":"visp-photomodel-tracker","version":1)";
  pm::test::writeText(d.file("bad1.json"), v1 + R"(,"lock_qualty":0.3})");
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::loadTrackerConfig(d.file("bad1.json")); }).find("lock_qualty"), std::string::npos);
  pm::test::writeText(d.file("bad2.json"), v1 + R"(,"rmga":{"populaton":10}})");
  EXPECT_NE(pm::test::errorOf([&] { pm::tracker::loadTrackerConfig(d.file("bad2.json")); }).find("populaton"), std::string::npos);
  pm::test::writeText(d.file("weights1.json"), v1 + R"(,"confidence":{"weights":[1,1,1,1,1,1,1,1,1,1,1,1,0,0,0,0,0,0]}})");
  EXPECT_EQ(pm::tracker::loadTrackerConfig(d.file("weights1.json")).judgement.confidence.kind, pm::tracker::ConfidenceKind::Custom);
}

TEST(TiltFilter, SmoothsTheTiltOnlyFollowsASteadyTurnAndRestartsOnAJump)
{
  pm::tracker::TiltFilter f; // alpha 0.2, beta 0.02, gate 5 deg
  const pm::core::Phi truth{10, -20, 500, 0.03, -0.02, 0.1};
  // Measurements whose tilt alternates +-1 deg about the truth, whose position and turn about z
  // (e3) jitter too: the tilt comes out much steadier, the rest exactly as measured.
  std::vector<double> tiltErr;
  for (int k = 0; k < 60; ++k) {
    const double s = k % 2 ? 1.0 : -1.0;
    const double d[6] = {0.5 * s, -0.3 * s, 1.0 * s, s * 0.0175, -s * 0.0175, 0.01 * s};
    const pm::core::Phi z = pm::core::applyTwist(truth, d);
    const pm::core::Phi out = f.update(z);
    EXPECT_EQ(out.x, z.x);
    EXPECT_EQ(out.y, z.y);
    EXPECT_EQ(out.z, z.z);
    if (k >= 30)
      tiltErr.push_back(pm::core::rotationDistanceDeg(pm::core::Phi{0, 0, 0, out.e1, out.e2, 0}, pm::core::Phi{0, 0, 0, truth.e1, truth.e2, 0}));
    // The turn about the hand's z axis passes: the rotation from the output to the measurement has no z part.
    const vpThetaUVector r(pm::core::toHomogeneousMatrix(z).getRotationMatrix() * pm::core::toHomogeneousMatrix(out).getRotationMatrix().t());
    EXPECT_NEAR(r[2], 0.0, 1e-3) << k;
  }
  for (double e : tiltErr)
    EXPECT_LT(e, 0.6); // the measurements are 1.4 deg off (1 deg about x and y)
  // A steady tilting (0.5 deg per frame about x) is followed without a lasting lag.
  pm::tracker::TiltFilter g;
  pm::core::Phi p = truth, out;
  for (int k = 0; k < 80; ++k) {
    const double turn[6] = {0, 0, 0, 0.5 * M_PI / 180, 0, 0};
    p = pm::core::applyTwist(p, turn);
    out = g.update(p);
  }
  EXPECT_LT(pm::core::rotationDistanceDeg(out, p), 0.1);
  // A jump past the gate: taken as measured, and the filter starts from it.
  const double jump[6] = {0, 0, 0, 0.2, 0, 0}; // 11 deg
  const pm::core::Phi j = pm::core::applyTwist(p, jump), gj = g.update(j);
  EXPECT_EQ(gj.e1, j.e1);
  EXPECT_EQ(gj.e2, j.e2);
  EXPECT_EQ(gj.e3, j.e3);
  // The hand moves: the filtered pose moves with it, so a still target stays still.
  pm::tracker::TiltFilter h;
  for (int k = 0; k < 5; ++k)
    h.update(truth);
  vpHomogeneousMatrix hNowMhPrev(0.01, 0, 0, 0, vpMath::rad(2), 0);
  h.transform(hNowMhPrev);
  const pm::core::Phi seen = pm::core::fromHomogeneousMatrix(hNowMhPrev * pm::core::toHomogeneousMatrix(truth));
  EXPECT_LT(pm::core::rotationDistanceDeg(h.update(seen), seen), 1e-6);
  // Off (alpha 1, beta 0): every pose passes unchanged; bad gains are refused.
  pm::tracker::TiltFilterParams off;
  off.alpha = 1;
  off.beta = 0;
  pm::tracker::TiltFilter o(off);
  EXPECT_EQ(o.update(truth).e1, truth.e1);
  EXPECT_THROW(o.update({0, 0, 500, 0.9, 0.9, 0}), pm::core::Error);
  pm::tracker::TiltFilterParams bad;
  bad.alpha = 0;
  EXPECT_THROW(pm::tracker::TiltFilter{bad}, pm::core::Error);
  bad = pm::tracker::TiltFilterParams();
  bad.gateDeg = -1;
  EXPECT_THROW(pm::tracker::TiltFilter{bad}, pm::core::Error);
}

TEST(MotionPrediction, CarriesAConstantMotionOnFollowsTheHandAndForgetsJumpsAndSearches)
{
  // A target moving on at 1.2 mm and turning 1.5 deg a frame about a tilted axis through its origin.
  const auto truthAt = [](int k) {
    const vpThetaUVector turn(vpMath::rad(1.5 * k) * 0.6, vpMath::rad(1.5 * k) * 0.8, 0);
    vpHomogeneousMatrix M;
    M.insert(vpRotationMatrix(turn) * vpRotationMatrix(vpThetaUVector(0.2, -0.1, 0.3)));
    M.insert(vpTranslationVector(0.010 + 0.0010 * k, -0.020 + 0.0006 * k, 0.500 - 0.0003 * k));
    return M;
  };
  const auto tracked = [](const vpHomogeneousMatrix &hMo, bool precise = true) {
    pm::tracker::TrackResult r;
    r.hMo = hMo;
    r.phi = pm::core::fromHomogeneousMatrix(hMo);
    r.state = pm::tracker::TrackState::Tracking;
    r.precise = precise;
    return r;
  };
  const auto phiOf = [](const vpHomogeneousMatrix &M) { return pm::core::fromHomogeneousMatrix(M); };
  // (Rotations compared within 1e-4 deg: rotationDistanceDeg's acos near 1 resolves about 2e-6 deg.)
  const pm::tracker::MotionPrediction m; // gain 1
  pm::tracker::PoseHistory h;
  h.remember(tracked(truthAt(0)));
  EXPECT_FALSE(m.moving(h)); // one pose: nothing to predict from
  EXPECT_EQ(m.predict(h).x, phiOf(truthAt(0)).x);
  for (int k = 1; k < 6; ++k) {
    h.remember(tracked(truthAt(k)));
    ASSERT_TRUE(m.moving(h));
    const pm::core::Phi p = m.predict(h), next = phiOf(truthAt(k + 1));
    EXPECT_LT(pm::core::translationDistanceMm(p, next), 1e-6) << k;
    EXPECT_LT(pm::core::rotationDistanceDeg(p, next), 1e-4) << k;
    EXPECT_GT(pm::core::rotationDistanceDeg(phiOf(truthAt(k)), next), 1.4); // the last pose itself is 1.5 deg behind
  }
  // The hand moves by M between frames: the target's own motion is still predicted, in the new hand frame.
  const vpHomogeneousMatrix M(0.004, -0.002, 0.003, vpMath::rad(2), vpMath::rad(-1), vpMath::rad(3));
  h.transform(M);
  const pm::core::Phi p = m.predict(h), next = phiOf(M * truthAt(6));
  EXPECT_LT(pm::core::translationDistanceMm(p, next), 1e-6);
  EXPECT_LT(pm::core::rotationDistanceDeg(p, next), 1e-4);
  EXPECT_LT(pm::core::translationDistanceMm(h.last().phi, phiOf(M * truthAt(5))), 1e-6); // the last pose followed the hand too
  // A jump to another pose (the lock verifier's) forgets the motion: the last pose as it is.
  pm::tracker::PoseHistory jumped = h;
  jumped.forgetMotion();
  EXPECT_FALSE(m.moving(jumped));
  EXPECT_EQ(m.predict(jumped).z, jumped.last().phi.z);
  // A frame the precise stage did not make forgets the motion; so does a lost frame.
  pm::tracker::PoseHistory f;
  f.remember(tracked(truthAt(0)));
  f.remember(tracked(truthAt(1)));
  ASSERT_TRUE(m.moving(f));
  f.remember(tracked(truthAt(2), false));
  f.remember(tracked(truthAt(3)));
  EXPECT_FALSE(m.moving(f));
  pm::tracker::TrackResult lost = tracked(truthAt(4));
  lost.state = pm::tracker::TrackState::Lost;
  f.remember(tracked(truthAt(4)));
  ASSERT_TRUE(m.moving(f));
  f.remember(lost);
  EXPECT_FALSE(m.moving(f));
  // A step past the largest turn (3 deg) is a jump: no prediction.
  pm::tracker::PoseHistory j;
  j.remember(tracked(truthAt(0)));
  j.remember(tracked(truthAt(3))); // 4.5 deg in one frame
  EXPECT_FALSE(m.moving(j));
  EXPECT_EQ(m.predict(j).e1, phiOf(truthAt(3)).e1);
  // Gain 0: off; half the gain, half the step; bad parameters refused.
  pm::tracker::MotionPredictionParams halfGain;
  halfGain.gain = 0.5;
  halfGain.maxStepDeg = 6; // the two frames below are 3 deg apart
  pm::tracker::PoseHistory two;
  two.remember(tracked(truthAt(0)));
  two.remember(tracked(truthAt(2)));
  const pm::core::Phi ph = pm::tracker::MotionPrediction(halfGain).predict(two);
  EXPECT_LT(pm::core::translationDistanceMm(ph, phiOf(truthAt(3))), 1e-6);
  EXPECT_LT(pm::core::rotationDistanceDeg(ph, phiOf(truthAt(3))), 1e-4);
  pm::tracker::MotionPredictionParams off;
  off.gain = 0;
  EXPECT_FALSE(pm::tracker::MotionPrediction(off).moving(f));
  EXPECT_FALSE(pm::tracker::MotionPrediction(off).moving(h));
  pm::tracker::MotionPredictionParams bad;
  bad.gain = -0.1;
  EXPECT_THROW(pm::tracker::MotionPrediction{bad}, pm::core::Error);
  bad = pm::tracker::MotionPredictionParams();
  bad.maxStepDeg = 0;
  EXPECT_THROW(pm::tracker::MotionPrediction{bad}, pm::core::Error);
}

TEST(PoseHistory, KeepsThePoseBeforeTheLastOnlyWhenBothWereTrackedAndFollowsTheHand)
{
  const auto frame = [](double x, pm::tracker::TrackState state) {
    pm::tracker::TrackResult r;
    r.phi = pm::core::Phi{x, -20, 500, 0.1, -0.05, 0.2};
    r.hMo = pm::core::toHomogeneousMatrix(r.phi);
    r.state = state;
    return r;
  };
  pm::tracker::PoseHistory h;
  EXPECT_EQ(h.last().state, pm::tracker::TrackState::Searching); // nothing seen yet
  EXPECT_EQ(h.beforeLast(), nullptr);
  h.remember(frame(10, pm::tracker::TrackState::Searching));
  h.remember(frame(12, pm::tracker::TrackState::Tracking));
  EXPECT_EQ(h.beforeLast(), nullptr); // the one before was not tracked
  h.remember(frame(14, pm::tracker::TrackState::Tracking));
  ASSERT_NE(h.beforeLast(), nullptr);
  EXPECT_DOUBLE_EQ(h.beforeLast()->x, 12.0);
  EXPECT_DOUBLE_EQ(h.last().phi.x, 14.0);
  EXPECT_EQ(h.preciseCount(), 0); // none of them the precise stage's
  // The hand moves 5 mm along its x axis: the target is 5 mm further along it, in both poses.
  const vpHomogeneousMatrix M(0.005, 0, 0, 0, 0, 0);
  h.transform(M);
  EXPECT_NEAR(h.beforeLast()->x, 17.0, 1e-9);
  EXPECT_NEAR(h.last().phi.x, 19.0, 1e-9);
  EXPECT_NEAR(h.last().hMo[0][3], 0.019, 1e-12);
  // A lost frame: nothing before it; a reset: its first frame, nothing before.
  h.remember(frame(16, pm::tracker::TrackState::Lost));
  EXPECT_EQ(h.beforeLast(), nullptr);
  h.remember(frame(18, pm::tracker::TrackState::Tracking));
  h.remember(frame(20, pm::tracker::TrackState::Tracking));
  ASSERT_NE(h.beforeLast(), nullptr);
  h.reset(frame(30, pm::tracker::TrackState::Tracking));
  EXPECT_EQ(h.beforeLast(), nullptr);
  EXPECT_DOUBLE_EQ(h.last().phi.x, 30.0);
}

TEST(PoseHistory, APoseMovedWithTheHandFollowsTheHandsMotionAndOneThatCannotBeReadStays)
{
  const pm::core::Phi p{10, -20, 500, 0.1, -0.05, 0.2};
  const vpHomogeneousMatrix M(0.005, 0.002, -0.001, vpMath::rad(2), vpMath::rad(-1), 0);
  const pm::core::Phi q = pm::tracker::movedWithHand(M, p);
  const pm::core::Phi expected = pm::core::fromHomogeneousMatrix(M * pm::core::toHomogeneousMatrix(p));
  EXPECT_LT(pm::core::translationDistanceMm(q, expected), 1e-9);
  EXPECT_LT(pm::core::rotationDistanceDeg(q, expected), 1e-4);
  EXPECT_GT(pm::core::translationDistanceMm(q, p), 5.0); // it did move
  vpHomogeneousMatrix broken = M;
  broken[0][3] = std::numeric_limits<double>::quiet_NaN();
  const pm::core::Phi kept = pm::tracker::movedWithHand(broken, p);
  EXPECT_EQ(kept.x, p.x);
  EXPECT_EQ(kept.e3, p.e3);
}

TEST(Tracker, SearchingFramesScoreManyPosesCoarselyAndReportTheExactFitness)
{
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(800);
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, p);
  t.initialize();
  const pm::tracker::TrackResult r = t.track(S.im.left, S.im.right); // searching: every candidate on a quarter of the points
  EXPECT_LE(r.evaluations, 801); // the work within the budget (and the best scored exactly)
  EXPECT_GT(r.candidates, 3 * r.evaluations);
  EXPECT_DOUBLE_EQ(r.fitness, t.fitness().evaluate(r.phi)); // F itself, not the estimate
  // Without the coarse search (only the early rejection of hopeless children) it scores under half as many.
  p.search.coarse = false;
  pm::tracker::PhotoModelTracker u(S.rig, S.sm.build.model, p);
  u.initialize();
  const pm::tracker::TrackResult q = u.track(S.im.left, S.im.right);
  EXPECT_LE(q.evaluations, 800);
  EXPECT_LT(2 * q.candidates, r.candidates);
}

TEST(Tracker, TheSmoothAscentRunsOnLockedFramesWithinItsBudgetAndTheFrameTimeIsAccountedFor)
{
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(400);
  p.refinement.ascent.climb.maxEvaluations = 10;
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, p);
  t.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  int climbed = 0;
  for (int k = 0; k < 20; ++k) {
    const pm::tracker::TrackResult r = t.track(S.im.left, S.im.right);
    EXPECT_LE(r.ascentEvaluations, 10);
    if (r.state == pm::tracker::TrackState::Tracking && r.quality >= p.lock.quality) {
      ++climbed;
      EXPECT_GT(r.ascentEvaluations, 0);
    }
    EXPECT_DOUBLE_EQ(r.fitness, t.fitness().evaluate(r.phi)); // the fitness reported is the pose's
    double sum = 0;
    for (double ms : r.steps.values()) {
      EXPECT_GE(ms, 0.0);
      sum += ms;
    }
    EXPECT_NEAR(sum, r.computeMs, 1e-6);
  }
  EXPECT_GT(climbed, 15);
  // Off: no climb.
  p.refinement.ascent.climb.maxEvaluations = 0;
  pm::tracker::PhotoModelTracker u(S.rig, S.sm.build.model, p);
  u.initFromPose(pm::core::toHomogeneousMatrix(S.truth));
  EXPECT_EQ(u.track(S.im.left, S.im.right).ascentEvaluations, 0);
}

TEST(StaticDetection, FindsTheStillTargetStopsByItsRulesAndTheNearestPeakScoresAtLeastTheTruth)
{
  // The paper's Table 1 on one still pair: the search runs frame after frame on it until the best
  // has not improved for `patience` frames; the fitness peak nearest the truth is where a perfect
  // detector would land.
  const C12Scene &S = c12();
  pm::tracker::TrackerParams p = evalBudget(3000);
  p.search.ga.population = 100;
  p.search.ga.restartGenerations = 30;
  pm::tracker::PhotoModelTracker t(S.rig, S.sm.build.model, p);
  t.initialize();
  pm::tracker::DetectionParams dp;
  dp.patience = 15;
  dp.maxTimeS = 600; // never reached: the patience stops it
  const pm::tracker::Detection d = pm::tracker::detectStatic(t, {S.im.left, S.im.right}, dp);
  EXPECT_EQ(d.best.state, pm::tracker::TrackState::Tracking);
  EXPECT_NEAR(d.best.phi.x, S.truth.x, 2.0);
  EXPECT_NEAR(d.best.phi.y, S.truth.y, 2.0);
  EXPECT_NEAR(d.best.phi.e3, S.truth.e3, 0.02);
  EXPECT_GT(d.frames, dp.patience);
  EXPECT_LE(d.evaluations, d.totalEvaluations);
  EXPECT_GT(d.evaluations, 0);
  EXPECT_LE(d.convergedS, d.totalS);
  const double fTruth = t.fitness().evaluate(S.truth);
  EXPECT_GE(d.best.fitness, fTruth);

  const pm::core::Phi peak = pm::tracker::nearestFitnessPeak(t.fitness(), S.truth, p.search.space);
  EXPECT_GE(t.fitness().evaluate(peak), fTruth);
  EXPECT_LT(pm::core::translationDistanceMm(peak, S.truth), 8.0); // the flat model's own bias on a 40 mm deep toy
  EXPECT_LT(pm::core::translationDistanceMm(peak, d.best.phi), 4.0); // the detection lands on the peak rather than on the truth

  // Without patience, the time limit stops it.
  pm::tracker::PhotoModelTracker t2(S.rig, S.sm.build.model, p);
  t2.initialize();
  dp.patience = 1000000;
  dp.maxTimeS = 0.3;
  const pm::tracker::Detection d2 = pm::tracker::detectStatic(t2, {S.im.left, S.im.right}, dp);
  EXPECT_GE(d2.totalS, 0.3);
  EXPECT_LT(d2.frames, 1000000);
}
