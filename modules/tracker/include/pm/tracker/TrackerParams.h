#pragma once
/*!
  \file TrackerParams.h
  Everything the tracker can be told, in one section per part of its frame (PhotoModelTracker.h):
  the fitness, the search, the lock state, the steady frames, the lock verifier, the refinement
  chain, the judgement and the background's learnt hue. The defaults are the measured ones that every program uses
  (docs/rmga-tracker.md, "Which options"): 800 evaluations per frame, 15 % of them on steady frames
  with the hue within 24 px of the model, locks verified by 3,000 evaluations of a challenger; a
  configuration file (TrackerConfigFile.h) with no keys gives the same. PhotoModelTracker copies
  them; validate() checks them.

  \code
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main()
{
  pm::tracker::TrackerParams params;            // the measured defaults
  params.search.budgetEvaluations = 0;          // a wall-time budget instead of evaluations:
  params.search.budgetMs = 30;                  // 30 ms of search a frame
  params.search.ga.seed = 7;                    // another random sequence
  params.judgement.confidence.threshold = 0.99; // trust fewer frames
  params.validate();                            // throws pm::core::Error naming the first value out of range
  pm::tracker::PhotoModelTracker tracker(pm::io::loadRig("rig.json"), pm::io::loadPhotoModel("model.json"), params);
}
  \endcode
*/
#include "pm/core/StereoFitness.h"
#include "pm/tracker/BackgroundLearning.h"
#include "pm/tracker/Judgement.h"
#include "pm/tracker/LockState.h"
#include "pm/tracker/LockVerifier.h"
#include "pm/tracker/PoseSearch.h"
#include "pm/tracker/RefinementChain.h"
#include "pm/tracker/SteadyFramePolicy.h"

namespace pm::tracker {

//! The tracker's parameters, by part (see the file's description).
struct TrackerParams
{
  core::FitnessParams fitness = trackerFitnessDefaults(); //!< Eqs. (8)-(11): how every part scores a pose
  SearchParams search;          //!< RM-GA on each frame, and the frame budget (PoseSearch.h)
  LockParams lock;              //!< searching, tracking, lost (LockState.h)
  SteadyParams steady;          //!< steady frames: their budget, their hue windows, escalation (SteadyFramePolicy.h)
  VerifierParams verifier;      //!< the lock's verification by a challenger (LockVerifier.h)
  RefinementParams refinement;  //!< the precise stage, the smooth ascent, the tilt filter (RefinementChain.h)
  JudgementParams judgement;    //!< the confidence, the trust, the uncertainty (Judgement.h)
  BackgroundParams background;  //!< the background's hue learnt on trusted frames (BackgroundLearning.h)

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

} // namespace pm::tracker
