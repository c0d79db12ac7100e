#include "pm/model/AllAroundModelBuilder.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <unordered_map>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/core/UndistortMap.h"

namespace pm {

void AllAroundParams::validate() const
{
  silhouette.validate();
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw Error(std::string("all-around model parameter ") + what);
  };
  check(minViews >= 2 && minViews <= 1000, "minimum views must lie in [2, 1000]");
  check(finestMm > 0.1 && finestMm <= 20, "finest cell must lie in (0.1, 20] mm");
  check(coarsestMm >= finestMm && coarsestMm <= 200, "coarsest cell must lie in [finest, 200] mm");
  check(outlierCarveFraction > 0 && outlierCarveFraction <= 1, "outlier carve fraction must lie in (0, 1]");
  check(visibilityTolMm > 0 && visibilityTolMm <= 50, "visibility tolerance must lie in (0, 50] mm");
  check(refineDepthMm >= 0 && refineDepthMm <= 100, "refine depth must lie in [0, 100] mm");
  check(refineMinScore >= -1 && refineMinScore <= 1, "refine minimum score must lie in [-1, 1]");
  check(refineMinGain >= 0 && refineMinGain <= 2, "refine minimum gain must lie in [0, 2]");
  check(minSaturation >= 0 && minSaturation < 1, "minimum saturation must lie in [0, 1)");
  check(minValue >= 0 && minValue < 1, "minimum value must lie in [0, 1)");
  check(minHueFromBackgroundDeg >= 0 && minHueFromBackgroundDeg < 180, "minimum hue from background must lie in [0, 180)");
  check(maxHueSpreadDeg > 0 && maxHueSpreadDeg <= 180, "maximum hue spread must lie in (0, 180]");
  check(viewpoints >= 1 && viewpoints <= 5000, "viewpoints must lie in [1, 5000]");
  check(capDeg > 0 && capDeg <= 180, "cap must lie in (0, 180] deg");
  check(nIn >= 8 && nIn <= 20000, "S_in points per viewpoint must lie in [8, 20000]");
  check(edgeShare >= 0 && edgeShare <= 1, "edge share must lie in [0, 1]");
  check(backdropHueDeg < 360, "the backdrop's hue must lie in [0, 360) degrees (negative: background images)");
  check(nOut >= 8 && nOut <= 20000, "S_out points per viewpoint must lie in [8, 20000]");
  check(stripGapPx >= 1 && stripGapPx <= 100, "strip gap must lie in [1, 100] px");
  check(stripWidthPx >= 0 && stripWidthPx <= 100, "strip width must lie in [0, 100] px");
  check(stripRows >= 1 && stripRows <= 10, "strip rows must lie in [1, 10]");
}

namespace {

using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Vec3 unit(const Vec3 &a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec3{a[0] / n, a[1] / n, a[2] / n} : Vec3{0, 0, 1};
}

//! A pinhole camera: cMw (mm), intrinsics, size.
struct Pinhole
{
  double R[9], t[3];
  double px, py, u0, v0;
  int w, h;
  Vec3 centre; //!< in the world (mm)

  Pinhole(const vpHomogeneousMatrix &wMc, const vpCameraParameters &cam, unsigned width, unsigned height)
      : px(cam.get_px()), py(cam.get_py()), u0(cam.get_u0()), v0(cam.get_v0()), w(static_cast<int>(width)),
        h(static_cast<int>(height))
  {
    const vpHomogeneousMatrix cMw = wMc.inverse();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        R[3 * r + c] = cMw[r][c];
      t[r] = 1e3 * cMw[r][3];
      centre[r] = 1e3 * wMc[r][3];
    }
  }
  //! Camera-frame position of world point \e X (mm).
  Vec3 toCam(const Vec3 &X) const
  {
    return {R[0] * X[0] + R[1] * X[1] + R[2] * X[2] + t[0], R[3] * X[0] + R[4] * X[1] + R[5] * X[2] + t[1],
            R[6] * X[0] + R[7] * X[1] + R[8] * X[2] + t[2]};
  }
  bool project(const Vec3 &X, double &u, double &v, double &z) const
  {
    const Vec3 c = toCam(X);
    z = c[2];
    if (!(z > 1))
      return false;
    u = px * c[0] / z + u0;
    v = py * c[1] / z + v0;
    return true;
  }
  //! The world ray direction of pixel (u, v).
  Vec3 ray(double u, double v) const
  {
    const Vec3 d{(u - u0) / px, (v - v0) / py, 1.0};
    return unit({R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2],
                 R[2] * d[0] + R[5] * d[1] + R[8] * d[2]});
  }
};

//! One camera of one view: its pinhole, ideal photo, silhouette's signed distance (px, > 0 inside).
struct ViewCamera
{
  Pinhole cam;
  vpImage<vpRGBa> photo;
  cv::Mat signedDist;
  int view;
  double sd(double u, double v) const
  {
    const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
    if (ui < 0 || vi < 0 || ui >= cam.w || vi >= cam.h)
      return -1e6;
    return signedDist.at<float>(vi, ui);
  }
};

