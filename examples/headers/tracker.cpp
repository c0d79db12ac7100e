// The usage examples of pm::tracker's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/tracker/AscentRefinement.h"
#include "pm/tracker/BackgroundLearning.h"
#include "pm/tracker/FramePlan.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/Judgement.h"
#include "pm/tracker/LockState.h"
#include "pm/tracker/LockVerifier.h"
#include "pm/tracker/MotionPrediction.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/PoseHistory.h"
#include "pm/tracker/PoseSearch.h"
#include "pm/tracker/LandingCorrection.h"
#include "pm/tracker/PreciseRefinement.h"
#include "pm/tracker/QualityScale.h"
#include "pm/tracker/RangeCorrection.h"
#include "pm/tracker/RefinementChain.h"
#include "pm/tracker/RmGaUpdate.h"
#include "pm/tracker/StaticDetection.h"
#include "pm/tracker/SteadyFramePolicy.h"
#include "pm/tracker/TrackConfidence.h"
#include "pm/tracker/TrackResult.h"
#include "pm/tracker/TrackerConfigFile.h"
#include "pm/tracker/TrackerParams.h"

#include <fstream>
#include <iostream>
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/tracker/TiltFilter.h"
namespace pm_examples {

pm::core::Phi estimate();
void use(const pm::core::Phi &pose);

// What an example leaves to its reader (declared, never defined: this file is compiled, never linked).
void use(const vpHomogeneousMatrix &hMo);
void moveTo(const pm::tracker::ScoredPose &better);
pm::tracker::TrackResult trackFrom(const pm::core::Phi &start);

// AscentRefinement.h
void exampleAscentRefinement(const pm::tracker::TrackerParams &params, const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame,
                             const pm::tracker::ScoredPose &searched, const pm::tracker::PoseHistory &history, pm::tracker::ScoredPose &pose)
{
  pm::tracker::AscentRefinement ascent(params.refinement.ascent, scorer);
  if (ascent.active()) {
    const pm::tracker::AscentRefinement::Climb c = ascent.refine(frame, searched, history);
    if (c.kept)
      pose = c.pose;                 // the climb's pose and F
  }
}

// BackgroundLearning.h
void exampleBackgroundLearning(const pm::tracker::TrackerParams &params, const pm::core::StereoScorer &scorer, pm::core::HueFrame &frame, const pm::tracker::TrackResult &result)
{
  pm::tracker::BackgroundLearning bg(params.background, scorer);
  // after each frame's judgement:
  if (const std::optional<double> hue = bg.learn(frame, result.phi, result.trusted))
    frame.setBackgroundHue(*hue);
}

// FrameSteps.h
void exampleFrameSteps(const pm::core::Phi &phi, double F, const pm::tracker::SearchWork &work, pm::tracker::RefinementChain &chain,
                       const pm::core::HueFrame &frame, const pm::tracker::PoseHistory &history, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR,
                       bool locked, const pm::tracker::Judgement &judgement, const pm::tracker::JudgedState &state)
{
  const pm::tracker::SearchedPose searched{{phi, F}, work};
  const pm::tracker::RefinedPose refined = chain.refine(frame, searched.pose, history, {IL, IR}, locked);
  const pm::tracker::Evidence e = judgement.measure(frame, refined);
  const pm::tracker::Verdict verdict = judgement.judge(refined, e, state);
  if (verdict.trusted)
    use(pm::core::toHomogeneousMatrix(refined.pose.phi));
}

// FramePlan.h
void exampleFramePlan(const pm::tracker::TrackerParams &params, const pm::tracker::SteadyFramePolicy &steady, const pm::tracker::LockVerifier &verifier, pm::tracker::TrackState state, double hueMs,
                      pm::rmga::RmGa &ga, pm::rmga::FitnessFunction &objective)
{
  pm::tracker::FramePlan plan = steady.plan(verifier.verifying(state));
  plan.hueMs = hueMs;
  plan.setBudgets(params.search, params.steady, params.verifier);
  const pm::rmga::FrameResult r = ga.evolve(objective, plan.main);
}

// Judgement.h
void exampleJudgement(const pm::tracker::TrackerParams &params, const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::tracker::QualityScale &scale, const pm::precise::ModelErrorFloor &modelError,
                      const pm::tracker::RefinedPose &refined, const pm::tracker::PoseHistory &history, const pm::tracker::LockState &lock, const pm::tracker::SteadyFramePolicy &steady,
                      const pm::tracker::LockVerifier &verifier)
{
  pm::tracker::Judgement judgement(params.judgement, params.verifier.farDeg, scorer, scale, modelError);
  const pm::tracker::Evidence e = judgement.measure(frame, refined); // refined: the refinement chain's pose
  const double q = scale.quality(refined.pose.fitness);
  const bool refused = lock.wouldLock(q) &&
                       judgement.firstLockConfidence(e, steady.recentBestQ(), params.verifier.evaluations == 0) < params.lock.confidence;
  // ... the lock's state from q and refused (LockState.h), then:
  pm::tracker::JudgedState state;
  state.state = lock.state();
  state.last = &history.last().phi; // the last frame's pose, when it was tracked
  state.recentBestQ = steady.recentBestQ();
  state.framesTracked = lock.framesTracked();
  state.verified = verifier.verified();
  state.lookingAgain = verifier.lookingAgain();
  const pm::tracker::Verdict verdict = judgement.judge(refined, e, state);
  if (verdict.trusted)
    use(pm::core::toHomogeneousMatrix(refined.pose.phi));
}

// LockState.h
void exampleLockState(const pm::tracker::TrackerParams &params, double q, double firstLockConfidence, pm::tracker::PoseSearch &search)
{
  pm::tracker::LockState lock(params.lock);
  // refused: the first lock's confidence under params.lock.confidence (Judgement::firstLockConfidence)
  const bool refused = lock.wouldLock(q) && firstLockConfidence < params.lock.confidence;
  pm::tracker::RmGaUpdate update;
  update.restart = lock.update(q, refused); // search again around the best (lost) or away from it (refused)
  search.apply(update);
}

// LockVerifier.h
void exampleLockVerifier(const pm::tracker::TrackerParams &params, const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::tracker::QualityScale &scale, pm::tracker::TrackState lastState, pm::tracker::TrackState prev, const pm::tracker::FramePlan &plan,
                         const pm::tracker::SearchedPose &searched, pm::tracker::SearchWork &work, const pm::tracker::ScoredPose &pose, pm::tracker::TrackState state,
                         const pm::tracker::Verdict &verdict, const pm::tracker::PoseSearch &search, pm::tracker::RefinementChain &chain,
                         const pm::core::CameraImages &images)
{
  pm::tracker::LockVerifier verifier(params.verifier, params.search, scorer, scale);
  const pm::tracker::LockVerifier::Settle settle = [&](const pm::core::Phi &phi) { return chain.settle(phi, images); }; // a second opinion
  if (verifier.verifying(lastState)) {
    const pm::tracker::LockVerifier::Challenge c = verifier.challenge(frame, plan.challenger, searched.pose, search.ga(), settle);
    work = work.plus(c.run);
    if (c.better)
      moveTo(*c.better); // a wrong first lock
  }
  verifier.onState(prev, state, pose.phi, search.ga());                      // a new lock is verified on the next frames
  verifier.afterJudgement(state, verdict.confidence, pose.phi, search.ga()); // a doubtful lock again
}

// MotionPrediction.h
void exampleMotionPrediction(const vpHomogeneousMatrix &hNowMhPrev)
{
  const pm::tracker::MotionPrediction motion;        // gain 1
  pm::tracker::PoseHistory history;
  for (;;) {
    const pm::core::Phi start = motion.predict(history); // the last pose moved on, or as it is
    const pm::tracker::TrackResult r = trackFrom(start);
    history.remember(r);                             // at the frame's end
    history.transform(hNowMhPrev);                   // the hand moved
  }
}

// PoseHistory.h
pm::tracker::TrackResult trackFrame(const pm::tracker::PoseHistory &history);
void examplePoseHistory(const vpHomogeneousMatrix &hNowMhPrev)
{
  pm::tracker::PoseHistory history;                 // nothing seen yet: last() is a searching frame
  for (;;) {
    const pm::tracker::TrackResult r = trackFrame(history); // the steps read history.last(), beforeLast(), ...
    history.remember(r);                            // at the frame's end
    history.transform(hNowMhPrev);                  // the hand moved
  }
}

// PoseSearch.h
void examplePoseSearch(const pm::tracker::TrackerParams &params, const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::tracker::QualityScale &scale, const pm::tracker::FramePlan &plan)
{
  pm::tracker::PoseSearch search(params.search, scorer, scale);
  search.initialize();                                   // a random population
  const pm::rmga::FrameResult r = search.evolve(frame, plan.main, pm::tracker::PoseSearch::Scoring::Exact); // tracked: every point
  pm::tracker::RmGaUpdate u;
  u.anchor = r.best;                                     // trusted
  search.apply(u);
}

// PreciseRefinement.h
void examplePreciseRefinement(const pm::tracker::TrackerParams &params, const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::tracker::QualityScale &scale,
                              const pm::tracker::ScoredPose &searched, const pm::tracker::PoseHistory &history, const pm::tracker::MotionPrediction &motion, const vpImage<vpRGBa> &IL,
                              const vpImage<vpRGBa> &IR, pm::tracker::PoseSearch &search)
{
  pm::tracker::PreciseRefinement stage(params.refinement.precise, rig, model, scorer, scale);
  const pm::tracker::PreciseRefinement::Attempt a = stage.refine(frame, searched, history, motion.predict(history), {IL, IR});
  if (a.kept) {
    pm::tracker::RmGaUpdate u;
    u.inject = pm::tracker::RmGaUpdate::Inject{a.pose.phi, a.pose.fitness}; // the frame's pose is the stage's: it joins RM-GA
    search.apply(u);
  }
}

// QualityScale.h
void exampleQualityScale(const pm::core::PhotoModel &model, const pm::core::StereoFitness &fitness, const pm::core::Phi &phi, double F)
{
  const pm::tracker::QualityScale scale(model, pm::tracker::trackerFitnessDefaults());
  const double q = scale.quality(fitness.evaluate(phi));
  const double minF = F - scale.fitnessSpan(0.02); // F lower by 0.02 in q
}

// RefinementChain.h
void exampleRefinementChain(const pm::tracker::TrackerParams &params, const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::tracker::QualityScale &scale,
                            const pm::tracker::SearchedPose &searched, const pm::tracker::PoseHistory &history, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR, bool locked,
                            pm::tracker::PoseSearch &search)
{
  pm::tracker::RefinementChain chain(params.refinement, rig, model, scorer, scale);
  const pm::tracker::RefinedPose refined = chain.refine(frame, searched.pose, history, {IL, IR}, locked);
  pm::tracker::RmGaUpdate u;
  if (refined.precise) // the precise stage's pose joins RM-GA
    u.inject = pm::tracker::RmGaUpdate::Inject{refined.pose.phi, refined.pose.fitness};
  search.apply(u);
}

// RmGaUpdate.h
void exampleRmGaUpdate(const pm::core::Phi &betterPose, const pm::core::Phi &trustedPose, pm::tracker::PoseSearch &search)
{
  pm::tracker::RmGaUpdate u;
  u.reseed = pm::tracker::RmGaUpdate::Reseed{betterPose, 0.02};
  u.anchor = trustedPose;
  search.apply(u);
}

// StaticDetection.h
void exampleStaticDetection(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  pm::tracker::PhotoModelTracker tracker(rig, model);
  tracker.initialize();
  const pm::tracker::Detection d = pm::tracker::detectStatic(tracker, {left, right}, pm::tracker::DetectionParams());
  std::cout << d.best.phi.toString() << " after " << d.convergedS << " s\n";
}

// SteadyFramePolicy.h
void exampleSteadyFramePolicy(const pm::tracker::TrackerParams &params, bool verifying, const pm::core::StereoScorer &scorer, pm::core::HueFrame &frame, const pm::tracker::QualityScale &scale, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR, const pm::tracker::PoseHistory &history,
                              pm::tracker::PoseSearch &search, pm::tracker::TrackState state)
{
  pm::tracker::SteadyFramePolicy steady(params.steady);
  const pm::tracker::FramePlan plan = steady.plan(verifying); // before the frame
  const pm::core::CameraImages images(IL, IR);                 // one image per camera
  if (plan.windowed)
    scorer.setImages(frame, images.data(), steady.windows(scorer, history).data());
  else
    scorer.setImages(frame, images.data());
  const pm::rmga::FrameResult r = search.evolve(frame, plan.main, pm::tracker::PoseSearch::Scoring::Exact);
  if (plan.steady && steady.escalates(scale.quality(r.fitness))) // after the steady search: it went wrong
    search.evolve(frame, plan.mainWhole, pm::tracker::PoseSearch::Scoring::Exact, pm::tracker::PoseSearch::Generations::SameFrame);
  steady.update(state, scale.quality(r.fitness));                // after the frame's state
}

// TrackConfidence.h
void exampleTrackConfidence(const pm::tracker::ConfidenceCues &cues, const vpHomogeneousMatrix &pose)
{
  pm::tracker::ConfidenceModel m;                 // the shipped coefficients
  const double c = m.confidence(cues);   // in (0, 1)
  if (c >= m.threshold) use(pose);
}

// TrackResult.h
void exampleTrackResult(pm::tracker::PhotoModelTracker &tracker, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR)
{
  const pm::tracker::TrackResult r = tracker.track(IL, IR);
  std::cout << pm::tracker::toString(r.state) << " q " << r.quality << " confidence " << r.confidence << "\n";
  if (r.trusted)          // tracking, verified, confident: a pose to act on
    use(r.hMo);
}

// TrackerConfigFile.h
void exampleTrackerConfigFile()
{
  std::string notice;
  pm::tracker::TrackerParams p = pm::tracker::loadTrackerConfig("tracker.json", pm::tracker::TrackerParams(), &notice);
  if (!notice.empty())
    std::cerr << "notice: " << notice << "\n";   // a file of version 1
  p.search.ga.seed = 7;
  std::ofstream("mine.json") << pm::tracker::trackerConfigToJson(p);
}

// TiltFilter.h
void exampleTiltFilter(const vpHomogeneousMatrix &hNowMhPrev)
{
  pm::tracker::TiltFilter filter;              // alpha 0.2, beta 0.02
  for (;;) {
    const pm::core::Phi raw = estimate();   // this frame's best pose
    use(filter.update(raw));          // its tilt smoothed
    filter.transform(hNowMhPrev);     // the hand moved (eye-in-hand)
  }
}

// RangeCorrection.h
void exampleRangeCorrectionFile(const pm::core::CameraRig &rig, const pm::core::PhotoModel &model, pm::precise::PreciseStage &stage, const pm::core::Phi &start)
{
  const pm::tracker::RangeCorrection range(rig, model.trust);
  const pm::core::Phi phi = range.corrected(stage.refine(start).phi); // what the tracker reports
  use(phi);
}
void exampleRangeCorrection(const pm::core::CameraRig &rig, const pm::core::PhotoModel &model)
{
  const pm::tracker::RangeCorrection none;                     // scale 1: poses unchanged
  const pm::tracker::RangeCorrection range(rig, model.trust);  // the pass's, on a rig of its camera count
  if (range.active()) std::cout << "range x" << range.scale() << "\n";
  (void)none;
}

// LandingCorrection.h
void exampleLandingCorrectionFile(const pm::core::CameraRig &rig, const pm::core::PhotoModel &model, pm::precise::PreciseStage &stage, const pm::core::Phi &start)
{
      const pm::tracker::LandingCorrection landing(model.passLandings, rig[0].hMc); // 4 deg wide
      const pm::core::Phi phi = landing.corrected(stage.refine(start).phi);        // what the tracker reports
  use(phi);
}
void exampleLandingCorrection(const pm::core::PhotoModel &model, const vpHomogeneousMatrix &hMc, const pm::core::Phi &phi)
{
  const pm::tracker::LandingCorrection none;                              // poses unchanged
  const pm::tracker::LandingCorrection landing(model.passLandings, hMc);  // the left camera's place on the hand
  const std::array<double, 6> e = landing.at(phi); // mm along the hand's x, y, z; deg about them
  (void)none;
  (void)e;
}

} // namespace pm_examples
