#pragma once
/*!
  \file PhotoModelTracker.h
  The photo-model tracker: the pose-estimation feature a ViSP program uses. Give it the stereo
  rig and a photo-model; it finds the target from scratch (initialize()) or from a known pose
  (initFromPose()), then track() takes each new stereo pair and returns hMo, the pose of the
  model in the hand frame, with the fitness, a state, a confidence and an uncertainty.

  A frame is one fixed list of steps, each done by a part that owns its state and its parameters
  (docs/architecture.md draws it). What the frame sees (its hue planes, the background's hue: a
  core::HueFrame) is made by the tracker alone and given to each step that scores; the parts keep
  only the core::StereoScorer, the model on the rig, which nothing changes. Each step returns what
  it made (FrameSteps.h: the searched pose, the refined pose, the verdict); the tracker's past (the
  last frames' poses, PoseHistory.h) is kept in one place, read by the steps and changed by the
  tracker alone; the TrackResult is assembled from the steps' values once, at the frame's end:
   1. plan: the steady-frame policy (SteadyFramePolicy.h) says whether the frame is steady, and
      the hue planes are computed (on a steady frame, only in the windows where the model can land);
   2. search: RM-GA (PoseSearch.h) within the frame's budget; a steady frame whose q falls escalates;
   3. challenge: while a new lock is verified, the lock verifier's challenger (LockVerifier.h)
      searches the same frame and may move the tracker to a better pose;
   4. refine: the refinement chain (RefinementChain.h): the precise stage, or the smooth ascent
      and the tilt filter;
   5. measure: the judgement's evidence, once (Judgement.h);
   6. state: searching, tracking or lost (LockState.h), a new lock refused when plainly wrong; the
      steadiness and the verification follow the state;
   7. judge: the confidence, the trust, the uncertainty;
   8. after the judgement: what the parts asked of RM-GA's population (RmGaUpdate.h), in one place;
      then a doubtful lock is verified again, from the population that leaves; the precise stage
      learns the colours of a trusted frame (and a new lock's aside until it is verified);
   9. background: a trusted frame teaches the background's hue as seen now (BackgroundLearning.h);
      the scoring takes it when it has moved away from the photos'.
  The pose the frame reports is the precise stage's less the model's own error at the pass's views
  near the camera's direction (LandingCorrection.h); the steps and the tracker's past keep the
  stage's pose, as the confidence was fitted on.

  Trust: "tracking" says the model fits somewhere, not that the pose is right. TrackResult::trusted
  (tracking, verified, confidence over its threshold) is what a robot should act on; with the
  precise stage (all-around models), TrackResult::uncertainty gives the pose's 1-sigma along and
  about the hand frame's axes in mm and deg: hold the robot when it exceeds what the task tolerates.
*/
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include <array>

#include "pm/core/StereoFitness.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/LandingCorrection.h"
#include "pm/tracker/PoseHistory.h"
#include "pm/tracker/TrackResult.h"
#include "pm/tracker/TrackerParams.h"

namespace pm::tracker {

/*!
  The photo-model tracker (see the file's description): a stereo pair in, the pose hMo of the
  model in the hand frame out, with its fitness, state and confidence. It copies the parameters
  and what it needs of the rig and the model (none of them need outlive it); the images given to
  track() are only read during the call. Not thread-safe: call it from one thread.

  \code
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");
  pm::tracker::PhotoModelTracker tracker(rig, model); // the default TrackerParams
  tracker.initialize();                               // search from scratch
  for (int k = 0; k < 100; ++k) {
    const vpImage<vpRGBa> IL = pm::io::readColorImage("left_" + std::to_string(k) + ".png");
    const vpImage<vpRGBa> IR = pm::io::readColorImage("right_" + std::to_string(k) + ".png");
    // eye-in-hand: tracker.applyHandMotion(hNowMhPrev) here, when the hand moved since the last frame
    const pm::tracker::TrackResult r = tracker.track(IL, IR);
    std::cout << pm::tracker::toString(r.state) << " q " << r.quality << " confidence " << r.confidence << "\n";
    if (r.trusted && (!r.uncertainty.known || (r.uncertainty.maxMm() < 2 && r.uncertainty.maxDeg() < 2)))
      std::cout << "hMo (m):\n" << r.hMo << "\n"; // tracking, verified, confident, precise enough: a pose to act on
  }
}
  \endcode
*/
class PhotoModelTracker
{
public:
  /*!
    Throws core::Error if the rig, the model or the parameters are invalid, or if the model does
    not fit the rig (under half of its points in an image at the centre of the search space).
  */
  PhotoModelTracker(const core::CameraRig &rig, const core::PhotoModel &model, const TrackerParams &params = TrackerParams());