cv::Mat signedDistance(const vpImage<unsigned char> &mask)
{
  const int h = static_cast<int>(mask.getHeight()), w = static_cast<int>(mask.getWidth());
  cv::Mat m(h, w, CV_8U, const_cast<unsigned char *>(mask.bitmap));
  cv::Mat inside, outside, inv;
  cv::distanceTransform(m, inside, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::bitwise_not(m, inv);
  cv::distanceTransform(inv, outside, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return inside - outside;
}

//! The hull as a dense grid of occupied cells.
struct Grid
{
  Vec3 origin; //!< world position of cell (0, 0, 0)'s corner (mm)
  double cell = 1;
  int n = 0;
  std::vector<std::uint8_t> occ;
  std::size_t idx(int x, int y, int z) const
  {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(n) + static_cast<std::size_t>(y)) * static_cast<std::size_t>(n) +
           static_cast<std::size_t>(x);
  }
  bool at(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n && occ[idx(x, y, z)]; }
  Vec3 centre(int x, int y, int z) const
  {
    return {origin[0] + (x + 0.5) * cell, origin[1] + (y + 0.5) * cell, origin[2] + (z + 0.5) * cell};
  }
};

enum class CellClass
{
  Outside,
  Inside,
  Boundary
};

//! How the cube of half-diagonal \e radius (mm) at \e c stands against the silhouettes of \e cams.
CellClass classify(const std::vector<const ViewCamera *> &cams, const Vec3 &c, double radius)
{
  bool allInside = true;
  for (const ViewCamera *vc : cams) {
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

void carve(const std::vector<const ViewCamera *> &cams, Grid &g, int x0, int y0, int z0, int size)
{
  const double s = size * g.cell;
  const Vec3 c{g.origin[0] + (x0 + 0.5 * size) * g.cell, g.origin[1] + (y0 + 0.5 * size) * g.cell,
               g.origin[2] + (z0 + 0.5 * size) * g.cell};
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

//! The point nearest (least squares) to the rays from each camera through its silhouette's centroid.
Vec3 raysMeet(const std::vector<ViewCamera> &cams, const std::vector<vpImage<unsigned char>> &masks)
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
        const double P = (r == c ? 1.0 : 0.0) - d[r] * d[c];
        A[3 * r + c] += P;
        b[r] += P * o[c];
      }
  }
  cv::Mat Am(3, 3, CV_64F, A), bm(3, 1, CV_64F, b), x;
  if (!cv::solve(Am, bm, x, cv::DECOMP_SVD))
    throw Error("all-around model: the views' rays do not meet (are the poses right?)");
  return {x.at<double>(0), x.at<double>(1), x.at<double>(2)};
}

//! Circular median-like hue: the sample with the least summed distance to the others (deg).
float medoidHue(const std::vector<float> &h, float &spread)
{
  float best = h[0];
  double bestSum = 1e18;
  for (float a : h) {
    double s = 0;
    for (float b : h)
      s += hueDistance(a, b);
    if (s < bestSum) {
      bestSum = s;
      best = a;
    }
  }
  std::vector<float> d;
  d.reserve(h.size());
  for (float b : h)
    d.push_back(hueDistance(best, b));
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  spread = d[d.size() / 2];
  return best;
}

struct ColourSample
{
  float h, s, v;
  unsigned char r, g, b;
};

//! A depth buffer of the surface points seen by \e cam, splatted over \e radius pixels.
void depthBuffer(const Pinhole &cam, const std::vector<Vec3> &pts, int radius, std::vector<float> &zbuf)
{
  zbuf.assign(static_cast<std::size_t>(cam.w) * static_cast<std::size_t>(cam.h), std::numeric_limits<float>::infinity());
  for (const Vec3 &p : pts) {
    double u, v, z;
    if (!cam.project(p, u, v, z))
      continue;
    const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
    for (int dv = -radius; dv <= radius; ++dv)
      for (int du = -radius; du <= radius; ++du) {
        const int x = ui + du, y = vi + dv;
        if (x < 0 || y < 0 || x >= cam.w || y >= cam.h)
          continue;
        float &d = zbuf[static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(x)];
        d = std::min(d, static_cast<float>(z));
      }
  }
}

//! The 5x5 patch around where \e X projects in \e vc's photo (R, G, B of each pixel), zero-mean and unit-norm; false off the image or flat.
bool patchAt(const ViewCamera &vc, const Vec3 &X, std::array<float, 75> &out)
{
  double u, v, z;
  if (!vc.cam.project(X, u, v, z))
    return false;
  const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
  if (ui < 2 || vi < 2 || ui >= vc.cam.w - 2 || vi >= vc.cam.h - 2)
    return false;
  double mean = 0;
  std::size_t k = 0;
  for (int dv = -2; dv <= 2; ++dv)
    for (int du = -2; du <= 2; ++du) {
      const vpRGBa px = vc.photo[static_cast<unsigned>(vi + dv)][static_cast<unsigned>(ui + du)];
      out[k++] = px.R, out[k++] = px.G, out[k++] = px.B;
      mean += px.R + px.G + px.B;
    }
  mean /= 75.0;
  double n2 = 0;
  for (float &x : out) {
    x = static_cast<float>(x - mean);
    n2 += static_cast<double>(x) * x;
  }
  if (n2 < 75.0 * 36.0) // under 6 grey levels of contrast: no texture to match
    return false;
  const float inv = static_cast<float>(1.0 / std::sqrt(n2));
  for (float &x : out)
    x *= inv;
  return true;
}

/*!
  Moves each surface point seen by 3 or more cameras inward along its normal, by whole cells up to
  refineDepthMm, to where the mean correlation of each camera's patch with the others' mean is
  highest, when that is clearly better than at the hull (by refineMinGain) and good in itself
  (refineMinScore). Returns the number of points moved.
*/
int refineByPhotoConsistency(const std::vector<const ViewCamera *> &cams, const std::vector<std::vector<std::uint16_t>> &seenBy,
                             const std::vector<Vec3> &normals, const AllAroundParams &p, double cell, std::vector<Vec3> &pts)
{
  const int steps = static_cast<int>(std::floor(p.refineDepthMm / cell));
  std::vector<Vec3> moved = pts;
  int n = 0;
  std::vector<std::array<float, 75>> patches;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (seenBy[i].size() < 3)
      continue;
    double best = -2, atHull = -2;
    int bestStep = 0;
    for (int s = 0; s <= steps; ++s) {
      const Vec3 q{pts[i][0] - s * cell * normals[i][0], pts[i][1] - s * cell * normals[i][1], pts[i][2] - s * cell * normals[i][2]};
      patches.clear();
      std::array<float, 75> pa;
      for (std::uint16_t ci : seenBy[i])
        if (patchAt(*cams[ci], q, pa))
          patches.push_back(pa);
      if (patches.size() < 3)
        break;
      // The mean patch, and each camera's correlation with it.
      std::array<double, 75> m{};
      for (const auto &q2 : patches)
        for (std::size_t k = 0; k < 75; ++k)
          m[k] += q2[k];
      double mn = 0;
      for (double x : m)
        mn += x * x;
      mn = std::sqrt(mn);
      double score = 0;
      for (const auto &q2 : patches) {
        double d = 0;
        for (std::size_t k = 0; k < 75; ++k)
          d += q2[k] * m[k];
        score += mn > 0 ? d / mn : 0.0;
      }
      score /= static_cast<double>(patches.size());
      if (s == 0)
        atHull = score;
      if (score > best) {
        best = score;
        bestStep = s;
      }
    }
    if (bestStep > 0 && best >= p.refineMinScore && best - atHull >= p.refineMinGain) {
      for (int k = 0; k < 3; ++k)
        moved[i][k] = pts[i][k] - bestStep * cell * normals[i][k];
      ++n;
    }
  }
  pts.swap(moved);
  return n;
}

