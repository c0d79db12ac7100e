#include "pm/core/StereoRig.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::core {

StereoRig StereoRig::symmetric(const vpCameraParameters &cam, unsigned w, unsigned h, double baselineM,
                               double toeInRad)
{
  StereoRig rig;
  rig.left = {"left", cam, w, h, vpHomogeneousMatrix(-baselineM / 2, 0, 0, 0, toeInRad, 0), LensDistortion()};
  rig.right = {"right", cam, w, h, vpHomogeneousMatrix(baselineM / 2, 0, 0, 0, -toeInRad, 0), LensDistortion()};
  return rig;
}

double StereoRig::toeInFor(double baselineM, double distanceM) { return std::atan2(baselineM / 2, distanceM); }

double StereoRig::baseline() const { return (right.hMc.getTranslationVector() - left.hMc.getTranslationVector()).frobeniusNorm(); }

void StereoRig::validate() const
{
  left.validate();
  right.validate();
}

} // namespace pm::core
