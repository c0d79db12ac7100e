#include "pm/model/VisualHull.h"

#include <algorithm>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"

namespace pm::model {

using hull::Vec3;

long VisualHull::occupied() const { return static_cast<long>(std::count(occ.begin(), occ.end(), std::uint8_t(1))); }

double VisualHull::volumeCm3() const { return static_cast<double>(occupied()) * cell * cell * cell * 1e-3; }

namespace hull {

Vec3 silhouettesMeet(const std::vector<HullView> &cams, const std::vector<vpImage<unsigned char>> &masks)
{
  double A[9] = {0}, b[3] = {0};
  for (std::size_t i = 0; i < cams.size(); ++i) {
    const cv::Mat m(static_cast<int>(masks[i].getHeight()), static_cast<int>(masks[i].getWidth()), CV_8U,
                    const_cast<unsigned char *>(masks[i].bitmap));
    const cv::Moments mo = cv::moments(m, true);
    if (mo.m00 <= 0)
      continue;
    const Vec3 d = cams[i].cam.ray(mo.m10 / mo.m00, mo.m01 / mo.m00), o = cams[i].cam.centre;
    // (I - d d^T) x = (I - d d^T) o, summed.
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const double P = (r == c ? 1.0 : 0.0) - d[static_cast<std::size_t>(r)] * d[static_cast<std::size_t>(c)];
        A[3 * r + c] += P;
        b[r] += P * o[static_cast<std::size_t>(c)];
      }
  }
  cv::Mat Am(3, 3, CV_64F, A), bm(3, 1, CV_64F, b), x;
  if (!cv::solve(Am, bm, x, cv::DECOMP_SVD))
    throw core::Error("all-around model: the views' rays do not meet (are the poses right?)");
  return {x.at<double>(0), x.at<double>(1), x.at<double>(2)};
}

double field(const std::vector<const HullView *> &cams, const Vec3 &X)
{
  double f = 1e6;
  for (const hull::HullView *vc : cams) {
    double u, v, z;
    if (!vc->cam.project(X, u, v, z))
      return -1e6;
    f = std::min(f, vc->sdSmooth(u, v));
  }
  return f;
}

} // namespace hull

namespace {

enum class CellClass
{
  Outside,
  Inside,
  Boundary
};

//! How the cube of half-diagonal \e radius (mm) at \e c stands against the silhouettes of \e cams.
CellClass classify(const std::vector<const hull::HullView *> &cams, const Vec3 &c, double radius)
{
  bool allInside = true;
  for (const hull::HullView *vc : cams) {
    double u, v, z;
    if (!vc->cam.project(c, u, v, z))
      return CellClass::Outside;
    const double rpx = radius * std::max(vc->cam.px, vc->cam.py) / std::max(z - radius, 1.0);
    const double d = vc->sd(u, v);
    if (d < -rpx)
      return CellClass::Outside;
    if (d <= rpx)
      allInside = false;
  }
  return allInside ? CellClass::Inside : CellClass::Boundary;
}

void carve(const std::vector<const hull::HullView *> &cams, VisualHull &g, int x0, int y0, int z0, int size)
{
  const double s = size * g.cell;
  const Vec3 c{g.origin[0] + (x0 + 0.5 * size) * g.cell, g.origin[1] + (y0 + 0.5 * size) * g.cell, g.origin[2] + (z0 + 0.5 * size) * g.cell};
  const CellClass k = classify(cams, c, size == 1 ? 0.0 : 0.5 * std::sqrt(3.0) * s);
  if (k == CellClass::Outside)
    return;
  if (k == CellClass::Inside || size == 1) {
    for (int z = z0; z < std::min(z0 + size, g.n); ++z)
      for (int y = y0; y < std::min(y0 + size, g.n); ++y)
        for (int x = x0; x < std::min(x0 + size, g.n); ++x)
          g.occ[g.idx(x, y, z)] = 1;
    return;
  }
  const int hs = size / 2;
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const int x = x0 + dx * hs, y = y0 + dy * hs, z = z0 + dz * hs;
        if (x < g.n && y < g.n && z < g.n)
          carve(cams, g, x, y, z, hs);
      }
}

} // namespace

