#include "pm/calib/TagBoard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <apriltag/apriltag.h>
#include <apriltag/tag36h11.h>

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/detection/vpDetectorAprilTag.h>

#include "pm/core/Error.h"

namespace pm::calib {

std::string TagBoard::describe() const
{
  char buf[160];
  std::snprintf(buf, sizeof buf, "%dx%d AprilTag 36h11 board (ids %d..%d), %g mm tags, %g mm apart", rows, cols, firstId,
                firstId + rows * cols - 1, tagSizeMm, pitchMm);
  return buf;
}

void TagBoard::validate() const
{
  if (rows < 1 || cols < 1 || rows * cols > 100 || firstId < 0 || firstId + rows * cols > 587)
    throw core::Error("tag board: 1 to 100 tags with ids in the 36h11 family (0..586)");
  // The black square is 8 of the tag's 10 cells: the white border takes tagSize / 8 on each side.
  if (!(tagSizeMm > 0) || !(pitchMm >= tagSizeMm * 10.0 / 8.0) || !(marginMm >= 0))
    throw core::Error("tag board: the pitch must leave the tags' white borders (pitch >= 1.25 x tag size)");
  if (minTags < 1)
    throw core::Error("tag board: at least one tag is needed for a pose");
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

BoardView TagBoard::find(const vpImage<vpRGBa> &I, const vpCameraParameters &cam, const std::string &name, bool whole) const
{
  validate();
  vpImage<unsigned char> grey;
  vpImageConvert::convert(I, grey);
  vpDetectorAprilTag det(vpDetectorAprilTag::TAG_36h11);
  det.setZAlignedWithCameraAxis(true); // the tag frame then matches the board's (z into the board)
  det.detect(grey);
  BoardView view;
  CornerMatches matches;
  for (std::size_t i = 0; i < det.getNbObjects(); ++i) {
    int id = -1;
    if (std::sscanf(det.getMessage(i).c_str(), "36h11 id: %d", &id) != 1 || !hasId(id))
      continue;
    // Match each detected corner with the board corner that the tag's own pose projects nearest.
    vpHomogeneousMatrix cMt;
    if (!det.getPose(i, tagSizeMm * 1e-3, cam, cMt))
      continue;
    const vpPoint o = centre(id);
    const vpHomogeneousMatrix cMb = cMt * vpHomogeneousMatrix(-o.get_oX(), -o.get_oY(), 0, 0, 0, 0);
    const auto model = corners(id);
    int n = 0;
    for (const vpImagePoint &ip : det.getPolygon(i)) {
      double best = 1e30;
      int bj = -1;
      for (int j = 0; j < 4; ++j) {
        vpPoint P = model[static_cast<std::size_t>(j)];
        P.track(cMb);
        double u = 0, v = 0;
        vpMeterPixelConversion::convertPoint(cam, P.get_x(), P.get_y(), u, v);
        const double d = std::hypot(u - ip.get_u(), v - ip.get_v());
        if (d < best)
          best = d, bj = j;
      }
      if (best > 5.0)
        continue;
      matches.add(model[static_cast<std::size_t>(bj)], ip, cam);
      ++n;
    }
    view.features += n == 4 ? 1 : 0;
  }
  const int needed = whole ? rows * cols : std::min(minTags, rows * cols);
  if (view.features < needed)
    throw core::Error("tag board: " + std::to_string(view.features) + " of its tags found in the " + name + " image (at least " +
                std::to_string(needed) + " needed: is the board in view, sharp, and the layout right?)");
  solveBoardPose(matches, cam, view);
  return view;
}


PatternDetection TagBoard::detect(const vpImage<vpRGBa> &I, const std::string &name) const
{
  validate();
  vpImage<unsigned char> grey;
  vpImageConvert::convert(I, grey);
  vpDetectorAprilTag det(vpDetectorAprilTag::TAG_36h11);
  det.setZAlignedWithCameraAxis(true);
  det.detect(grey);
  PatternDetection d;
  int tags = 0;
  for (std::size_t i = 0; i < det.getNbObjects(); ++i) {
    int id = -1;
    if (std::sscanf(det.getMessage(i).c_str(), "36h11 id: %d", &id) != 1 || !hasId(id))
      continue;
    const std::vector<vpImagePoint> poly = det.getPolygon(i);
    if (poly.size() != 4)
      continue;
    const auto model = corners(id);
    for (int k = 0; k < 4; ++k) {
      d.ids.push_back(4 * id + (3 - k)); // the detector's corner k is the tag frame's corner 3 - k (test TagBoard.DetectNumbersCornersAsFind)
      d.pixels.push_back(poly[static_cast<std::size_t>(k)]);
      d.points.push_back(model[static_cast<std::size_t>(3 - k)]);
    }
    ++tags;
  }
  const int needed = std::min(minTags, rows * cols);
  if (tags < needed)
    throw core::Error("tag board: " + std::to_string(tags) + " of its tags found in the " + name + " image (at least " +
                std::to_string(needed) + " needed: is the board in view, sharp, and the layout right?)");
  return d;
}

} // namespace pm::calib
