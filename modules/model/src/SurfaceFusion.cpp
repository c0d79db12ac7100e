#include "pm/model/SurfaceFusion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/core/Rounding.h"
#include "pm/model/StereoDepth.h"

namespace pm::model {

using hull::Vec3;

void FusionParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("all-around model's surface fusion: ") + what);
  };
  check(truncationMm > 0 && truncationMm <= 100, "the truncation must lie in (0, 100] mm");
  check(backdropMarginMm >= 0 && backdropMarginMm <= 100, "the backdrop margin must lie in [0, 100] mm");
  check(blockPx >= 1 && blockPx <= 21 && blockPx % 2 == 1, "the block must be odd, in [1, 21] px");
  check(maxDisparitySpreadPx > 0 && maxDisparitySpreadPx <= 50, "the disparity spread must lie in (0, 50] px");
  check(erodePx >= 0 && erodePx <= 50, "the erosion must lie in [0, 50] px");
  check(minTexture >= 0 && minTexture <= 255 && uniquenessPercent >= 0 && uniquenessPercent <= 100,
        "the least texture must lie in [0, 255] and the uniqueness in [0, 100] %");
  check(grazingCos >= 0 && grazingCos < 1, "the grazing cosine must lie in [0, 1)");
  check(outlineMarginPx > 0 && outlineMarginPx <= 100, "the outline margin must lie in (0, 100] px");
  check(edgeRampPx > 0 && edgeRampPx <= 200, "the edge ramp must lie in (0, 200] px");
  check(backdropSearchMm > 0 && backdropSearchMm <= 5000, "the backdrop's search must lie in (0, 5000] mm");
}

