#pragma once
/*!
  \file ComparedTracker.h
  One tracker of pm-compare's line-up, behind one interface: started on the first stereo pair
  (with the true pose if it needs one), then fed every stereo pair of a sequence; it returns
  hMm, the pose of the model frame in the hand frame, so that all are scored the same way.
*/
#include <memory>
#include <string>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraImages.h"

namespace pm::compare {

//! What a ComparedTracker gives for one frame.
struct Estimate
{
  vpHomogeneousMatrix hMm; //!< the tracker's pose of the model in the hand frame
  bool valid = false;      //!< false: the tracker has no pose for this frame (it says it lost the target, or threw)
};

/*!
  The interface of a tracker in pm-compare's line-up (see ComparedTracker.h). Made by
  makeOurTracker(), makeMbtTracker() or makeTemplateTracker(); the caller owns it.

  \code
    std::unique_ptr<pm::compare::ComparedTracker> t = pm::compare::makeOurTracker(rig, model, pm::tracker::TrackerParams());
    t->start({left0, right0}, hMmTrue0); // one image per camera; hMmTrue0 is ignored here: ours needs no initial pose
    const pm::compare::Estimate e = t->track({left0, right0});
  \endcode
*/
class ComparedTracker
{
public:
  virtual ~ComparedTracker() = default;
  //! The tracker's name in pm-compare's tables and plots (e.g. "ViSP MBT edge").
  virtual std::string name() const = 0;
  //! It cannot start by itself: start() needs the true pose.
  virtual bool needsInitialPose() const = 0;
  //! Starts on the first frame (one image per camera of its rig); \e hMmTrue is used only when needsInitialPose().
  virtual void start(const core::CameraImages &images, const vpHomogeneousMatrix &hMmTrue) = 0;
  //! One frame. Never throws for a tracking failure: the estimate is then invalid.
  virtual Estimate track(const core::CameraImages &images) = 0;
};

} // namespace pm::compare
