#include "pm/lab/SurfaceTruth.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/model/HullGeometry.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/TargetShape.h"

namespace pm::lab {

namespace {

constexpr int kW = 640, kH = 480;

//! cMm of a camera looking at the model's origin from \e C (mm; Pinhole::lookingAtOrigin), metres.
vpHomogeneousMatrix cMmOf(const core::PinholeCamera::Projection &pin)
{
  vpHomogeneousMatrix cMm;
  for (unsigned r = 0; r < 3; ++r) {
    for (unsigned k = 0; k < 3; ++k)
      cMm[r][k] = pin.R[3 * r + k];
    cMm[r][3] = pin.t[r] * 1e-3;
  }
  return cMm;
}

//! The toy drawn by a camera at \e cMo (metres) into \e r: coverage and depth by id 2.
void drawToy(sim::Rasterizer &r, const sim::Mesh &toy, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam, unsigned ss)
{
  r.reset(kW, kH, ss);
  r.clear(0, 0, 0);
  r.draw(toy, cMo, cam, sim::Lighting(), 2);
}

} // namespace

SurfaceTruth checkSurface(const sim::Scene &scene, const model::AllAroundBuild &b, const vpHomogeneousMatrix &oMm, const vpCameraParameters &cam,
                          int stride)
{
  if (b.mesh.triangles.empty())
    throw core::Error("surface check: the build has no mesh");
  SurfaceTruth t;
  t.volumeCm3 = b.surfaceVolumeCm3;
  const sim::Mesh toy = sim::buildTargetMesh(scene.target(), 0.5);
  const vpHomogeneousMatrix mMo = oMm.inverse();
  const model::hull::Vec3 rest{b.model.cameraMm[0], b.model.cameraMm[1], b.model.cameraMm[2]};
  sim::Rasterizer r;
  // The surface from the rest direction and turned about the model's x axis.
  for (std::size_t k = 0; k < t.views.size(); ++k) {
    DepthCheck &d = t.views[k];
    d.turnDeg = 20.0 * static_cast<double>(k);
    const double a = d.turnDeg * M_PI / 180;
    const model::hull::Vec3 C{rest[0], rest[1] * std::cos(a) - rest[2] * std::sin(a), rest[1] * std::sin(a) + rest[2] * std::cos(a)};
    const core::PinholeCamera::Projection pin = core::PinholeCamera::Projection::lookingAtOrigin(C, cam, kW, kH);
    std::vector<float> zb;
    b.mesh.depthMap(pin, zb);
    drawToy(r, toy, cMmOf(pin) * mMo, cam, 2);
    std::vector<double> e;
    for (unsigned y = 0; y < static_cast<unsigned>(kH); ++y)
      for (unsigned x = 0; x < static_cast<unsigned>(kW); ++x) {
        const double truth = r.depthAt(x, y, 2) * 1e3;
        const float z = zb[y * static_cast<unsigned>(kW) + x];
        if (std::isfinite(truth) && std::isfinite(z))
          e.push_back(std::fabs(z - truth));
        else if (std::isfinite(z) && r.coverage(x, y, 2) == 0)
          ++d.modelOnlyPx;
      }
    std::sort(e.begin(), e.end());
    d.pixels = static_cast<long>(e.size());
    if (!e.empty()) {
      d.medianMm = e[e.size() / 2];
      d.p90Mm = e[e.size() * 9 / 10];
    }
  }
  // The outlines of every stride-th viewpoint, against the toy's coverage there.
  std::vector<const double *> centres{b.model.cameraMm};
  std::vector<const std::vector<core::ContourPoint> *> contours{&b.model.contour};
  for (const core::ModelView &v : b.model.views)
    centres.push_back(v.cameraMm), contours.push_back(&v.contour);
  const double bands[5] = {0, 15, 30, 45, 75};
  std::array<double, 4> sum{}, sum2{};
  std::array<long, 4> far{};
  for (std::size_t v = 0; v < centres.size(); v += static_cast<std::size_t>(std::max(1, stride))) {
    const model::hull::Vec3 C{centres[v][0], centres[v][1], centres[v][2]};
    const double ang = std::acos(std::clamp(model::hull::dot(model::hull::unit(C), model::hull::unit(rest)), -1.0, 1.0)) * 180 / M_PI;
    std::size_t band = 0;
    while (band < 3 && ang >= bands[band + 1])
      ++band;
    const core::PinholeCamera::Projection pin = core::PinholeCamera::Projection::lookingAtOrigin(C, cam, kW, kH);
    drawToy(r, toy, cMmOf(pin) * mMo, cam, 4);
    auto cov = [&](double u, double vv) {
      const int x = static_cast<int>(std::floor(u)), y = static_cast<int>(std::floor(vv));
      if (x < 0 || y < 0 || x >= kW - 1 || y >= kH - 1)
        return 0.0;
      const double fu = u - x, fv = vv - y;
      auto c = [&](int xx, int yy) { return r.coverage(static_cast<unsigned>(xx), static_cast<unsigned>(yy), 2); };
      return (1 - fv) * ((1 - fu) * c(x, y) + fu * c(x + 1, y)) + fv * ((1 - fu) * c(x, y + 1) + fu * c(x + 1, y + 1));
    };
    for (const core::ContourPoint &p : *contours[v]) {
      double u, vv, z;
      if (!pin.project({p.x, p.y, p.z}, u, vv, z))
        continue;
      const model::hull::Vec3 Xc = pin.toCam({p.x, p.y, p.z}), Nc = pin.toCam({p.x + p.nx, p.y + p.ny, p.z + p.nz});
      double nu = Nc[0] - Xc[0], nv = Nc[1] - Xc[1];
      const double nn = std::hypot(nu, nv);
      if (!(nn > 0))
        continue;
      nu /= nn, nv /= nn;
      double best = 1e9;
      // Each step's far end is the next step's near end (s + 0.02 is the next s, to the bit): read once.
      double a1 = cov(u - 8 * nu, vv - 8 * nv);
      for (double s = -8; s <= 8; s += 0.02) {
        const double a2 = cov(u + (s + 0.02) * nu, vv + (s + 0.02) * nv);
        if (a1 >= 0.5 && a2 < 0.5) {
          const double at = s + 0.02 * (a1 - 0.5) / (a1 - a2);
          if (std::fabs(at) < std::fabs(best))
            best = at;
        }
        a1 = a2;
      }
      OutlineCheck &o = t.outlines[band];
      ++o.points;
      if (best > 1e8) {
        ++far[band];
        continue;
      }
      sum[band] += -best; // the toy's outline at 'best' along the normal: the model lies -best outside it
      sum2[band] += best * best;
    }
  }
  for (std::size_t k = 0; k < 4; ++k) {
    OutlineCheck &o = t.outlines[k];
    o.fromDeg = bands[k], o.toDeg = bands[k + 1];
    const long near = o.points - far[k];
    o.meanPx = near > 0 ? sum[k] / static_cast<double>(near) : 0.0;
    o.rmsPx = near > 0 ? std::sqrt(sum2[k] / static_cast<double>(near)) : 0.0;
    o.farShare = o.points > 0 ? static_cast<double>(far[k]) / static_cast<double>(o.points) : 0.0;
  }
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << "  against the toy: surface depth error (median / p90)";
  for (const DepthCheck &d : t.views)
    s << " " << d.medianMm << " / " << d.p90Mm << " mm at " << std::setprecision(0) << d.turnDeg << std::setprecision(2) << " deg;";
  s << "\n  outlines (mean / rms px, points over 8 px)";
  for (const OutlineCheck &o : t.outlines)
    s << " " << std::setprecision(0) << o.fromDeg << "-" << o.toDeg << " deg: " << std::setprecision(2) << o.meanPx << " / " << o.rmsPx
      << " (" << std::setprecision(1) << 100 * o.farShare << " %);";
  s << "\n";
  t.text = s.str();
  return t;
}

std::string surfaceTruthJson(const SurfaceTruth &t)
{
  nlohmann::json depth = nlohmann::json::array(), outlines = nlohmann::json::array();
  for (const DepthCheck &d : t.views)
    depth.push_back({{"turn_deg", d.turnDeg}, {"median_mm", d.medianMm}, {"p90_mm", d.p90Mm}, {"model_only_px", d.modelOnlyPx}, {"pixels", d.pixels}});
  for (const OutlineCheck &o : t.outlines)
    outlines.push_back({{"from_deg", o.fromDeg}, {"to_deg", o.toDeg}, {"mean_px", o.meanPx}, {"rms_px", o.rmsPx}, {"far_share", o.farShare},
                        {"points", o.points}});
  return nlohmann::json{{"surface_depth_error", depth}, {"outline_error", outlines}, {"surface_volume_cm3", t.volumeCm3}}.dump();
}

} // namespace pm::lab
