#include "pm/lab/SilhouetteTruth.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/TargetShape.h"

namespace pm::lab {

SilhouetteTruth checkSilhouettes(const sim::Scene &scene, const std::vector<model::PassView> &pass, const vpHomogeneousMatrix &fMo,
                                 const model::AllAroundBuild &build, const core::StereoRig &rig)
{
  if (build.silhouettes.size() != 2 * pass.size())
    throw core::Error("silhouette check: the build holds no silhouettes for this pass");
  const sim::Mesh toy = sim::buildTargetMesh(scene.target(), 0.5);
  sim::Rasterizer r;
  std::vector<double> signedPx, outside;
  long toyPx = 0, added = 0, missed = 0;
  for (std::size_t k = 0; k < pass.size(); ++k)
    for (int c = 0; c < 2; ++c) {
      const core::PinholeCamera &cam = c == 0 ? rig.left : rig.right;
      const vpImage<unsigned char> &s = build.silhouettes[2 * k + static_cast<std::size_t>(c)];
      const int w = static_cast<int>(cam.width), h = static_cast<int>(cam.height);
      if (static_cast<int>(s.getWidth()) != w || static_cast<int>(s.getHeight()) != h)
        throw core::Error("silhouette check: a silhouette is not of its camera's size");
      r.reset(cam.width, cam.height, 2);
      r.clear(0, 0, 0);
      r.draw(toy, cam.cMh() * pass[k].fMh.inverse() * fMo, cam.cam, sim::Lighting(), 2);
      cv::Mat truth(h, w, CV_8U), est(h, w, CV_8U);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          truth.at<unsigned char>(y, x) = r.coverage(static_cast<unsigned>(x), static_cast<unsigned>(y), 2) >= 0.5 ? 255 : 0;
          est.at<unsigned char>(y, x) = s[static_cast<unsigned>(y)][static_cast<unsigned>(x)] ? 255 : 0;
        }
      // Distances to the toy's outline from either side (px).
      cv::Mat toOutside, toInside, notTruth;
      cv::bitwise_not(truth, notTruth);
      cv::distanceTransform(truth, toOutside, cv::DIST_L2, 3);    // inside the toy: how far to its edge
      cv::distanceTransform(notTruth, toInside, cv::DIST_L2, 3);  // outside: how far to the toy
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const bool t = truth.at<unsigned char>(y, x) != 0, e = est.at<unsigned char>(y, x) != 0;
          toyPx += t;
          added += e && !t;
          missed += t && !e;
          if (!e || x == 0 || y == 0 || x + 1 == w || y + 1 == h)
            continue;
          const bool edge = !est.at<unsigned char>(y, x - 1) || !est.at<unsigned char>(y, x + 1) || !est.at<unsigned char>(y - 1, x) ||
                            !est.at<unsigned char>(y + 1, x);
          if (!edge)
            continue;
          const double d = t ? -(toOutside.at<float>(y, x) - 0.5) : toInside.at<float>(y, x) - 0.5;
          signedPx.push_back(d);
          if (d > 0)
            outside.push_back(d);
        }
    }
  SilhouetteTruth out;
  out.edgePx = static_cast<long>(signedPx.size());
  if (!signedPx.empty()) {
    double s = 0, s2 = 0;
    for (double d : signedPx)
      s += d, s2 += d * d;
    out.meanPx = s / static_cast<double>(signedPx.size());
    out.rmsPx = std::sqrt(s2 / static_cast<double>(signedPx.size()));
  }
  if (!outside.empty()) {
    std::sort(outside.begin(), outside.end());
    out.p95OutsidePx = outside[outside.size() * 95 / 100];
  }
  out.addedShare = toyPx > 0 ? static_cast<double>(added) / static_cast<double>(toyPx) : 0;
  out.missedShare = toyPx > 0 ? static_cast<double>(missed) / static_cast<double>(toyPx) : 0;
  std::ostringstream t;
  t << std::fixed << std::setprecision(2) << "  silhouettes against the toy's outline: edge mean " << out.meanPx << " px, rms " << out.rmsPx
    << " px, 95 % of the edge outside within " << out.p95OutsidePx << " px; " << std::setprecision(1) << 100 * out.addedShare
    << " % of the toy's area added, " << 100 * out.missedShare << " % missed\n";
  out.text = t.str();
  return out;
}

} // namespace pm::lab
