#pragma once
/*!
  \file RangeCorrection.h
  The precise stage's pose moved along the line from the cameras by what the pass measured
  (core::TrustCalibration::rangeScale): depth read from the model's size in the images is off by a
  steady share of the range where the model's colours and outline sit a tenth of a pixel off, and the
  pass's held-out views, whose poses the arm knew, measure that share through the user's own rig
  (pm::trust::measureRangeBias). Only the translation moves, about the centre of the rig's cameras
  (the hand frame's origin for the lab's symmetric pair); the rotation stays. A rig of another
  number of cameras than the pass was tried on, or a model without the calibration, leaves the pose
  as it is (scale 1). A value: made once from the rig and the model, never changed.

  \code
      const pm::tracker::RangeCorrection range(rig, model.trust);
      const pm::core::Phi phi = range.corrected(stage.refine(start).phi); // what the tracker reports
  \endcode
*/
#include <array>

#include "pm/core/CameraRig.h"
#include "pm/core/Pose.h"
#include "pm/core/TrustCalibration.h"

namespace pm::tracker {

/*!
  Scales a pose's distance from the rig's cameras (see RangeCorrection.h).
  \code
  const pm::tracker::RangeCorrection none;                     // scale 1: poses unchanged
  const pm::tracker::RangeCorrection range(rig, model.trust);  // the pass's, on a rig of its camera count
  if (range.active()) std::cout << "range x" << range.scale() << "\n";
  \endcode
*/
class RangeCorrection
{
public:
  //! No correction (scale 1).
  RangeCorrection() = default;
  //! \e trust's rangeScale on \e rig when it was measured through as many cameras as \e rig has; else none.
  RangeCorrection(const core::CameraRig &rig, const core::TrustCalibration &trust);
  //! \e phi with its position moved to centre + (position - centre) * scale (mm); the rotation unchanged.
  core::Phi corrected(const core::Phi &phi) const;
  //! The factor applied to the range (1: none).
  double scale() const { return m_scale; }
  //! True unless the scale is 1.
  bool active() const { return m_scale != 1; }
  //! The centre of the rig's cameras in the hand frame (mm).
  const std::array<double, 3> &centreMm() const { return m_centreMm; }

private:
  double m_scale = 1;
  std::array<double, 3> m_centreMm{0, 0, 0};
};

//! The mean of \e rig's camera centres in the hand frame (mm): what a rig's range is measured from.
std::array<double, 3> cameraCentreMm(const core::CameraRig &rig);

} // namespace pm::tracker
