#include "TrueOutline.h"

#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "pm/sim/Rasterizer.h"
#include "pm/sim/TargetShape.h"

namespace pm::test {

namespace {

using V3 = std::array<double, 3>;
constexpr int kW = 640, kH = 480, kPoints = 200;

V3 unit(const V3 &a)
{
  const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}
V3 cross(const V3 &a, const V3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

//! The toy's outline seen from camera centre \e C (model frame, mm) looking at the model's origin, drawn
//! with \e ras (reset to kW x kH, 4 x 4 samples: one renderer for every view, its 100 MB of buffers made once).
std::vector<core::ContourPoint> trueContour(sim::Rasterizer &ras, const sim::Mesh &toy, const vpHomogeneousMatrix &mMo, const double C[3],
                                            const vpCameraParameters &cam)
{
  const V3 zc = unit({-C[0], -C[1], -C[2]});
  const V3 up = std::fabs(zc[1]) < 0.9 ? V3{0, 1, 0} : V3{1, 0, 0};
  const V3 xc = unit(cross(up, zc)), yc = cross(zc, xc);
  vpHomogeneousMatrix mMc;
  for (unsigned r = 0; r < 3; ++r)
    mMc[r][0] = xc[r], mMc[r][1] = yc[r], mMc[r][2] = zc[r], mMc[r][3] = C[r] * 1e-3;
  ras.clear(0, 0, 0);
  ras.draw(toy, mMc.inverse() * mMo, cam, sim::Lighting(), 2);
  cv::Mat cov(kH, kW, CV_32F), mask(kH, kW, CV_8U);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      cov.at<float>(y, x) = static_cast<float>(ras.coverage(static_cast<unsigned>(x), static_cast<unsigned>(y), 2));
      mask.at<unsigned char>(y, x) = cov.at<float>(y, x) >= 0.5f ? 255 : 0;
    }
  auto bilinear = [&](double u, double v) {
    const int x = static_cast<int>(std::floor(u)), y = static_cast<int>(std::floor(v));
    if (x < 0 || y < 0 || x >= kW - 1 || y >= kH - 1)
      return 0.0;
    const double fu = u - x, fv = v - y;
    return (1 - fv) * ((1 - fu) * cov.at<float>(y, x) + fu * cov.at<float>(y, x + 1)) +
           fv * ((1 - fu) * cov.at<float>(y + 1, x) + fu * cov.at<float>(y + 1, x + 1));
  };
  auto inMask = [&](int x, int y) { return x >= 0 && y >= 0 && x < kW && y < kH && mask.at<unsigned char>(y, x) != 0; };
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  double total = 0;
  for (const auto &c : contours)
    total += static_cast<double>(c.size());
  std::vector<core::ContourPoint> out;
  for (const auto &c : contours) {
    const int n = static_cast<int>(c.size());
    if (n < 8)
      continue;
    const int count = std::max(1, static_cast<int>(std::lround(kPoints * n / total)));
    for (int j = 0; j < count; ++j) {
      const int a = static_cast<int>(static_cast<long>(j) * n / count);
      const cv::Point P = c[static_cast<std::size_t>(a)], A = c[static_cast<std::size_t>((a + n - 3) % n)],
                      B = c[static_cast<std::size_t>((a + 3) % n)];
      double nu = B.y - A.y, nv = -(B.x - A.x);
      const double nn = std::hypot(nu, nv);
      if (!(nn > 0))
        continue;
      nu /= nn, nv /= nn;
      if (cv::pointPolygonTest(c, cv::Point2f(static_cast<float>(P.x + 2 * nu), static_cast<float>(P.y + 2 * nv)), false) > 0)
        nu = -nu, nv = -nv; // outward
      double at = 1e9; // where the coverage crosses one half along the normal, nearest P
      for (double t = -2.5; t <= 2.5; t += 0.02) {
        const double a1 = bilinear(P.x + t * nu, P.y + t * nv), a2 = bilinear(P.x + (t + 0.02) * nu, P.y + (t + 0.02) * nv);
        if (a1 >= 0.5 && a2 < 0.5) {
          const double s = t + 0.02 * (a1 - 0.5) / (a1 - a2);
          if (std::fabs(s) < std::fabs(at))
            at = s;
        }
      }
      double depth = NAN;
      for (int k = 1; k < 8 && !std::isfinite(depth); ++k)
        depth = ras.depthAt(static_cast<unsigned>(std::clamp<long>(std::lround(P.x - k * nu), 0, kW - 1)),
                            static_cast<unsigned>(std::clamp<long>(std::lround(P.y - k * nv), 0, kH - 1)), 2);
      if (at > 1e8 || !std::isfinite(depth))
        continue;
      depth *= 1e3;
      auto run = [&](double sign, bool wantIn) {
        int k = 1;
        while (k <= 60 && inMask(static_cast<int>(std::lround(P.x + sign * k * nu)), static_cast<int>(std::lround(P.y + sign * k * nv))) == wantIn)
          ++k;
        return k;
      };
      const double x = (P.x + at * nu - cam.get_u0()) / cam.get_px() * depth, y = (P.y + at * nv - cam.get_v0()) / cam.get_py() * depth;
      core::ContourPoint cp;
      cp.x = static_cast<float>(xc[0] * x + yc[0] * y + zc[0] * depth + C[0]);
      cp.y = static_cast<float>(xc[1] * x + yc[1] * y + zc[1] * depth + C[1]);
      cp.z = static_cast<float>(xc[2] * x + yc[2] * y + zc[2] * depth + C[2]);
      const V3 n3 = unit({xc[0] * nu + yc[0] * nv, xc[1] * nu + yc[1] * nv, xc[2] * nu + yc[2] * nv});
      cp.nx = static_cast<float>(n3[0]), cp.ny = static_cast<float>(n3[1]), cp.nz = static_cast<float>(n3[2]);
      cp.insideMm = static_cast<float>((run(-1, true) - 0.5) * depth / cam.get_px());
      cp.outsideMm = static_cast<float>((run(1, false) - 0.5) * depth / cam.get_px());
      out.push_back(cp);
    }
  }
  return out;
}

} // namespace

void useTrueOutlines(core::PhotoModel &model, const sim::Scene &scene, const vpHomogeneousMatrix &oMm, const vpCameraParameters &cam,
                     double withinDeg)
{
  const sim::Mesh toy = sim::buildTargetMesh(scene.target(), 0.5);
  const vpHomogeneousMatrix mMo = oMm.inverse();
  const V3 front = unit({model.cameraMm[0], model.cameraMm[1], model.cameraMm[2]});
  sim::Rasterizer ras;
  ras.reset(kW, kH, 4);
  model.contour = trueContour(ras, toy, mMo, model.cameraMm, cam);
  for (core::ModelView &v : model.views) {
    const V3 d = unit({v.cameraMm[0], v.cameraMm[1], v.cameraMm[2]});
    if (d[0] * front[0] + d[1] * front[1] + d[2] * front[2] >= std::cos(withinDeg * M_PI / 180))
      v.contour = trueContour(ras, toy, mMo, v.cameraMm, cam);
  }
}

} // namespace pm::test
