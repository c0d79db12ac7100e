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
  for (const RigCamera *c : {&left, &right}) {
    const double vals[] = {c->cam.get_px(), c->cam.get_py(), c->cam.get_u0(), c->cam.get_v0()};
    const char *names[] = {"px", "py", "u0", "v0"};
    for (int i = 0; i < 4; ++i) {
      if (!std::isfinite(vals[i]) || (i < 2 && vals[i] <= 0) || (i >= 2 && vals[i] < 0))
        throw Error("camera '" + c->name + "': " + names[i] + " = " + std::to_string(vals[i]) +
                    (i < 2 ? " must be a positive focal length in pixels" : " must be a finite, non-negative pixel coordinate"));
    }
    if (c->width == 0 || c->height == 0)
      throw Error("camera '" + c->name + "': image size " + std::to_string(c->width) + "x" + std::to_string(c->height) +
                  " must be positive");
    if (!c->hMc.isAnHomogeneousMatrix())
      throw Error("camera '" + c->name + "': hMc is not a rigid transformation");
    c->distortion.validate(c->cam, c->width, c->height, "camera '" + c->name + "'");
  }
}

} // namespace pm::core
