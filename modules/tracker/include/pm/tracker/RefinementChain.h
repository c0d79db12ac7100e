#pragma once
/*!
  \file RefinementChain.h
  After the search (and the lock verifier), on a frame whose q reaches the lock, the frame's pose
  goes through the refinement chain, three stages in a fixed order, each with its own acceptance
  rule in its own parameters:
   1. the precise stage (PreciseRefinement.h): when its pose is kept, it is final: the chain ends
      there (the later stages are for the models and frames it does not serve) and the tilt filter
      restarts;
   2. the smooth ascent (AscentRefinement.h): the top of F's plateau near the frame's pose;
   3. the tilt filter (TiltFilter.h): the tilt smoothed from frame to frame (a model of one or a few
      views sees it poorly; an all-around model gets a lighter filter), on frames tracked in a row.
  A frame under the lock skips the chain (the tilt filter restarts).

  \code
    pm::tracker::RefinementChain chain(params.refinement, rig, model, scorer, scale);
    const pm::tracker::RefinedPose refined = chain.refine(frame, searched.pose, history, {IL, IR}, locked);
    pm::tracker::RmGaUpdate u;
    if (refined.precise) // the precise stage's pose joins RM-GA
      u.inject = pm::tracker::RmGaUpdate::Inject{refined.pose.phi, refined.pose.fitness};
    search.apply(u);
  \endcode
*/
#include "pm/tracker/AscentRefinement.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/MotionPrediction.h"
#include "pm/tracker/PoseHistory.h"
#include "pm/tracker/PreciseRefinement.h"
#include "pm/tracker/TiltFilter.h"

namespace pm::tracker {

//! The chain's stages' parameters, in their order (see RefinementChain.h).
struct RefinementParams
{
  PreciseRefinementParams precise; //!< 1. the precise stage
  MotionPredictionParams motion;   //!< 1. where the precise stage starts on a tracked target: the pose the last frames predict
  AscentParams ascent;             //!< 2. the smooth ascent
  /*!
    3. The tilt filter for a model of one or a few views (flat, a stereo snapshot); alpha 1 and beta 0: off.
  */
  TiltFilterParams tiltFilter;
  /*!
    3. The same for an all-around model (core::PhotoModel::isAllAround), whose outline changes with
    the tilt as the toy's does: a lighter smoothing, so that a tilted step is not lagged (the
    figures that chose it: docs/all-around-model.md).
  */
  TiltFilterParams tiltFilterAllAround{0.5, 0.0, 5.0};

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The refinement chain (see the file's description): owns its stages and their state.
class RefinementChain
{
public:
  //! The stages for \e model on \e rig (the precise stage only for a model with outlines), scoring with \e scorer (it must outlive the chain).
  RefinementChain(const RefinementParams &params, const core::CameraRig &rig, const core::PhotoModel &model,
                  const core::StereoScorer &scorer, const QualityScale &scale);

  /*!
    The stages on \e searched, the frame's pose after the search, on \e frame (\e locked: its q
    reaches the lock; \e history: the past frames). Returns the frame's pose.
  */
  RefinedPose refine(const core::HueFrame &frame, const ScoredPose &searched, const PoseHistory &history, const core::CameraImages &images,
                     bool locked);
  //! Where the lock stands after the verifier's turn on a frame (RefinementChain::learn).
  struct LockStanding
  {
    bool tracking = false;     //!< a lock is tracked
    bool verified = false;     //!< the verifier has accepted it (LockVerifier::verified)
    bool lookingAgain = false; //!< the verifier found another pose scoring as well and looks again (LockVerifier::lookingAgain)
  };
  /*!
    After the judgement (\e verdict) and the verifier's turn (\e lock): what the precise stage learns
    of the scene's colours along the outline of \e refined, when the pose is the stage's.
    - A trusted frame's colours are learnt.
    - A frame of a new lock that awaits its verification (not verified when judged, no ambiguity)
      is learnt aside; once the verifier accepts the lock (lockAccepted(), or \e lock here), those
      colours are taken: the frame that it accepts in is measured with the colours of the whole
      verification, not with the model's alone. A lock lost, an ambiguity, or a frame whose
      confidence is under PreciseRefinementParams::learnAsideMinConfidence forgets them.
  */
  void learn(const RefinedPose &refined, const Verdict &verdict, const LockStanding &lock);
  //! The hand moved by \e hNowMhPrev: the tilt filter's state follows.
  void transform(const vpHomogeneousMatrix &hNowMhPrev) { m_tilt.transform(hNowMhPrev); }
  //! A new start, or a jump to another pose: the tilt filter starts again, and the colours learnt aside are forgotten.
  void reset()
  {
    m_tilt.reset();
    m_precise.dropColoursLearntAside();
  }
  //! The verifier has just accepted the lock (in the frame's challenge, before its refinement): the colours learnt aside are taken (see learn()).
  void lockAccepted() { m_precise.takeColoursLearntAside(); }
  //! The background's hue learnt (BackgroundLearning): the precise stage's hidden lines compare with it.
  void setBackgroundHue(double deg) { m_precise.setBackgroundHue(deg); }

  //! Where the precise stage settles from \e start (PreciseRefinement::settle); nothing without the stage.
  std::optional<core::Phi> settle(const core::Phi &start, const core::CameraImages &images) { return m_precise.settle(start, images); }
  const PreciseRefinement &precise() const { return m_precise; } //!< stage 1
  const TiltFilterParams &tiltFilter() const { return m_tiltParams; } //!< stage 3's parameters for this model

private:
  PreciseRefinement m_precise;
  AscentRefinement m_ascent;
  TiltFilterParams m_tiltParams;
  TiltFilter m_tilt;
  MotionPrediction m_motion;
  const core::StereoScorer &m_scorer;
};

} // namespace pm::tracker
