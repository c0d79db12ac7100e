#include "pm/calib/TagBoard.h"

#include <cmath>
#include <cstdlib>
#include <memory>

#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>

#include "pm/core/Error.h"

namespace pm::calib {

void TagBoard::validate() const
{
  if (rows < 1 || cols < 1 || rows * cols > 100 || firstId < 0 || firstId + rows * cols > 587)
    throw Error("tag board: 1 to 100 tags with ids in the 36h11 family (0..586)");
  // The black square is 8 of the tag's 10 cells: the white border takes tagSize / 8 on each side.
  if (!(tagSizeMm > 0) || !(pitchMm >= tagSizeMm * 10.0 / 8.0) || !(marginMm >= 0))
    throw Error("tag board: the pitch must leave the tags' white borders (pitch >= 1.25 x tag size)");
}

vpPoint TagBoard::centre(int id) const
{
  const int k = id - firstId, r = k / cols, c = k % cols;
  return vpPoint((c - (cols - 1) / 2.0) * pitchMm * 1e-3, (r - (rows - 1) / 2.0) * pitchMm * 1e-3, 0);
}

std::array<vpPoint, 4> TagBoard::corners(int id) const
{
  const vpPoint o = centre(id);
  const double h = tagSizeMm / 2e3, x = o.get_oX(), y = o.get_oY();
  return {vpPoint(x - h, y - h, 0), vpPoint(x + h, y - h, 0), vpPoint(x + h, y + h, 0), vpPoint(x - h, y + h, 0)};
}

vpImage<vpRGBa> TagBoard::render(double pixelsPerMm) const
{
  validate();
  std::unique_ptr<apriltag_family_t, void (*)(apriltag_family_t *)> fam(tag36h11_create(), tag36h11_destroy);
  const unsigned w = static_cast<unsigned>(std::lround(widthMm() * pixelsPerMm));
  const unsigned h = static_cast<unsigned>(std::lround(heightMm() * pixelsPerMm));
  vpImage<vpRGBa> img(h, w, vpRGBa(255, 255, 255));
  const double cell = tagSizeMm / 8.0;
  for (int k = 0; k < rows * cols; ++k) {
    image_u8_t *t = apriltag_to_image(fam.get(), firstId + k);
    const vpPoint o = centre(firstId + k);
    for (unsigned v = 0; v < h; ++v)
      for (unsigned u = 0; u < w; ++u) {
        const double x = (u + 0.5) / pixelsPerMm - widthMm() / 2, y = (v + 0.5) / pixelsPerMm - heightMm() / 2;
        const double gx = (x - o.get_oX() * 1e3) / cell + t->width / 2.0, gy = (y - o.get_oY() * 1e3) / cell + t->height / 2.0;
        if (gx >= 0 && gy >= 0 && gx < t->width && gy < t->height) {
          const unsigned char g = t->buf[static_cast<int>(gy) * t->stride + static_cast<int>(gx)];
          img[v][u] = vpRGBa(g, g, g);
        }
      }
    free(t->buf);
    free(t);
  }
  return img;
}

} // namespace pm::calib