//! For each surface point with a hue: whether a point with a hue within \e radiusMm differs from it by over \e hueDeg.
std::vector<bool> hueEdges(const std::vector<SurfacePoint> &s, double radiusMm, double hueDeg)
{
  std::unordered_map<long long, std::vector<std::size_t>> cells;
  auto cellOf = [radiusMm](float x) { return static_cast<long long>(std::floor(x / radiusMm)); };
  auto key = [](long long x, long long y, long long z) { return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL); };
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].hasHue)
      cells[key(cellOf(s[i].x), cellOf(s[i].y), cellOf(s[i].z))].push_back(i);
  std::vector<bool> edge(s.size(), false);
  const double r2 = radiusMm * radiusMm;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s[i].hasHue)
      continue;
    const long long cx = cellOf(s[i].x), cy = cellOf(s[i].y), cz = cellOf(s[i].z);
    for (long long dz = -1; dz <= 1 && !edge[i]; ++dz)
      for (long long dy = -1; dy <= 1 && !edge[i]; ++dy)
        for (long long dx = -1; dx <= 1 && !edge[i]; ++dx) {
          const auto it = cells.find(key(cx + dx, cy + dy, cz + dz));
          if (it == cells.end())
            continue;
          for (std::size_t j : it->second) {
            const double ex = s[j].x - s[i].x, ey = s[j].y - s[i].y, ez = s[j].z - s[i].z;
            if (ex * ex + ey * ey + ez * ez <= r2 && hueDistance(s[i].hue, s[j].hue) > hueDeg) {
              edge[i] = true;
              break;
            }
          }
        }
  }
  return edge;
}

} // namespace

