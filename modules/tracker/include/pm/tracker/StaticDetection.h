#pragma once
/*!
  \file StaticDetection.h
  Static detection (the paper's Sec. 5, Table 1): the tracker searches one still stereo pair from
  a random population, frame after frame on the same pair, until its best pose has not improved
  for a number of frames (and it is tracking) or a time limit passes; and the fitness peak nearest
  a pose, which the paper's Table 1 measures against.
*/
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/rmga/SearchSpace.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::tracker {

//! When a static detection stops.
struct DetectionParams
{
  double maxTimeS = 10; //!< give up after this long (s, wall time)
  int patience = 20;    //!< stop when the best has not improved for this many frames and the tracker is tracking
};

//! What a static detection found.
struct Detection
{
  TrackResult best;            //!< the frame with the highest fitness, or the last frame when the precise stage gave its pose (its pose: best.phi, best.hMo)
  double convergedS = 0;       //!< when that frame was found (s from the start)
  double totalS = 0;           //!< the whole search (s)
  long evaluations = 0;        //!< fitness evaluations until the best was found
  long totalEvaluations = 0;   //!< over the whole search
  int frames = 0;              //!< frames tracked (all on the same pair)
};

/*!
  Runs \e tracker (initialise it first: tracker.initialize()) on the still \e images (one per
  camera of its rig) until DetectionParams says stop. The tracker keeps its state afterwards.

  \code
    pm::tracker::PhotoModelTracker tracker(rig, model);
    tracker.initialize();
    const pm::tracker::Detection d = pm::tracker::detectStatic(tracker, {left, right}, pm::tracker::DetectionParams());
    std::cout << d.best.phi.toString() << " after " << d.convergedS << " s\n";
  \endcode
*/
Detection detectStatic(PhotoModelTracker &tracker, const core::CameraImages &images, const DetectionParams &params);

//! The fitness peak nearest \e start: a pattern search of RM-GA's genes within \e space (5,000 evaluations).
core::Phi nearestFitnessPeak(const core::StereoFitness &fitness, const core::Phi &start, const rmga::SearchSpace &space);

} // namespace pm::tracker