  //! Searches from scratch: a random population over the search space (state: searching).
  void initialize();
  //! Starts from a known pose (state: tracking, the lock taken as verified).
  void initFromPose(const vpHomogeneousMatrix &hMo);
  /*!
    One frame (the steps of the file's description), one image per camera of the rig. Throws
    core::Error if their number is not the rig's or an image's size differs from its camera's.
  */
  TrackResult track(const core::CameraImages &images);
  //! A stereo rig's frame: track({left, right}).
  TrackResult track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) { return track(core::CameraImages(left, right)); }
  //! The rig's number of cameras.
  int cameraCount() const { return m_fitness.scorer().cameraCount(); }
  /*!
    The hand moved by \e hNowMhPrev (the previous hand frame seen from the current one, from the
    robot's odometry) since the last frame: every part follows, so that a target that did not move
    is still where the search looks (eye-in-hand ego-motion compensation).
  */
  void applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev);

  //! hMo of the last frame as track() reported it, or the one given to initFromPose() (metres); moved by applyHandMotion().
  vpHomogeneousMatrix getPose() const { return lastResult().hMo; }
  //! The last frame's F (0 before the first frame).
  double getFitness() const { return m_history.last().fitness; }
  //! The state after the last frame (Searching after initialize(), Tracking after initFromPose()).
  TrackState getState() const { return m_history.last().state; }
  //! Everything the last track() returned (reset by initialize() and initFromPose()).
  TrackResult lastResult() const
  {
    TrackResult r = m_history.last();
    takeLandingOff(r);
    return r;
  }
  //! q of a fitness value for this model.
  double quality(double fitness) const { return m_scale.quality(fitness); }
  //! The model's points at the last pose as the precise stage landed (before LandingCorrection) in camera \e camera's image (a stereo rig: 0 left, 1 right), each with its score class (for drawing).
  std::vector<core::PointScore> pointScores(int camera) const { return m_fitness.pointScores(m_history.last().phi, camera); }
  //! The stereo fitness the tracker scores with (its hue planes: those of the last frame).
  const core::StereoFitness &fitness() const { return m_fitness; }
  //! The parameters (the tracker's copy, validated, the confidence's coefficients those of the model's kind).
  const TrackerParams &params() const { return m_params; }
  //! The tilt filter this model gets: RefinementParams::tiltFilterAllAround for an all-around model, tiltFilter otherwise.
  const TiltFilterParams &tiltFilter() const { return m_refinement.tiltFilter(); }
  //! True when the precise stage runs (PreciseRefinementParams::enabled and a model with outlines).
  bool hasPreciseStage() const { return m_refinement.precise().active(); }
  //! The precise stage (its colour statistics, its last lines); null when off.
  const precise::PreciseStage *preciseStage() const { return m_refinement.precise().stage(); }

private:
  //! A frame's wall clock, from the start of track().
  struct Clock;
  //! 1. The frame's plan; the hue planes made (on a steady frame, in its windows).
  FramePlan plan(const core::CameraImages &images, const Clock &clock);
  //! 2. RM-GA within the plan's budget, escalated when a steady frame's q falls.
  SearchedPose search(const FramePlan &plan, const core::CameraImages &images, const Clock &clock);
  //! 3. The lock verifier's challenger when the plan says so: \e searched, or the better pose it moved to (then \e update reseeds RM-GA).
  SearchedPose challenge(const FramePlan &plan, const SearchedPose &searched, const core::CameraImages &images, RmGaUpdate &update);
  //! Before 5: on a windowed frame, the hue under \e phi and its competitors, which the judgement scores on the whole images.
  void completeHue(const FramePlan &plan, const SearchedPose &searched, const core::Phi &phi, const core::CameraImages &images);
  //! 6. The lock's state from \e pose's q (a plainly wrong new lock refused); returns its restart of RM-GA.
  RmGaUpdate::Restart updateState(const ScoredPose &pose, const Evidence &evidence);
  //! 7. The verdict on \e refined with the tracker's state after 6.
  Verdict judge(const RefinedPose &refined, const Evidence &evidence) const;
  //! 8. What the lock, RM-GA (\e update, applied), the verifier and the precise stage learn from the verdict.
  void afterJudgement(const RefinedPose &refined, const Verdict &verdict, RmGaUpdate &update);
  //! The frame's result from the steps' values; \e at: the clock at the end of each step (StepTimes' order, ms).
  TrackResult assembled(const SearchedPose &searched, const RefinedPose &refined, TrackState state, const Verdict &verdict,
                        double backgroundHueDeg, const std::array<double, StepTimes::kCount> &at) const;
  //! \e r made what track() reports: a precise pose less the model's own error at its pass's views (LandingCorrection.h); allocates nothing.
  void takeLandingOff(TrackResult &r) const;
  //! A new start whose last frame is \e first (searching, or a pose given: tracking and verified).
  void reset(const TrackResult &first);
  //! The fitness and the precise stage compare with the background's hue \e deg from now on.
  void useBackgroundHue(double deg);

  TrackerParams m_params;
  core::CameraRig m_rig;         //!< the rig, for its images' sizes
  core::StereoFitness m_fitness; //!< the scorer, which every part keeps (never changed), and the frame's hues, given to each step
  QualityScale m_scale;
  PoseSearch m_search;
  LockState m_lock;
  SteadyFramePolicy m_steady;
  LockVerifier m_verifier;
  RefinementChain m_refinement;
  Judgement m_judgement;
  BackgroundLearning m_background; //!< the background's hue as seen now (learnt on trusted frames)
  LandingCorrection m_landing;     //!< the model's own error at its pass's views, taken off the reported pose (never changed)
  std::array<double, 6> m_landingTaken{}; //!< what the last frame took off its pose (model frame: mm, deg), changed only by track() and reset()
  PoseHistory m_history;           //!< the last frames' results and poses, changed only by track(), reset() and applyHandMotion()
};

} // namespace pm::tracker