AllAroundBuild buildAllAroundModel(const StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &p)
{
  const auto t0 = std::chrono::steady_clock::now();
  p.validate();
  rig.validate();
  if (pass.size() < p.minViews)
    throw Error("all-around model: the pass holds " + std::to_string(pass.size()) + " views; at least " +
                std::to_string(p.minViews) + " are needed");
  AllAroundBuild out;
  out.nViews = pass.size();

  // 1. Silhouettes in the ideal images.
  const RigCamera *rc[2] = {&rig.left, &rig.right};
  std::unique_ptr<UndistortMap> und[2];
  for (int c = 0; c < 2; ++c)
    if (!rc[c]->distortion.isNone())
      und[c] = std::make_unique<UndistortMap>(*rc[c]);
  std::vector<ViewCamera> cams;
  std::vector<vpImage<vpRGBa>> backgrounds;
  for (std::size_t k = 0; k < pass.size(); ++k) {
    const PassView &v = pass[k];
    const std::string name = v.name.empty() ? "view " + std::to_string(k) : v.name;
    const vpImage<vpRGBa> *ph[2] = {&v.left, &v.right}, *bg[2] = {&v.backgroundLeft, &v.backgroundRight};
    for (int c = 0; c < 2; ++c) {
      const char *side = c ? "right" : "left";
      const bool plain = p.backdropHueDeg >= 0; // a plain backdrop: the photo alone
      for (const vpImage<vpRGBa> *im : {ph[c], bg[c]})
        if ((im == ph[c] || !plain) && (im->getWidth() != rc[c]->width || im->getHeight() != rc[c]->height))
          throw Error(name + ": a " + side + " image is " + std::to_string(im->getWidth()) + "x" +
                      std::to_string(im->getHeight()) + " but the rig's " + side + " camera is " +
                      std::to_string(rc[c]->width) + "x" + std::to_string(rc[c]->height));
      vpImage<vpRGBa> photo = und[c] ? und[c]->undistorted(*ph[c]) : *ph[c];
      // Against a plain backdrop the photo serves as its own background (H_B around the silhouette).
      vpImage<vpRGBa> back = plain ? photo : und[c] ? und[c]->undistorted(*bg[c]) : *bg[c];
      SilhouetteStats st;
      vpImage<unsigned char> mask = plain ? silhouetteOnBackdrop(photo, p.backdropHueDeg, p.silhouette, &st, name + " (" + side + ")")
                                          : silhouette(photo, back, p.silhouette, &st, name + " (" + side + ")");
      if (st.touchesBorder)
        throw Error(name + ": the target is cut by the " + std::string(side) +
                    " image's border: every view must see the whole target");
      out.shadowPx += st.shadowPx;
      ViewCamera vc{Pinhole(v.fMh * rc[c]->hMc, rc[c]->cam, rc[c]->width, rc[c]->height), std::move(photo),
                    signedDistance(mask), static_cast<int>(k)};
      cams.push_back(std::move(vc));
      backgrounds.push_back(std::move(back));
      out.silhouettes.push_back(std::move(mask));
    }
  }

  // 2. The box around the target.
  const Vec3 centre = raysMeet(cams, out.silhouettes);
  double radius = 0;
  for (std::size_t i = 0; i < cams.size(); ++i) {
    double u, v, z;
    if (!cams[i].cam.project(centre, u, v, z))
      throw Error("all-around model: the target's centre is behind a camera of view " + std::to_string(cams[i].view) +
                  " (are the poses right?)");
    double far2 = 0;
    const vpImage<unsigned char> &m = out.silhouettes[i];
    for (unsigned y = 0; y < m.getHeight(); ++y)
      for (unsigned x = 0; x < m.getWidth(); ++x)
        if (m[y][x])
          far2 = std::max(far2, (x - u) * (x - u) + (y - v) * (y - v));
    radius = std::max(radius, 1.3 * std::sqrt(far2) * z / std::min(cams[i].cam.px, cams[i].cam.py));
  }
  radius = std::max(radius, 5.0);
  double cell = std::max(p.finestMm, 2 * radius / 256);
  int levels = 0;
  while ((1 << levels) * cell < 2 * radius)
    ++levels;
  Grid g;
  g.cell = cell;
  g.n = static_cast<int>(std::ceil(2 * radius / cell));
  g.origin = {centre[0] - 0.5 * g.n * cell, centre[1] - 0.5 * g.n * cell, centre[2] - 0.5 * g.n * cell};
  const int rootSize = 1 << levels;
  out.cellMm = cell;

  // Views that disagree: on a coarse grid, the cells each view alone carves of what the others keep.
  std::vector<bool> used(pass.size(), true);
  {
    const int coarse = std::max(1, std::min(rootSize, static_cast<int>(std::lround(4.0 / cell))));
    const int nc = (g.n + coarse - 1) / coarse;
    const double r = 0.5 * std::sqrt(3.0) * coarse * cell;
    std::vector<std::vector<int>> carvers; // per coarse cell: the views that carve it
    carvers.reserve(static_cast<std::size_t>(nc) * nc * nc);
    for (int z = 0; z < nc; ++z)
      for (int y = 0; y < nc; ++y)
        for (int x = 0; x < nc; ++x) {
          const Vec3 c{g.origin[0] + (x + 0.5) * coarse * cell, g.origin[1] + (y + 0.5) * coarse * cell,
                       g.origin[2] + (z + 0.5) * coarse * cell};
          std::vector<int> by;
          for (const ViewCamera &vc : cams) {
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
    for (std::size_t round = 0; round < pass.size() / 4; ++round) {
      std::vector<long> alone(pass.size(), 0);
      long kept = 0;
      for (const std::vector<int> &by : carvers) {
        int n = 0, who = -1;
        for (int v : by)
          if (used[static_cast<std::size_t>(v)]) {
            ++n;
            who = v;
          }
        if (n == 0)
          ++kept;
        else if (n == 1)
          ++alone[static_cast<std::size_t>(who)];
      }
      std::size_t worst = 0;
      double worstF = -1;
      for (std::size_t v = 0; v < pass.size(); ++v)
        if (used[v]) {
          const double f = static_cast<double>(alone[v]) / static_cast<double>(std::max(1L, kept + alone[v]));
          if (f > worstF) {
            worstF = f;
            worst = v;
          }
        }
      if (worstF <= p.outlierCarveFraction)
        break;
      used[worst] = false;
      out.leftOut.push_back((pass[worst].name.empty() ? "view " + std::to_string(worst) : pass[worst].name) +
                            ": its silhouettes alone carve " + std::to_string(static_cast<int>(100 * worstF)) +
                            " % of what the other views keep (a wrong pose or background?)");
    }
  }
  out.nViewsUsed = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  if (out.nViewsUsed < p.minViews)
    throw Error("all-around model: " + std::to_string(out.nViewsUsed) + " views agree, at least " +
                std::to_string(p.minViews) + " are needed (" + (out.leftOut.empty() ? "" : out.leftOut[0]) + ")");
  std::vector<const ViewCamera *> usedCams;
  for (const ViewCamera &vc : cams)
    if (used[static_cast<std::size_t>(vc.view)])
      usedCams.push_back(&vc);

  // 3. Carving, coarse to fine.
  g.occ.assign(static_cast<std::size_t>(g.n) * g.n * g.n, 0);
  int start = 1; // a power of two, so that halving reaches single cells
  while (start * 2 <= rootSize && start * 2 * cell <= p.coarsestMm)
    start *= 2;
  for (int z = 0; z < g.n; z += start)
    for (int y = 0; y < g.n; y += start)
      for (int x = 0; x < g.n; x += start)
        carve(usedCams, g, x, y, z, start);
  const long nOcc = std::count(g.occ.begin(), g.occ.end(), std::uint8_t(1));
  if (nOcc < 8)
    throw Error("all-around model: the views carve the hull to nothing (the poses, the rig's calibration or the "
                "silhouettes disagree)");
  out.hullVolumeCm3 = static_cast<double>(nOcc) * cell * cell * cell * 1e-3;

  // 4. The surface and its normals.
  Vec3 mean{0, 0, 0};
  std::vector<Vec3> pts, normals;
  for (int z = 0; z < g.n; ++z)
    for (int y = 0; y < g.n; ++y)
      for (int x = 0; x < g.n; ++x) {
        if (!g.occ[g.idx(x, y, z)])
          continue;
        const Vec3 c = g.centre(x, y, z);
        for (int k = 0; k < 3; ++k)
          mean[k] += c[k];
        if (g.at(x - 1, y, z) && g.at(x + 1, y, z) && g.at(x, y - 1, z) && g.at(x, y + 1, z) && g.at(x, y, z - 1) &&
            g.at(x, y, z + 1))
          continue;
        Vec3 n{0, 0, 0};
        const int R = 2;
        for (int dz = -R; dz <= R; ++dz)
          for (int dy = -R; dy <= R; ++dy)
            for (int dx = -R; dx <= R; ++dx)
              if (g.at(x + dx, y + dy, z + dz)) {
                n[0] -= dx;
                n[1] -= dy;
                n[2] -= dz;
              }
        pts.push_back(c);
        normals.push_back(unit(n));
      }
  for (int k = 0; k < 3; ++k)
    mean[k] /= static_cast<double>(nOcc);

  // 5. Which cameras see each point (the hull's depth buffer, the normal facing the camera, off the outline).
  std::vector<std::vector<std::uint16_t>> seenBy(pts.size());
  const int splat = std::max(1, static_cast<int>(std::ceil(0.5 * cell * rig.left.cam.get_px() / 400.0)));
  std::vector<float> zbuf;
  for (std::size_t ci = 0; ci < usedCams.size(); ++ci) {
    const ViewCamera *vc = usedCams[ci];
    depthBuffer(vc->cam, pts, splat, zbuf);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double u, v, z;
      if (!vc->cam.project(pts[i], u, v, z))
        continue;
      const Vec3 toCam = unit(sub(vc->cam.centre, pts[i]));
      if (dot(toCam, normals[i]) < 0.2)
        continue;
      const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
      if (ui < 0 || vi < 0 || ui >= vc->cam.w || vi >= vc->cam.h)
        continue;
      if (z > zbuf[static_cast<std::size_t>(vi) * static_cast<std::size_t>(vc->cam.w) + static_cast<std::size_t>(ui)] + p.visibilityTolMm)
        continue;
      if (vc->sd(u, v) < 2) // on the outline the pixel mixes target and background
        continue;
      seenBy[i].push_back(static_cast<std::uint16_t>(ci));
    }
  }
  // 6. Photo-consistency: the hull bulges in front of flat and concave faces (no silhouette carves
  // them); where the target has texture, each point moves inward along its normal to the depth where
  // the patches of the cameras that see it agree best.
  if (p.refineDepthMm > 0)
    out.nRefined = refineByPhotoConsistency(usedCams, seenBy, normals, p, cell, pts);
  std::vector<std::vector<ColourSample>> samples(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::uint16_t ci : seenBy[i]) {
      const ViewCamera *vc = usedCams[ci];
      double u, v, z;
      if (!vc->cam.project(pts[i], u, v, z))
        continue;
      const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
      if (ui < 0 || vi < 0 || ui >= vc->cam.w || vi >= vc->cam.h)
        continue;
      const vpRGBa px = vc->photo[static_cast<unsigned>(vi)][static_cast<unsigned>(ui)];
      const Hsv hsv = rgbToHsv(px);
      samples[i].push_back({hsv.h, hsv.s, hsv.v, px.R, px.G, px.B});
    }
  // H_B: the backgrounds around the silhouettes.
  std::vector<float> bgHues;
  for (std::size_t i = 0; i < cams.size(); ++i) {
    if (!used[static_cast<std::size_t>(cams[i].view)])
      continue;
    for (unsigned y = 0; y < out.silhouettes[i].getHeight(); y += 3)
      for (unsigned x = 0; x < out.silhouettes[i].getWidth(); x += 3) {
        const float d = cams[i].signedDist.at<float>(static_cast<int>(y), static_cast<int>(x));
        if (d < -3 && d > -40)
          bgHues.push_back(hueDeg(backgrounds[i][y][x]));
      }
  }
  const float bgHue = bgHues.empty() ? 0.f : circularMeanHue(bgHues);

  // Model frame: origin at the hull's centroid, axes those of the hand at the first used view.
  std::size_t first = 0;
  while (!used[first])
    ++first;
  const vpRotationMatrix fRm = pass[first].fMh.getRotationMatrix();
  out.fMm = vpHomogeneousMatrix(vpTranslationVector(mean[0] * 1e-3, mean[1] * 1e-3, mean[2] * 1e-3), fRm);
  auto toModel = [&](const Vec3 &w) {
    const Vec3 d = sub(w, mean);
    return Vec3{fRm[0][0] * d[0] + fRm[1][0] * d[1] + fRm[2][0] * d[2], fRm[0][1] * d[0] + fRm[1][1] * d[1] + fRm[2][1] * d[2],
                fRm[0][2] * d[0] + fRm[1][2] * d[1] + fRm[2][2] * d[2]};
  };
  auto dirToModel = [&](const Vec3 &d) {
    return Vec3{fRm[0][0] * d[0] + fRm[1][0] * d[1] + fRm[2][0] * d[2], fRm[0][1] * d[0] + fRm[1][1] * d[1] + fRm[2][1] * d[2],
                fRm[0][2] * d[0] + fRm[1][2] * d[1] + fRm[2][2] * d[2]};
  };

  std::vector<Vec3> mpts(pts.size()), mnorm(pts.size());
  out.surface.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    mpts[i] = toModel(pts[i]);
    mnorm[i] = dirToModel(normals[i]);
    SurfacePoint &s = out.surface[i];
    s.x = static_cast<float>(mpts[i][0]), s.y = static_cast<float>(mpts[i][1]), s.z = static_cast<float>(mpts[i][2]);
    s.nx = static_cast<float>(mnorm[i][0]), s.ny = static_cast<float>(mnorm[i][1]), s.nz = static_cast<float>(mnorm[i][2]);
    s.hue = 0, s.r = s.g = s.b = 128, s.nSeen = static_cast<std::uint8_t>(std::min<std::size_t>(255, samples[i].size()));
    s.hasHue = false, s.highlight = false;
    std::vector<ColourSample> &sm = samples[i];
    if (sm.empty())
      continue;
    // Highlights: samples much brighter and paler than the point's median.
    std::vector<float> vs, ss;
    for (const ColourSample &c : sm)
      vs.push_back(c.v), ss.push_back(c.s);
    std::nth_element(vs.begin(), vs.begin() + static_cast<long>(vs.size() / 2), vs.end());
    std::nth_element(ss.begin(), ss.begin() + static_cast<long>(ss.size() / 2), ss.end());
    const float mv = vs[vs.size() / 2], ms = ss[ss.size() / 2];
    std::vector<float> hues;
    std::vector<unsigned char> rs, gs, bs;
    for (const ColourSample &c : sm) {
      if (sm.size() >= 3 && c.v > mv + 0.15f && c.s < ms - 0.1f) {
        ++out.nHighlightSamples;
        continue;
      }
      rs.push_back(c.r), gs.push_back(c.g), bs.push_back(c.b);
      if (c.s >= p.minSaturation && c.v >= p.minValue)
        hues.push_back(c.h);
    }
    auto med = [](std::vector<unsigned char> &x) {
      std::nth_element(x.begin(), x.begin() + static_cast<long>(x.size() / 2), x.end());
      return x[x.size() / 2];
    };
    if (!rs.empty())
      s.r = med(rs), s.g = med(gs), s.b = med(bs);
    if (hues.size() * 2 < sm.size() || hues.empty())
      continue; // mostly pale: no hue to score
    float spread = 0;
    s.hue = medoidHue(hues, spread);
    if (hues.size() >= 2 && spread > p.maxHueSpreadDeg) {
      s.highlight = true;
      ++out.nHighlight;
      continue;
    }
    s.hasHue = hueDistance(s.hue, bgHue) > p.minHueFromBackgroundDeg;
  }

  // Hue edges: a point with a hue whose neighbours within 3 mm include one of a hue over 30 deg away.
  const std::vector<bool> edge = p.edgeShare > 0 ? hueEdges(out.surface, 3.0, 30.0) : std::vector<bool>(out.surface.size(), false);
  constexpr long kEdgeKey = 1L << 40; // picks on an edge sort after the others, one per cell of their own

  // 7. The viewpoints: a Fibonacci lattice over the sphere, those within the cap.
  const vpHomogeneousMatrix mMf = out.fMm.inverse();
  const vpHomogeneousMatrix mMh0 = mMf * pass[first].fMh;
  const Vec3 rest{1e3 * mMh0[0][3], 1e3 * mMh0[1][3], 1e3 * mMh0[2][3]};
  const double D = std::sqrt(dot(rest, rest));
  const Vec3 restDir = unit(rest);
  const double capCos = std::cos(p.capDeg * M_PI / 180);
  const int nSphere = static_cast<int>(std::ceil(p.viewpoints * 2.0 / (1.0 - capCos)));
  std::vector<Vec3> dirs{restDir};
  {
    // A lattice about the rest direction: its pole on restDir.
    const Vec3 a = unit(cross(restDir, std::fabs(restDir[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 b = cross(restDir, a);
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < nSphere; ++i) {
      const double zz = 1.0 - (i + 0.5) * 2.0 / nSphere;
      if (zz < capCos)
        break;
      const double r = std::sqrt(std::max(0.0, 1 - zz * zz)), phi = golden * i;
      const Vec3 d{zz * restDir[0] + r * (std::cos(phi) * a[0] + std::sin(phi) * b[0]),
                   zz * restDir[1] + r * (std::cos(phi) * a[1] + std::sin(phi) * b[1]),
                   zz * restDir[2] + r * (std::cos(phi) * a[2] + std::sin(phi) * b[2])};
      if (dot(d, restDir) < 1 - 1e-6)
        dirs.push_back(d);
    }
  }
  const vpCameraParameters &ci = rig.left.cam;
  PhotoModel &M = out.model;
  M.distanceMm = D;
  M.px = ci.get_px(), M.py = ci.get_py(), M.u0 = ci.get_u0(), M.v0 = ci.get_v0();
  M.photoWidth = rig.left.width, M.photoHeight = rig.left.height;
  M.centroidU = M.u0, M.centroidV = M.v0;
  M.backgroundHue = bgHue;
  M.nInDropped = out.nHighlight;
  for (int k = 0; k < 3; ++k)
    M.originInHandMm[k] = 1e3 * mMh0.inverse()[k][3];
  std::vector<float> vz;
  for (std::size_t vi = 0; vi < dirs.size(); ++vi) {
    const Vec3 d = dirs[vi], C{D * d[0], D * d[1], D * d[2]};
    // Look at the origin: z toward it, x across, y down-ish.
    const Vec3 zc = unit({-d[0], -d[1], -d[2]});
    const Vec3 up = std::fabs(zc[1]) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    const Vec3 xc = unit(cross(up, zc)), yc = cross(zc, xc);
    vpHomogeneousMatrix mMc;
    for (int r = 0; r < 3; ++r) {
      mMc[r][0] = xc[r], mMc[r][1] = yc[r], mMc[r][2] = zc[r], mMc[r][3] = C[r] * 1e-3;
    }
    const Pinhole cam(mMc, ci, rig.left.width, rig.left.height);
    depthBuffer(cam, mpts, splat, zbuf);
    // The hull's mask: every surface point splatted, closed.
    cv::Mat mask(cam.h, cam.w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < cam.h; ++y)
      for (int x = 0; x < cam.w; ++x)
        if (std::isfinite(zbuf[static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(x)]))
          mask.at<unsigned char>(y, x) = 255;
    cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
    // S_in: visible points with a hue, one per cell of a grid over the image.
    double area = cv::countNonZero(mask);
    const double step = std::max(1.0, std::sqrt(area / p.nIn));
    struct Pick
    {
      long key;
      double d2;
      std::size_t i;
      float u, v;
    };
    std::vector<Pick> picks;
    for (std::size_t i = 0; i < mpts.size(); ++i) {
      if (!out.surface[i].hasHue)
        continue;
      double u, v, z;
      if (!cam.project(mpts[i], u, v, z))
        continue;
      const int ui = static_cast<int>(std::lround(u)), vv = static_cast<int>(std::lround(v));
      if (ui < 0 || vv < 0 || ui >= cam.w || vv >= cam.h)
        continue;
      if (z > zbuf[static_cast<std::size_t>(vv) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(ui)] + p.visibilityTolMm)
        continue;
      if (dot(unit(sub(C, mpts[i])), mnorm[i]) < 0.2)
        continue;
      const long cx = static_cast<long>(std::floor(u / step)), cy = static_cast<long>(std::floor(v / step));
      const double ddx = u - (static_cast<double>(cx) + 0.5) * step, ddy = v - (static_cast<double>(cy) + 0.5) * step;
      picks.push_back({cy * 100000 + cx + (p.edgeShare > 0 && edge[i] ? kEdgeKey : 0), ddx * ddx + ddy * ddy, i, static_cast<float>(u), static_cast<float>(v)});
    }
    std::sort(picks.begin(), picks.end(), [](const Pick &a, const Pick &b) { return a.key != b.key ? a.key < b.key : a.d2 < b.d2; });
    ModelView view;
    for (int k = 0; k < 3; ++k)
      view.cameraMm[k] = C[k];
    // One point per cell of each kind (on a hue edge, elsewhere); edgeShare of nIn from the edges,
    // the rest elsewhere, each thinned evenly.
    std::vector<ModelPoint> onEdge, plain;
    for (std::size_t j = 0; j < picks.size(); ++j) {
      if (j > 0 && picks[j].key == picks[j - 1].key)
        continue;
      const SurfacePoint &s = out.surface[picks[j].i];
      (picks[j].key >= kEdgeKey ? onEdge : plain).push_back({s.x, s.y, s.z, s.hue, picks[j].u, picks[j].v});
    }
    auto thin = [](std::vector<ModelPoint> &v, std::size_t n) {
      if (v.size() <= n)
        return;
      std::vector<ModelPoint> t;
      const double r = static_cast<double>(v.size()) / static_cast<double>(n);
      for (std::size_t j = 0; j < n; ++j)
        t.push_back(v[static_cast<std::size_t>(static_cast<double>(j) * r)]);
      v.swap(t);
    };
    const std::size_t nEdge = std::min(onEdge.size(), static_cast<std::size_t>(std::lround(p.edgeShare * p.nIn)));
    thin(onEdge, nEdge);
    thin(plain, static_cast<std::size_t>(p.nIn) - onEdge.size());
    view.inner = std::move(onEdge);
    view.inner.insert(view.inner.end(), plain.begin(), plain.end());
    // S_out: along the outline, offset outward, at the outline's depth.
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    double total = 0;
    for (const auto &c : contours)
      total += static_cast<double>(c.size());
    const int perRow = std::max(1, p.nOut / p.stripRows);
    for (const auto &c : contours) {
      const int n = static_cast<int>(c.size());
      if (n < 8)
        continue;
      const int count = std::max(1, static_cast<int>(std::lround(perRow * n / total)));
      for (int j = 0; j < count; ++j) {
        const int a = static_cast<int>(static_cast<long>(j) * n / count);
        const cv::Point P = c[static_cast<std::size_t>(a)], A = c[static_cast<std::size_t>((a + n - 3) % n)],
                        B = c[static_cast<std::size_t>((a + 3) % n)];
        double nx = B.y - A.y, ny = -(B.x - A.x);
        const double nn = std::hypot(nx, ny);
        if (nn <= 0)
          continue;
        nx /= nn, ny /= nn;
        if (cv::pointPolygonTest(c, cv::Point2f(static_cast<float>(P.x + 2 * nx), static_cast<float>(P.y + 2 * ny)), false) > 0)
          nx = -nx, ny = -ny;
        // The outline's depth: the nearest depth under the outline pixel and its neighbours.
        float depth = std::numeric_limits<float>::infinity();
        for (int dv = -2; dv <= 2; ++dv)
          for (int du = -2; du <= 2; ++du) {
            const int x = P.x + du, y = P.y + dv;
            if (x >= 0 && y >= 0 && x < cam.w && y < cam.h)
              depth = std::min(depth, zbuf[static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(x)]);
          }
        if (!std::isfinite(depth))
          continue;
        for (int row = 0; row < p.stripRows; ++row) {
          const double off = p.stripGapPx + (p.stripRows > 1 ? p.stripWidthPx * row / (p.stripRows - 1) : 0.0);
          const double u = P.x + off * nx, v = P.y + off * ny;
          const int ui = static_cast<int>(std::lround(u)), vv = static_cast<int>(std::lround(v));
          if (ui >= 0 && vv >= 0 && ui < cam.w && vv < cam.h && mask.at<unsigned char>(vv, ui))
            continue; // in a concavity, on the target
          const double x = (u - cam.u0) / cam.px * depth, y = (v - cam.v0) / cam.py * depth;
          const Vec3 w{xc[0] * x + yc[0] * y + zc[0] * depth + C[0], xc[1] * x + yc[1] * y + zc[1] * depth + C[1],
                       xc[2] * x + yc[2] * y + zc[2] * depth + C[2]};
          view.outer.push_back({static_cast<float>(w[0]), static_cast<float>(w[1]), static_cast<float>(w[2]), bgHue,
                                static_cast<float>(u), static_cast<float>(v)});
        }
      }
    }
    if (view.inner.size() < 8 || view.outer.size() < 8) {
      if (vi == 0)
        throw Error("all-around model: from the first view's direction fewer than 8 points with a hue are seen (" +
                    std::to_string(view.inner.size()) + "): the target's colours are too close to the background's");
      continue; // a direction from which too little is seen: its neighbours serve it
    }
    if (vi == 0) {
      M.inner = std::move(view.inner);
      M.outer = std::move(view.outer);
      for (int k = 0; k < 3; ++k)
        M.cameraMm[k] = view.cameraMm[k];
      std::vector<float> hs;
      for (const ModelPoint &q : M.inner) {
        hs.push_back(q.hue);
        vz.push_back(static_cast<float>(mMh0.inverse()[2][0] * q.x + mMh0.inverse()[2][1] * q.y + mMh0.inverse()[2][2] * q.z +
                                        1e3 * mMh0.inverse()[2][3]));
      }
      M.targetHue = circularMeanHue(hs);
    } else
      M.views.push_back(std::move(view));
  }
  if (!vz.empty()) {
    M.depthRangeMm[0] = *std::min_element(vz.begin(), vz.end());
    M.depthRangeMm[1] = *std::max_element(vz.begin(), vz.end());
  }
  M.validate("the all-around model");
  out.buildS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

vpImage<vpRGBa> drawSurface(const std::vector<SurfacePoint> &surface, const vpHomogeneousMatrix &mMc,
                            const vpCameraParameters &cam, unsigned w, unsigned h, vpImage<unsigned char> *mask)
{
  const Pinhole pin(mMc, cam, w, h);
  vpImage<vpRGBa> out(h, w, vpRGBa(0, 0, 0));
  std::vector<float> zbuf(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity());
  for (const SurfacePoint &s : surface) {
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

} // namespace pm