void hullBox(const std::vector<hull::HullView> &cams, const std::vector<vpImage<unsigned char>> &masks, Vec3 &centre, double &radius)
{
  centre = hull::silhouettesMeet(cams, masks);
  radius = 0;
  for (std::size_t i = 0; i < cams.size(); ++i) {
    double u, v, z;
    if (!cams[i].cam.project(centre, u, v, z))
      throw core::Error("all-around model: the target's centre is behind a camera of view " + std::to_string(cams[i].view) +
                  " (are the poses right?)");
    double far2 = 0;
    const vpImage<unsigned char> &m = masks[i];
    for (unsigned y = 0; y < m.getHeight(); ++y)
      for (unsigned x = 0; x < m.getWidth(); ++x)
        if (m[y][x])
          far2 = std::max(far2, (x - u) * (x - u) + (y - v) * (y - v));
    radius = std::max(radius, 1.3 * std::sqrt(far2) * z / std::min(cams[i].cam.px, cams[i].cam.py));
  }
  radius = std::max(radius, 5.0);
}

std::vector<bool> agreeingViews(const std::vector<hull::HullView> &cams, std::size_t nViews, const Vec3 &origin, int n, double cell,
                                double maxFraction, const std::vector<std::string> &names, std::vector<std::string> &why)
{
  std::vector<bool> used(nViews, true);
  const double r = 0.5 * std::sqrt(3.0) * cell;
  std::vector<std::vector<int>> carvers; // per coarse cell: the views that carve it (when two or fewer)
  carvers.reserve(static_cast<std::size_t>(n) * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3 c{origin[0] + (x + 0.5) * cell, origin[1] + (y + 0.5) * cell, origin[2] + (z + 0.5) * cell};
        std::vector<int> by;
        for (const hull::HullView &vc : cams) {
          if (!by.empty() && by.back() == vc.view)
            continue;
          double u, v, zz;
          const bool out1 = !vc.cam.project(c, u, v, zz) || vc.sd(u, v) < -r * vc.cam.px / std::max(zz - r, 1.0);
          if (out1)
            by.push_back(vc.view);
          if (by.size() > 2)
            break;
        }
        if (by.size() <= 2)
          carvers.push_back(std::move(by));
      }
  for (std::size_t round = 0; round < nViews / 4; ++round) {
    std::vector<long> alone(nViews, 0);
    long kept = 0;
    for (const std::vector<int> &by : carvers) {
      int k = 0, who = -1;
      for (int v : by)
        if (used[static_cast<std::size_t>(v)]) {
          ++k;
          who = v;
        }
      if (k == 0)
        ++kept;
      else if (k == 1)
        ++alone[static_cast<std::size_t>(who)];
    }
    std::size_t worst = 0;
    double worstF = -1;
    for (std::size_t v = 0; v < nViews; ++v)
      if (used[v]) {
        const double f = static_cast<double>(alone[v]) / static_cast<double>(std::max(1L, kept + alone[v]));
        if (f > worstF) {
          worstF = f;
          worst = v;
        }
      }
    if (worstF <= maxFraction)
      break;
    used[worst] = false;
    why.push_back(names[worst] + ": its silhouettes alone carve " + std::to_string(static_cast<int>(100 * worstF)) +
                  " % of what the other views keep (a wrong pose or background?)");
  }
  return used;
}

VisualHull hullGrid(const Vec3 &centre, double radius, double finestMm)
{
  VisualHull g;
  g.cell = std::max(finestMm, 2 * radius / 256);
  g.n = static_cast<int>(std::ceil(2 * radius / g.cell));
  g.origin = {centre[0] - 0.5 * g.n * g.cell, centre[1] - 0.5 * g.n * g.cell, centre[2] - 0.5 * g.n * g.cell};
  return g;
}

void carveVisualHull(const std::vector<const hull::HullView *> &cams, VisualHull &g, double coarsestMm)
{
  int levels = 0;
  while ((1 << levels) < g.n)
    ++levels;
  const int rootSize = 1 << levels;
  g.occ.assign(static_cast<std::size_t>(g.n) * g.n * g.n, 0);
  int start = 1; // a power of two, so that halving reaches single cells
  while (start * 2 <= rootSize && start * 2 * g.cell <= coarsestMm)
    start *= 2;
  for (int z = 0; z < g.n; z += start)
    for (int y = 0; y < g.n; y += start)
      for (int x = 0; x < g.n; x += start)
        carve(cams, g, x, y, z, start);
  if (g.occupied() < 8)
    throw core::Error("all-around model: the views carve the hull to nothing (the poses, the rig's calibration or the "
                "silhouettes disagree)");
}

} // namespace pm::model
