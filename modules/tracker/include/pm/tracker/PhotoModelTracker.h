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
  only the core::StereoScorer, the model on the rig, which nothing changes:
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
   8. apply: what the parts asked of RM-GA's population (RmGaUpdate.h), in one place; a doubtful
      lock is verified again; the precise stage learns the colours of a trusted frame;
   9. background: a trusted frame teaches the background's hue as seen now (BackgroundLearning.h);
      the scoring takes it when it has moved away from the photos'.

  Trust: "tracking" says the model fits somewhere, not that the pose is right. TrackResult::trusted
  (tracking, verified, confidence over its threshold) is what a robot should act on; with the
  precise stage (all-around models), TrackResult::uncertainty gives the pose's 1-sigma along and
  about the hand frame's axes in mm and deg: hold the robot when it exceeds what the task tolerates.
*/
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/StereoFitness.h"
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
  PhotoModelTracker(const core::StereoRig &rig, const core::PhotoModel &model, const TrackerParams &params = TrackerParams());

  //! Searches from scratch: a random population over the search space (state: searching).
  void initialize();
  //! Starts from a known pose (state: tracking, the lock taken as verified).
  void initFromPose(const vpHomogeneousMatrix &hMo);
  //! One frame (the steps of the file's description). Throws core::Error if an image's size differs from its camera's.
  TrackResult track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right);
  /*!
    The hand moved by \e hNowMhPrev (the previous hand frame seen from the current one, from the
    robot's odometry) since the last frame: every part follows, so that a target that did not move
    is still where the search looks (eye-in-hand ego-motion compensation).
  */
  void applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev);

  //! hMo of the last frame, or the one given to initFromPose() (metres); moved by applyHandMotion().
  vpHomogeneousMatrix getPose() const { return m_last.hMo; }
  //! The last frame's F (0 before the first frame).
  double getFitness() const { return m_last.fitness; }
  //! The state after the last frame (Searching after initialize(), Tracking after initFromPose()).
  TrackState getState() const { return m_last.state; }
  //! Everything the last track() returned (reset by initialize() and initFromPose()).
  const TrackResult &lastResult() const { return m_last; }
  //! q of a fitness value for this model.
  double quality(double fitness) const { return m_scale.quality(fitness); }
  //! The model's points at the last pose in camera \e camera's image (0 left, 1 right), each with its score class (for drawing).
  std::vector<core::PointScore> pointScores(int camera) const { return m_fitness.pointScores(m_last.phi, camera); }
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
  FramePlan plan(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Clock &clock);
  TrackResult search(const FramePlan &plan, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Clock &clock);
  void challenge(const FramePlan &plan, TrackResult &r, RmGaUpdate &update);
  void completeHue(const FramePlan &plan, const TrackResult &r, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right);
  RmGaUpdate::Restart updateState(TrackResult &r, const Evidence &evidence);
  void judge(TrackResult &r, const Evidence &evidence, TrackState prev) const;
  enum class Start { Unverified, Verified }; //!< how reset() takes its first pose: a search's, or one given (verified)
  void reset(TrackState state, Start start);
  //! The fitness and the precise stage compare with the background's hue \e deg from now on.
  void useBackgroundHue(double deg);

  TrackerParams m_params;
  core::StereoFitness m_fitness; //!< the scorer, which every part keeps (never changed), and the frame's hues, given to each step
  QualityScale m_scale;
  PoseSearch m_search;
  LockState m_lock;
  SteadyFramePolicy m_steady;
  LockVerifier m_verifier;
  RefinementChain m_refinement;
  Judgement m_judgement;
  BackgroundLearning m_background; //!< the background's hue as seen now (learnt on trusted frames)
  TrackResult m_last;
};

} // namespace pm::tracker
