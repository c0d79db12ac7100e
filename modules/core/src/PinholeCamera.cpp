#include "pm/core/PinholeCamera.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::core {

void PinholeCamera::validate() const
{
  const double vals[] = {cam.get_px(), cam.get_py(), cam.get_u0(), cam.get_v0()};
  const char *names[] = {"px", "py", "u0", "v0"};
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(vals[i]) || (i < 2 && vals[i] <= 0) || (i >= 2 && vals[i] < 0))
      throw Error("camera '" + name + "': " + names[i] + " = " + std::to_string(vals[i]) +
                  (i < 2 ? " must be a positive focal length in pixels" : " must be a finite, non-negative pixel coordinate"));
  }
  if (width == 0 || height == 0)
    throw Error("camera '" + name + "': image size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
  if (!hMc.isAnHomogeneousMatrix())
    throw Error("camera '" + name + "': hMc is not a rigid transformation");
  distortion.validate(cam, width, height, "camera '" + name + "'");
}

PinholeCamera::Projection::Projection(const vpHomogeneousMatrix &fMc, const vpCameraParameters &cam, unsigned width, unsigned height)
    : px(cam.get_px()), py(cam.get_py()), u0(cam.get_u0()), v0(cam.get_v0()), w(static_cast<int>(width)), h(static_cast<int>(height))
{
  const vpHomogeneousMatrix cMf = fMc.inverse();
  for (unsigned r = 0; r < 3; ++r) {
    for (unsigned c = 0; c < 3; ++c)
      R[3 * r + c] = cMf[r][c];
    t[r] = 1e3 * cMf[r][3];
    centre[r] = 1e3 * fMc[r][3];
  }
}

PinholeCamera::Projection PinholeCamera::Projection::lookingAtOrigin(const Vec3 &C, const vpCameraParameters &cam, unsigned width,
                                                                     unsigned height)
{
  const Vec3 zc = unit({-C[0], -C[1], -C[2]});
  const Vec3 up = std::fabs(zc[1]) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  const Vec3 xc = unit(cross(up, zc)), yc = cross(zc, xc);
  vpHomogeneousMatrix fMc;
  for (unsigned r = 0; r < 3; ++r) {
    fMc[r][0] = xc[r], fMc[r][1] = yc[r], fMc[r][2] = zc[r], fMc[r][3] = C[r] * 1e-3;
  }
  return Projection(fMc, cam, width, height);
}

} // namespace pm::core
