#include "pm/core/PhotoModel.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::core {

namespace {
bool finite(float a) { return std::isfinite(a); }

void validatePoints(const std::vector<ModelPoint> &inner, const std::vector<ModelPoint> &outer, const std::string &where)
{
  for (const auto *set : {&inner, &outer}) {
    const char *name = set == &inner ? "S_in" : "S_out";
    for (std::size_t i = 0; i < set->size(); ++i) {
      const ModelPoint &p = (*set)[i];
      if (!finite(p.x) || !finite(p.y) || !finite(p.z) || !finite(p.u) || !finite(p.v))
        throw Error(where + name + " point " + std::to_string(i) + " has a non-finite coordinate");
      if (!(p.hue >= 0.f && p.hue < 360.f))
        throw Error(where + name + " point " + std::to_string(i) + " has hue " + std::to_string(p.hue) +
                    ", outside [0, 360)");
    }
  }
}

void validateContour(const std::vector<ContourPoint> &c, const std::string &where)
{
  for (std::size_t i = 0; i < c.size(); ++i) {
    const ContourPoint &p = c[i];
    if (!finite(p.x) || !finite(p.y) || !finite(p.z) || !finite(p.insideMm) || !finite(p.outsideMm))
      throw Error(where + "contour point " + std::to_string(i) + " has a non-finite coordinate");
    const float n2 = p.nx * p.nx + p.ny * p.ny + p.nz * p.nz;
    if (!(std::fabs(n2 - 1.f) < 1e-2f))
      throw Error(where + "contour point " + std::to_string(i) + " has a normal that is not of unit length");
    if (!(p.insideMm >= 0.f && p.outsideMm >= 0.f))
      throw Error(where + "contour point " + std::to_string(i) + " has a negative line length");
  }
}

//! A camera centre usable as a view direction: finite and at least 1 mm from the model origin.
bool validCamera(const double c[3])
{
  const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  return std::isfinite(n) && n > 1.0;
}
} // namespace

bool PhotoModel::hasContours() const
{
  if (contour.empty())
    return false;
  for (const ModelView &v : views)
    if (v.contour.empty())
      return false;
  return true;
}

bool PhotoModel::hasDepth() const
{
  for (const auto *set : {&inner, &outer})
    for (const ModelPoint &p : *set)
      if (p.z != 0.f)
        return true;
  return false;
}

std::array<double, 6> rmsOffsets(const std::vector<PassLanding> &landings)
{
  std::array<double, 6> r{};
  if (landings.empty())
    return r;
  for (const PassLanding &l : landings)
    for (std::size_t i = 0; i < 3; ++i) {
      r[i] += l.offsetMm[i] * l.offsetMm[i];
      r[3 + i] += l.offsetDeg[i] * l.offsetDeg[i];
    }
  for (double &v : r)
    v = std::sqrt(v / static_cast<double>(landings.size()));
  return r;
}

void PhotoModel::validate(const std::string &source) const
{
  const std::string where = "photo-model " + source + ": ";
  if (!(distanceMm > 0) || !std::isfinite(distanceMm))
    throw Error(where + "distance_mm must be positive, got " + std::to_string(distanceMm));
  if (!(px > 0 && py > 0) || !std::isfinite(px) || !std::isfinite(py))
    throw Error(where + "photo camera focal lengths px, py must be positive");
  if (inner.empty())
    throw Error(where + "S_in is empty: the target could not be told from the background");
  if (!(backgroundHue >= 0.f && backgroundHue < 360.f))
    throw Error(where + "background hue must lie in [0, 360) degrees");
  validatePoints(inner, outer, where);
  validateContour(contour, where);
  const std::size_t bins = static_cast<std::size_t>(kColourBins) * kColourBins * kColourBins;
  for (const std::vector<float> *h : {&foregroundHistogram, &backgroundHistogram}) {
    if (h->empty())
      continue;
    double sum = 0;
    for (float b : *h) {
      if (!(b >= 0.f && b <= 1.f))
        throw Error(where + "a colour histogram holds a bin outside [0, 1]");
      sum += b;
    }
    if (h->size() != bins || !(std::fabs(sum - 1.0) < 1e-3))
      throw Error(where + "a colour histogram must hold " + std::to_string(bins) + " bins summing to 1");
  }
  for (std::size_t k = 0; k < passLandings.size(); ++k) {
    const PassLanding &l = passLandings[k];
    bool ok = validCamera(l.cameraMm);
    for (int i = 0; i < 3; ++i)
      ok = ok && std::fabs(l.offsetMm[i]) <= 50 && std::fabs(l.offsetDeg[i]) <= 45; // false for NaN too
    if (!ok)
      throw Error(where + "pass landing " + std::to_string(k + 1) +
                  ": its camera centre must be finite and at least 1 mm from the origin, its offsets finite and within 50 mm and 45 deg");
  }
  if (views.empty())
    return;
  if (!hasDepth())
    throw Error(where + "a flat model cannot have further views (only a stereo model can)");
  if (!validCamera(cameraMm))
    throw Error(where + "a model with further views needs its camera centre (camera_mm), at least 1 mm from the origin");
  for (std::size_t k = 0; k < views.size(); ++k) {
    const std::string w = where + "view " + std::to_string(k + 1) + ": ";
    if (views[k].inner.empty())
      throw Error(w + "S_in is empty");
    if (!validCamera(views[k].cameraMm))
      throw Error(w + "its camera centre (camera_mm) must be finite and at least 1 mm from the origin");
    validatePoints(views[k].inner, views[k].outer, w);
    validateContour(views[k].contour, w);
  }
}

} // namespace pm::core
