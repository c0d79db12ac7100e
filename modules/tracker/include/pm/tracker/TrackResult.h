#pragma once
/*!
  \file TrackResult.h
  What the tracker says about a frame: the pose hMo, its fitness, the state, the confidence and
  the uncertainty (PhotoModelTracker::track()).

  \code
    const pm::tracker::TrackResult r = tracker.track(IL, IR);
    std::cout << pm::tracker::toString(r.state) << " q " << r.quality << " confidence " << r.confidence << "\n";
    if (r.trusted)          // tracking, verified, confident: a pose to act on
      use(r.hMo);
  \endcode
*/
#include <array>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"
#include "pm/precise/PoseUncertainty.h"
#include "pm/precise/PreciseStage.h"
#include "pm/tracker/TrackConfidence.h"

namespace pm::tracker {

/*!
  The tracker's state (LockState.h): Searching after initialize(), until a first lock; Tracking
  while q holds; Lost after LockParams::lostFrames frames under LockParams::lostQuality, until a new lock.
*/
enum class TrackState { Searching, Tracking, Lost };
//! The state's name: "searching", "tracking" or "lost".
const char *toString(TrackState s);

/*!
  Where a frame's time went (ms), PhotoModelTracker::track()'s steps in order; their sum is the
  frame's TrackResult::computeMs. frames.csv keeps them (step_plan_ms ... step_apply_ms).
*/
struct StepTimes
{
  double plan = 0;      //!< 1. the frame's plan: steady or not, the budgets, the hue planes (in the steady windows)
  double search = 0;    //!< 2. RM-GA, and its escalation when a steady frame's q falls
  double challenge = 0; //!< 3. the lock verifier's challenger, on the frames it verifies
  double refine = 0;    //!< 4. the refinement chain: the precise stage (or the smooth ascent and the tilt filter)
  double measure = 0;   //!< 5. the judgement's evidence (and, on a windowed frame, the hue it reads on the whole images)
  double judge = 0;     //!< 6-7. the lock's state, the confidence, the trust and the uncertainty
  double apply = 0;     //!< 8-9. what the parts learn and ask of RM-GA; the background's hue
  static constexpr std::size_t kCount = 7; //!< the steps
  //! Their names, in order: "plan", "search", "challenge", "refine", "measure", "judge", "apply".
  static const std::array<const char *, kCount> &names();
  //! Their times, in the order of names().
  std::array<double, kCount> values() const { return {plan, search, challenge, refine, measure, judge, apply}; }
};

//! What PhotoModelTracker::track() says about a frame (also kept: PhotoModelTracker::lastResult()).
struct TrackResult
{
  vpHomogeneousMatrix hMo;  //!< pose of the model in the hand frame (metres)
  core::Phi phi;            //!< the same as phi (mm, quaternion vector)
  double fitness = 0;       //!< F at phi
  double quality = 0;       //!< q, the normalised fitness
  TrackState state = TrackState::Searching; //!< the state after this frame
  long evaluations = 0;     //!< the work of RM-GA and the verification, in whole evaluations (see rmga::FrameResult)
  long candidates = 0;      //!< poses they scored
  int generations = 0;      //!< RM-GA generations they ran
  double computeMs = 0;     //!< time spent in track()
  StepTimes steps;          //!< where it went, step by step (their sum is computeMs)
  bool steady = false;      //!< the frame had the steady budget (and no more)
  bool escalated = false;   //!< a steady frame whose q fell, given the rest of the whole budget (SteadyParams::escalation)
  int ascentEvaluations = 0; //!< evaluations of the smooth score and its gradient by the climb (0: none)
  bool precise = false;      //!< the precise stage's pose is the frame's (PreciseRefinementParams::enabled)
  precise::PreciseResult preciseResult; //!< what the precise stage found (its lines, residual, information), when it ran
  //! The pose's 1-sigma per axis in mm and deg (PoseUncertainty.h): known when the precise stage's pose is the frame's.
  precise::PoseUncertainty uncertainty;

  ConfidenceCues cues;       //!< what the confidence is computed from
  /*!
    The share of the model's points on the images that the stereo visibility did not find hidden,
    the lower of the two cameras' (core::FitnessCounts::visibleShare(); 1: nothing hidden, or
    core::FitnessParams::stereoVisibility off).
  */
  double visibleShare = 1;
  //! The background's hue the frame was scored with (deg): the model's, or the one learnt since (BackgroundLearning.h).
  double backgroundHueDeg = 0;
  double confidence = 0;     //!< in (0, 1): how likely the estimate is within 2 cm and 5 deg (see TrackConfidence.h)
  bool verified = false;     //!< the lock survived its challenger search (VerifierParams::evaluations)
  bool switched = false;     //!< the challenger found a better pose elsewhere this frame and the tracker moved there
  //! Tracking, verified and confidence at or above the threshold: a pose a robot may act on.
  bool trusted = false;
  /*!
    Why a frame is not trusted, for the user whose arm waits (null when trusted): the state
    ("searching", "lost"), "verification" (a new lock awaits its challenger's search),
    "verification_ambiguous" (the challenger found another pose of the same object scoring as well,
    and searches again: LockVerifier::lookingAgain()), or the cue
    that lowers the confidence most below what a right pose reads (ConfidenceModel::weakestCue(): one
    of ConfidenceCues::featureNames(), "precise_residual_px", "separation", ...; "confidence" when no
    cue reads below a right pose's). A static string.
  */
  const char *heldBy = nullptr;
};

} // namespace pm::tracker
