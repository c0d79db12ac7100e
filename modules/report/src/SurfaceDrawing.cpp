#include "pm/report/SurfaceDrawing.h"

#include <cmath>
#include <limits>

#include "pm/core/PinholeCamera.h"
#include "pm/model/HullGeometry.h"

namespace pm::report {

using model::hull::Vec3;
using model::hull::dot;
using model::hull::sub;
using model::hull::unit;

vpImage<vpRGBa> drawSurface(const std::vector<model::SurfacePoint> &surface, const vpHomogeneousMatrix &mMc,
                            const vpCameraParameters &cam, unsigned w, unsigned h, vpImage<unsigned char> *mask)
{
  const core::PinholeCamera::Projection pin(mMc, cam, w, h);
  vpImage<vpRGBa> out(h, w, vpRGBa(0, 0, 0));
  std::vector<float> zbuf(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity());
  for (const model::SurfacePoint &s : surface) {
    double u, v, z;
    if (!pin.project({s.x, s.y, s.z}, u, v, z))
      continue;
    const Vec3 toCam = unit(sub(pin.centre, {s.x, s.y, s.z}));
    const bool facing = dot(toCam, {s.nx, s.ny, s.nz}) > 0;
    const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
    for (int dv = -1; dv <= 1; ++dv)
      for (int du = -1; du <= 1; ++du) {
        const int x = ui + du, y = vi + dv;
        if (x < 0 || y < 0 || x >= pin.w || y >= pin.h)
          continue;
        float &d = zbuf[static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)];
        if (z < d) {
          d = static_cast<float>(z);
          // Shaded by the normal, so that the shape reads where the colour is plain.
          const double shade = facing ? 0.55 + 0.45 * dot(toCam, {s.nx, s.ny, s.nz}) : 0.4;
          out[static_cast<unsigned>(y)][static_cast<unsigned>(x)] =
              vpRGBa(static_cast<unsigned char>(s.r * shade), static_cast<unsigned char>(s.g * shade),
                     static_cast<unsigned char>(s.b * shade));
        }
      }
  }
  if (mask) {
    mask->resize(h, w, 0);
    for (unsigned y = 0; y < h; ++y)
      for (unsigned x = 0; x < w; ++x)
        (*mask)[y][x] = std::isfinite(zbuf[static_cast<std::size_t>(y) * w + x]) ? 255 : 0;
  }
  return out;
}

} // namespace pm::report
