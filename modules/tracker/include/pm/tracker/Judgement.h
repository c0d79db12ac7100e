#pragma once
/*!
  \file Judgement.h
  The judgement of a frame's pose: its confidence (how likely it lies within 2 cm and 5 deg of the
  truth, TrackConfidence.h), whether a robot may act on it (trusted: tracking, verified, confidence
  over the threshold) and, when the precise stage gave it, its 1-sigma per axis in mm and deg
  (precise::PoseUncertainty). The evidence (the pose's fit in each camera, the competing poses of
  the same object, the precise stage's lines and their sigmas) is measured once a frame (measure());
  a new lock's confidence (firstLockConfidence(), for LockState's gate) and the frame's (judge())
  are read from it with the tracker's state of the moment.

  \code
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
  \endcode
*/
#include <array>
#include <cstddef>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoScorer.h"
#include "pm/precise/PoseUncertainty.h"
#include "pm/tracker/QualityScale.h"
#include "pm/tracker/TrackConfidence.h"
#include "pm/precise/ModelErrorFloor.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/TrackResult.h"

namespace pm::tracker {

//! The judgement's parameters: the confidence's model and threshold, the uncertainty's scales and floors.
struct JudgementParams
{
  /*!
    How the frame's confidence is computed from its cues, and its threshold (TrackResult::trusted).
    Its kind Auto (the default): the coefficients shipped for the model's kind (flat, stereo or
    all-around, forModel()); the threshold is this one.
  */
  ConfidenceModel confidence;
  //! From the precise stage's information to the reported 1-sigma per axis (TrackResult::uncertainty).
  precise::UncertaintyModel uncertainty;

  //! These parameters for \e model: a confidence of kind Auto replaced by the coefficients of the model's kind (the threshold kept).
  JudgementParams forModel(const core::PhotoModel &model) const;
  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! What measure() found of a pose on the frame: the cues that do not depend on the tracker's state, and the precise stage's sigmas.
struct Evidence
{
  ConfidenceCues cues;                //!< the pose's fit, tilt, competitors and precise cues (the state's own left to judge())
  std::array<double, 6> lineSigmas{}; //!< the precise stage's lines' own 1-sigma per axis (mm, deg), when its pose is the frame's
  double visibleShare = 1;            //!< the lower of the cameras' shares of points not hidden (TrackResult::visibleShare)
};

//! The tracker's state that a frame is judged with (see Judgement::judge()).
struct JudgedState
{
  TrackState state = TrackState::Searching; //!< the state after this frame (LockState::state())
  const core::Phi *last = nullptr; //!< the last frame's pose when it was tracked (the jump), else null
  double recentBestQ = 0;          //!< SteadyFramePolicy::recentBestQ() after this frame
  int framesTracked = 0;           //!< LockState::framesTracked()
  bool verified = false;           //!< LockVerifier::verified()
  bool lookingAgain = false;       //!< LockVerifier::lookingAgain(): the verification follows an ambiguity
};

//! The judgement (see the file's description). Keeps a reference to the scorer: it must outlive the judgement.
class Judgement
{
public:
  /*!
    \e params as resolved for the model (JudgementParams::forModel); \e competitorMinDeg: competing
    poses turned less than this are the same pose (VerifierParams::farDeg); \e modelError: the model's
    own error near each view, the uncertainty's floor there (the model's pass landings).
  */
  Judgement(const JudgementParams &params, double competitorMinDeg, const core::StereoScorer &scorer, const QualityScale &scale,
            const precise::ModelErrorFloor &modelError);

  //! The competing poses of \e phi it scores (turned about its z axis, its tilt mirrored), valid ones only; returns their number.
  std::size_t competitors(const core::Phi &phi, core::Phi *out) const;
  //! The evidence of the frame's pose \e refined (its pose, its F and the precise stage's result) on \e frame.
  Evidence measure(const core::HueFrame &frame, const RefinedPose &refined) const;
  //! The confidence of \e e as a first, unverified lock (\e verifiedAtOnce: locks need no verification).
  double firstLockConfidence(const Evidence &e, double recentBestQ, bool verifiedAtOnce) const;
  //! The verdict on \e refined, from its evidence \e e and the tracker's \e state.
  Verdict judge(const RefinedPose &refined, const Evidence &e, const JudgedState &state) const;

  const JudgementParams &params() const { return m_p; } //!< the parameters (resolved for the model)

private:
  JudgementParams m_p;
  double m_competitorMinDeg;
  const core::StereoScorer &m_scorer;
  QualityScale m_scale;
  precise::ModelErrorFloor m_modelError;
};

} // namespace pm::tracker
