#pragma once
/*!
  \file FrameSteps.h
  The values a frame's steps hand on (PhotoModelTracker.h): each step takes what it reads and
  returns one of these; none is changed once made. The search returns a SearchedPose (RM-GA's
  pose, or the lock verifier's when it takes over, with their work), the refinement chain a
  RefinedPose (the pose the frame ends with, and what the precise stage found), the judgement a
  Verdict (the confidence, the trust, the uncertainty). The tracker assembles its TrackResult from
  them once, at the frame's end.

  \code
    const pm::tracker::SearchedPose searched{{phi, F}, work};
    const pm::tracker::RefinedPose refined = chain.refine(frame, searched.pose, history, {IL, IR}, locked);
    const pm::tracker::Evidence e = judgement.measure(frame, refined);
    const pm::tracker::Verdict verdict = judgement.judge(refined, e, state);
    if (verdict.trusted)
      use(pm::core::toHomogeneousMatrix(refined.pose.phi));
  \endcode
*/
#include "pm/core/Pose.h"
#include "pm/precise/PoseUncertainty.h"
#include "pm/precise/PreciseStage.h"
#include "pm/rmga/RmGa.h"
#include "pm/tracker/TrackConfidence.h"

namespace pm::tracker {

//! A pose of the frame and its fitness F on the frame.
struct ScoredPose
{
  core::Phi phi;      //!< the pose (mm, quaternion vector)
  double fitness = 0; //!< F at phi
};

//! The work of the frame's searches (RM-GA, any escalation, the lock verifier's challenger), in rmga::FrameResult's units.
struct SearchWork
{
  long evaluations = 0; //!< whole evaluations
  long candidates = 0;  //!< poses scored
  int generations = 0;  //!< generations run

  //! This work and \e run's.
  SearchWork plus(const rmga::FrameResult &run) const
  {
    return SearchWork{evaluations + run.evaluations, candidates + run.candidates, generations + run.generations};
  }
};

//! What the search step made: the frame's pose before refinement, and how it was found.
struct SearchedPose
{
  ScoredPose pose;        //!< RM-GA's best, or the challenger's better pose
  SearchWork work;        //!< the search's and the challenger's work
  bool steady = false;    //!< the frame had the steady budget and no more
  bool escalated = false; //!< a steady frame whose q fell, given the rest of the whole budget
  bool switched = false;  //!< the challenger found a better pose elsewhere and the tracker moved there
};

//! What the refinement chain made (RefinementChain.h): the frame's pose.
struct RefinedPose
{
  ScoredPose pose;                      //!< the frame's pose and its F
  bool precise = false;                 //!< the pose is the precise stage's
  precise::PreciseResult preciseResult; //!< what the precise stage found, kept or not (default when it did not run)
  int ascentEvaluations = 0;            //!< evaluations of the smooth ascent (0: it did not run)
};

//! What the judgement made of the frame's pose (Judgement.h).
struct Verdict
{
  ConfidenceCues cues;                //!< what the confidence is computed from
  double confidence = 0;              //!< in (0, 1): how likely the pose lies within 2 cm and 5 deg
  bool verified = false;              //!< the lock survived its challenger
  bool trusted = false;               //!< tracking, verified, confidence at or over the threshold
  const char *heldBy = nullptr;       //!< why it is not trusted (TrackResult::heldBy); null when trusted
  precise::PoseUncertainty uncertainty; //!< the pose's 1-sigma per axis, known when the pose is the precise stage's
  double visibleShare = 1;            //!< the lower of the cameras' shares of points not hidden
};

} // namespace pm::tracker