namespace {

//! The depth at (u, v): bilinear over the four pixels around when all are measured, else the nearest if measured; NaN otherwise.
double depthAt(const cv::Mat &z, double u, double v)
{
  const int x = static_cast<int>(std::floor(u)), y = static_cast<int>(std::floor(v));
  if (x < 0 || y < 0 || x + 1 >= z.cols || y + 1 >= z.rows)
    return std::numeric_limits<double>::quiet_NaN();
  const float a = z.at<float>(y, x), b = z.at<float>(y, x + 1), c = z.at<float>(y + 1, x), d = z.at<float>(y + 1, x + 1);
  const double fu = u - x, fv = v - y;
  if (std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d))
    return (1 - fv) * ((1 - fu) * a + fu * b) + fv * ((1 - fu) * c + fu * d);
  const float n = z.at<float>(fv < 0.5 ? y : y + 1, fu < 0.5 ? x : x + 1);
  return std::isfinite(n) ? n : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

double DepthEvidence::field(const Vec3 &X) const
{
  const double T = params.truncationMm;
  double sum = 0, w = 0, behind1 = std::numeric_limits<double>::infinity(), behind2 = behind1;
  for (const View &v : views) {
    double u, vv, z;
    if (!v.cam.project(X, u, vv, z))
      continue;
    const double d = depthAt(v.target, u, vv);
    if (std::isfinite(d)) {
      const double sdf = d - z; // > 0: X in front of the measured surface
      // Near its silhouette's edge a view sees the surface at a grazing angle, where the matcher's
      // blocks straddle a steep slope: its word counts less, and nothing at the edge itself.
      const int x = static_cast<int>(core::roundHalfAway(u)), y = static_cast<int>(core::roundHalfAway(vv));
      const double edge = x >= 0 && y >= 0 && x < v.silhouette.cols && y < v.silhouette.rows ? v.silhouette.at<float>(y, x) : 0.0;
      const double wv = std::clamp((edge - params.erodePx) / params.edgeRampPx, 0.0, 1.0) * v.weight.at<float>(y, x);
      if (wv > 0) {
        sum += wv * std::clamp(sdf, -T, T);
        w += wv;
      }
    }
    if (!v.backdrop.empty()) {
      const double b = depthAt(v.backdrop, u, vv);
      if (std::isfinite(b)) {
        const double inFront = b + params.backdropMarginMm - z; // < 0: behind the backdrop
        if (inFront < behind1)
          behind2 = behind1, behind1 = inFront;
        else if (inFront < behind2)
          behind2 = inFront;
      }
    }
  }
  const double surface = w > 0 ? -sum / w : std::numeric_limits<double>::infinity();
  return std::min(surface, behind2);
}

long DepthEvidence::carve(VisualHull &g, const std::vector<const hull::HullView *> &cams) const
{
  long removed = 0;
  for (int z = 0; z < g.n; ++z)
    for (int y = 0; y < g.n; ++y)
      for (int x = 0; x < g.n; ++x) {
        std::uint8_t &o = g.occ[g.idx(x, y, z)];
        if (!o)
          continue;
        // fieldInside() never lies below the evidence's own field: a cell the evidence alone keeps
        // is kept without the silhouettes' field (a lookup in every camera).
        const Vec3 X = g.centre(x, y, z);
        const double f = field(X);
        if (!(f < 0))
          continue;
        if (raisedNearOutline(f, hull::field(cams, X)) < 0) {
          o = 0;
          ++removed;
        }
      }
  return removed;
}

DepthEvidence DepthEvidence::only(const std::vector<bool> &used) const
{
  DepthEvidence e;
  e.params = params;
  for (const View &v : views)
    if (v.view >= 0 && static_cast<std::size_t>(v.view) < used.size() && used[static_cast<std::size_t>(v.view)])
      e.views.push_back(v);
  return e;
}

void DepthEvidence::counts(long &target, long &backdrop) const
{
  target = backdrop = 0;
  for (const View &v : views) {
    target += cv::countNonZero(v.target == v.target); // NaN != NaN
    if (!v.backdrop.empty())
      backdrop += cv::countNonZero(v.backdrop == v.backdrop);
  }
}

DepthEvidence measureStereo(const core::StereoRig &rig, const std::vector<hull::HullView> &cams, const std::vector<vpImage<unsigned char>> &masks,
                            const std::vector<vpImage<vpRGBa>> &backgrounds, const std::vector<bool> &used, bool plainBackdrop,
                            const VisualHull &hull, const FusionParams &p)
{
  p.validate();
  DepthEvidence ev;
  ev.params = p;
  const stereo::Rectification rect(rig);
  // The carved hull's occupied box (world, mm).
  Vec3 box[2] = {{1e18, 1e18, 1e18}, {-1e18, -1e18, -1e18}};
  for (int z = 0; z < hull.n; ++z)
    for (int y = 0; y < hull.n; ++y)
      for (int x = 0; x < hull.n; ++x)
        if (hull.occ[hull.idx(x, y, z)])
          for (int k = 0; k < 3; ++k) {
            const Vec3 c = hull.centre(x, y, z);
            box[0][static_cast<std::size_t>(k)] = std::min(box[0][static_cast<std::size_t>(k)], c[static_cast<std::size_t>(k)] - hull.cell);
            box[1][static_cast<std::size_t>(k)] = std::max(box[1][static_cast<std::size_t>(k)], c[static_cast<std::size_t>(k)] + hull.cell);
          }
  stereo::MatchParams mp;
  mp.blockPx = p.blockPx;
  mp.maxDisparitySpreadPx = p.maxDisparitySpreadPx;
  mp.fast = p.fastMatching;
  mp.minTexture = p.minTexture;
  mp.uniquenessPercent = p.uniquenessPercent;
  for (std::size_t i = 0; i + 1 < cams.size(); i += 2) {
    const hull::HullView &L = cams[i], &R = cams[i + 1];
    if (!used[static_cast<std::size_t>(L.view)])
      continue;
    // The depths the carved hull spans in this camera: its occupied box's corners.
    double zNear = 1e18, zFar = -1e18;
    for (int k = 0; k < 8; ++k) {
      const Vec3 X{k & 1 ? box[1][0] : box[0][0], k & 2 ? box[1][1] : box[0][1], k & 4 ? box[1][2] : box[0][2]};
      const Vec3 c = L.cam.toCam(X);
      zNear = std::min(zNear, c[2]), zFar = std::max(zFar, c[2]);
    }
    if (!(zNear > 1))
      continue;
    DepthEvidence::View view;
    view.cam = L.cam;
    view.view = L.view;
    view.silhouette = L.signedDist;
    // The target inside its silhouette, eroded (the edge mixes target and backdrop).
    vpImage<unsigned char> region = masks[i];
    if (p.erodePx > 0) {
      cv::Mat m(static_cast<int>(region.getHeight()), static_cast<int>(region.getWidth()), CV_8U, region.bitmap);
      cv::erode(m, m, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * p.erodePx + 1, 2 * p.erodePx + 1)));
    }
    view.target = stereo::leftDepth(rect, L.photo, R.photo, region, zNear, zFar, mp);
    // Each depth's weight by how squarely the view sees the surface there (the depth map's slope).
    view.weight = cv::Mat(view.target.size(), CV_32F, cv::Scalar(0));
    for (int y = 1; y + 1 < view.target.rows; ++y)
      for (int x = 1; x + 1 < view.target.cols; ++x) {
        const float z0 = view.target.at<float>(y, x), zl = view.target.at<float>(y, x - 1), zr = view.target.at<float>(y, x + 1),
                    zu = view.target.at<float>(y - 1, x), zd = view.target.at<float>(y + 1, x);
        if (!std::isfinite(z0) || !std::isfinite(zl) || !std::isfinite(zr) || !std::isfinite(zu) || !std::isfinite(zd))
          continue;
        const double mmPerPx = z0 / L.cam.px, gx = 0.5 * (zr - zl) / mmPerPx, gy = 0.5 * (zd - zu) / mmPerPx;
        const double cosA = 1.0 / std::sqrt(1.0 + gx * gx + gy * gy);
        view.weight.at<float>(y, x) = static_cast<float>(std::clamp((cosA - p.grazingCos) / (1.0 - p.grazingCos) * 2.0, 0.0, 1.0));
      }
    // The backdrop around and behind the target, from the pair without it.
    if (!plainBackdrop) {
      vpImage<unsigned char> around = masks[i];
      cv::Mat m(static_cast<int>(around.getHeight()), static_cast<int>(around.getWidth()), CV_8U, around.bitmap);
      cv::dilate(m, m, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(61, 61)));
      stereo::MatchParams mb = mp; // the backdrop: every match (a wrong one moves the bound by little, and needs a second view)
      mb.minTexture = 0;
      view.backdrop = stereo::leftDepth(rect, backgrounds[i], backgrounds[i + 1], around, zNear, zFar + p.backdropSearchMm, mb);
    }
    ev.views.push_back(std::move(view));
  }
  return ev;
}

} // namespace pm::model
