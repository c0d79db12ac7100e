#include "PhotoConsistency.h"

#include <array>
#include <cmath>

namespace pm::model {

namespace {

using hull::HullView;
using hull::Vec3;

//! The 5x5 patch around where \e X projects in \e vc's photo (R, G, B of each pixel), zero-mean and unit-norm; false off the image or flat.
bool patchAt(const HullView &vc, const Vec3 &X, std::array<float, 75> &out)
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

} // namespace

/*!
  Moves each surface point seen by 3 or more cameras inward along its normal, by whole cells up to
  refineDepthMm, to where the mean correlation of each camera's patch with the others' mean is
  highest, when that is clearly better than at the hull (by refineMinGain) and good in itself
  (refineMinScore). Returns the number of points moved.
*/
int refineByPhotoConsistency(const std::vector<const HullView *> &cams, const std::vector<std::vector<std::uint16_t>> &seenBy,
                             const std::vector<Vec3> &normals, const AllAroundParams &p, double cell, std::vector<Vec3> &pts)
{
  const int steps = static_cast<int>(std::floor(p.surface.refineDepthMm / cell));
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
    if (bestStep > 0 && best >= p.surface.refineMinScore && best - atHull >= p.surface.refineMinGain) {
      for (int k = 0; k < 3; ++k)
        moved[i][k] = pts[i][k] - bestStep * cell * normals[i][k];
      ++n;
    }
  }
  pts.swap(moved);
  return n;
}

} // namespace pm::model
