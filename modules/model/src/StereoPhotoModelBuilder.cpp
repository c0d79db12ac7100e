#include "pm/model/StereoPhotoModelBuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/core/UndistortMap.h"
#include "pm/core/Hue.h"
#include "pm/model/StereoDepth.h"

namespace pm::model {

void StereoModelParams::validate() const
{
  photo.validate();
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("stereo photo-model parameter ") + what);
  };
  check(backdropMm >= 0 && std::isfinite(backdropMm), "backdrop distance must be 0 (measured) or positive");
  check(maxReliefMm > 0 && maxReliefMm <= 2000, "maximum relief must lie in (0, 2000] mm");
  check(behindBackdropMm >= 0 && behindBackdropMm <= 1000, "distance behind the backdrop must lie in [0, 1000] mm");
  check(blockPx >= 1 && blockPx <= 21 && blockPx % 2 == 1, "block size must be odd, in [1, 21] px");
  check(uniquenessPercent >= 0 && uniquenessPercent <= 100, "uniqueness must lie in [0, 100] %");
  check(maxDisparitySpreadPx > 0 && maxDisparitySpreadPx <= 50, "disparity spread must lie in (0, 50] px");
  check(silhouetteRadiusPx >= 1 && silhouetteRadiusPx <= 100, "silhouette radius must lie in [1, 100] px");
  check(localRadiusPx >= 1 && localRadiusPx <= 100, "local radius must lie in [1, 100] px");
  check(maxLocalDeviationMm > 0 && std::isfinite(maxLocalDeviationMm), "local deviation must be positive");
  check(minMatchedFraction >= 0 && minMatchedFraction <= 1, "minimum matched fraction must lie in [0, 1]");
  check(maxRegionFraction > 0 && maxRegionFraction <= 1, "maximum region fraction must lie in (0, 1]");
  check(maxBackgroundChange >= 0 && maxBackgroundChange <= 255, "maximum background change must lie in [0, 255]");
}

namespace {

using stereo::Rectification;
using stereo::disparity;
using stereo::sampleDisparity;
using stereo::toBgr;

double median(std::vector<double> v)
{
  if (v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

//! Median of the finite values of \e z within \e radius px of \e p (NaN if none).
double localMedian(const cv::Mat &z, const cv::Point2f &p, double radius)
{
  std::vector<double> v;
  const int r = static_cast<int>(std::ceil(radius)), u0 = static_cast<int>(std::lround(p.x)), v0 = static_cast<int>(std::lround(p.y));
  for (int y = std::max(0, v0 - r); y <= std::min(z.rows - 1, v0 + r); ++y)
    for (int x = std::max(0, u0 - r); x <= std::min(z.cols - 1, u0 + r); ++x)
      if ((x - u0) * (x - u0) + (y - v0) * (y - v0) <= radius * radius && std::isfinite(z.at<float>(y, x)))
        v.push_back(z.at<float>(y, x));
  return median(v);
}

void checkSize(const vpImage<vpRGBa> &im, const core::PinholeCamera &cam, const char *what)
{
  if (im.getWidth() != cam.width || im.getHeight() != cam.height)
    throw core::Error(std::string("stereo photo-model: the ") + what + " is " + std::to_string(im.getWidth()) + "x" +
                std::to_string(im.getHeight()) + " but the rig's " + cam.name + " camera is " +
                std::to_string(cam.width) + "x" + std::to_string(cam.height) +
                " (take the photos with the rig's cameras at their calibrated size)");
}

//! A view's points placed in the hand frame (mm; x, y, z of each ModelPoint), before the origin is chosen.
struct PlacedView
{
  std::vector<core::ModelPoint> inner, outer, dropped;
  int nOutFallback = 0;
};

//! \e p placed in the hand frame (mm) on its pixel's ray of \e cam, at the camera's depth \e z (mm).
core::ModelPoint onRay(const core::PinholeCamera &cam, const core::ModelPoint &p, double z)
{
  const vpCameraParameters &c = cam.cam;
  const double X = (p.u - c.get_u0()) / c.get_px() * z, Y = (p.v - c.get_v0()) / c.get_py() * z;
  float h[3];
  for (unsigned i = 0; i < 3; ++i)
    h[i] = static_cast<float>(cam.hMc[i][0] * X + cam.hMc[i][1] * Y + cam.hMc[i][2] * z + cam.hMc[i][3] * 1e3);
  core::ModelPoint q = p;
  q.x = h[0];
  q.y = h[1];
  q.z = h[2];
  return q;
}

/*!
  Places the S_in and S_out points sampled in one camera's photo, given the camera's depth \e camZ (mm)
  at its region pixels (NaN where unmatched). S_in: at its pixel's depth, dropped when unmatched or off
  the median of the matched pixels around it; S_out: at the depth of the silhouette next to it.
*/
PlacedView placeView(const core::PhotoModel &sampled, const cv::Mat &camZ, const core::PinholeCamera &cam, const StereoModelParams &params,
                     double fallbackZ)
{
  PlacedView pv;
  for (const core::ModelPoint &p : sampled.inner) {
    const int u = static_cast<int>(std::lround(p.u)), v = static_cast<int>(std::lround(p.v));
    const double z = (u >= 0 && v >= 0 && u < camZ.cols && v < camZ.rows) ? camZ.at<float>(v, u) : std::nan("");
    // A match off the relief around it (a wrong match on a thin part or an edge) is no match.
    const double local = std::isfinite(z) ? localMedian(camZ, cv::Point2f(p.u, p.v), params.localRadiusPx) : 0.0;
    if (!std::isfinite(z) || !(std::fabs(z - local) <= params.maxLocalDeviationMm)) {
      pv.dropped.push_back(p);
      continue;
    }
    pv.inner.push_back(onRay(cam, p, z));
  }
  const int w = camZ.cols, h = camZ.rows;
  const int rad = static_cast<int>(std::ceil(params.silhouetteRadiusPx + params.photo.stripGapPx + params.photo.stripWidthPx));
  std::vector<double> outZ, allZ;
  for (const core::ModelPoint &p : sampled.outer) {
    std::vector<double> zs;
    const int u0 = static_cast<int>(std::lround(p.u)), v0 = static_cast<int>(std::lround(p.v));
    for (int v = std::max(0, v0 - rad); v <= std::min(h - 1, v0 + rad); ++v)
      for (int u = std::max(0, u0 - rad); u <= std::min(w - 1, u0 + rad); ++u) {
        const float z = camZ.at<float>(v, u);
        if (std::isfinite(z) && (u - u0) * (u - u0) + (v - v0) * (v - v0) <= rad * rad)
          zs.push_back(z);
      }
    // The silhouette is where the surface turns away from the camera: the farthest of the matched
    // surface next to the point (its 90th percentile, robust to a wrong match).
    double z = std::numeric_limits<double>::quiet_NaN();
    if (!zs.empty()) {
      std::nth_element(zs.begin(), zs.begin() + static_cast<long>(zs.size() * 9 / 10), zs.end());
      z = zs[zs.size() * 9 / 10];
      allZ.push_back(z);
    }
    outZ.push_back(z);
  }
  const double fallback = allZ.empty() ? fallbackZ : median(allZ);
  for (std::size_t i = 0; i < sampled.outer.size(); ++i) {
    const core::ModelPoint &p = sampled.outer[i];
    double z = outZ[i];
    if (!std::isfinite(z)) {
      z = fallback;
      ++pv.nOutFallback;
    }
    pv.outer.push_back(onRay(cam, p, z));
  }
  return pv;
}

//! \e pts moved by -o (hand frame to model frame).
std::vector<core::ModelPoint> shifted(std::vector<core::ModelPoint> pts, const cv::Vec3d &o)
{
  for (core::ModelPoint &p : pts) {
    p.x = static_cast<float>(p.x - o[0]);
    p.y = static_cast<float>(p.y - o[1]);
    p.z = static_cast<float>(p.z - o[2]);
  }
  return pts;
}

/*!
  Camera \e to's depth (mm) at its \e region pixels from camera \e from's depth map: each matched pixel's
  3-D point projected into \e to, splatted on the four pixels around it, the nearest surface kept.
*/
cv::Mat warpedDepth(const cv::Mat &fromZ, const core::PinholeCamera &from, const core::PinholeCamera &to, const vpImage<unsigned char> &region)
{
  cv::Mat z(fromZ.size(), CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  const vpHomogeneousMatrix cMc = to.hMc.inverse() * from.hMc;
  const vpCameraParameters &a = from.cam, &b = to.cam;
  for (int v = 0; v < fromZ.rows; ++v)
    for (int u = 0; u < fromZ.cols; ++u) {
      const double Z = fromZ.at<float>(v, u);
      if (!std::isfinite(Z))
        continue;
      const double X = (u - a.get_u0()) / a.get_px() * Z, Y = (v - a.get_v0()) / a.get_py() * Z;
      double c[3];
      for (unsigned i = 0; i < 3; ++i)
        c[i] = cMc[i][0] * X + cMc[i][1] * Y + cMc[i][2] * Z + cMc[i][3] * 1e3;
      if (!(c[2] > 1))
        continue;
      const double x = b.get_px() * c[0] / c[2] + b.get_u0(), y = b.get_py() * c[1] / c[2] + b.get_v0();
      const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const int xx = x0 + dx, yy = y0 + dy;
          if (xx < 0 || yy < 0 || xx >= z.cols || yy >= z.rows || !region[static_cast<unsigned>(yy)][static_cast<unsigned>(xx)])
            continue;
          float &t = z.at<float>(yy, xx);
          if (!(t <= c[2]))
            t = static_cast<float>(c[2]);
        }
    }
  return z;
}

//! The flat build of one view, with an error that names the view.
PhotoModelBuild viewRegion(const vpImage<vpRGBa> &bg, const vpImage<vpRGBa> &im, const core::PinholeCamera &cam,
                           const StereoModelParams &p)
{
  PhotoModelBuild b;
  try {
    b = buildPhotoModel(bg, im, cam.cam, 500, p.photo);
  } catch (const core::Error &e) {
    throw core::Error("stereo photo-model: the target is not found in the " + cam.name + " view (" + e.what() +
                "); it must be whole in both views");
  }
  const unsigned w = b.region.getWidth(), h = b.region.getHeight();
  std::size_t area = 0, border = 0;
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u)
      if (b.region[v][u]) {
        ++area;
        border += (u == 0 || v == 0 || u + 1 == w || v + 1 == h) ? 1 : 0;
      }
  if (static_cast<double>(area) > p.maxRegionFraction * w * h)
    throw core::Error("stereo photo-model: " + std::to_string(static_cast<int>(100.0 * static_cast<double>(area) / (w * h))) + " % of the " +
                cam.name + " photo differs from its background photo: the background pair does not match the photo "
                "pair (take both pairs from the same hand pose, the backdrop alone first)");
  // Outside the target the photo shows what the background photo shows (up to noise): else the
  // two were not taken from the same pose, or of the same backdrop.
  cv::Mat grown;
  const cv::Mat region(static_cast<int>(h), static_cast<int>(w), CV_8U, b.region.bitmap);
  cv::dilate(region, grown, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(31, 31)));
  std::vector<double> diffs;
  for (unsigned v = 0; v < h; v += 2)
    for (unsigned u = 0; u < w; u += 2)
      if (!grown.at<unsigned char>(static_cast<int>(v), static_cast<int>(u))) {
        const vpRGBa &a = bg[v][u], &c = im[v][u];
        diffs.push_back((std::abs(a.R - c.R) + std::abs(a.G - c.G) + std::abs(a.B - c.B)) / 3.0);
      }
  const double mad = median(diffs);
  if (!(mad <= p.maxBackgroundChange))
    throw core::Error("stereo photo-model: outside the target the " + cam.name + " photo differs from its background photo by " +
                std::to_string(static_cast<int>(std::lround(mad))) + " grey levels (median): the background pair does "
                "not match the photo pair (take both pairs from the same hand pose, the backdrop alone first, under the "
                "same light)");
  if (border > 0)
    throw core::Error("stereo photo-model: the target touches the border of the " + cam.name +
                " view; it must be whole in both views (move the rig back or centre the target)");
  return b;
}

//! The backdrop's depth (rectified left z, mm), matched on the background pair at a quarter of the
//! resolution over a wide range, the median over the target's region \e rRegionL (rectified). Throws pm::core::Error.
double measuredBackdropMm(const Rectification &rect, const vpImage<vpRGBa> &bgL, const vpImage<vpRGBa> &bgR, const cv::Mat &rRegionL,
                          const StereoModelParams &params)
{
  cv::Mat a = rect.remap(toBgr(bgL), 0), b = rect.remap(toBgr(bgR), 1);
  cv::pyrDown(a, a);
  cv::pyrDown(a, a);
  cv::pyrDown(b, b);
  cv::pyrDown(b, b);
  const double dNear = rect.disparityAt(150.0) / 4, dFar = rect.disparityAt(5000.0) / 4;
  const int dMin = static_cast<int>(std::floor(std::min(dNear, dFar))) - 2;
  const int n = std::max(16, ((static_cast<int>(std::ceil(std::fabs(dNear - dFar))) + 4 + 15) / 16) * 16);
  StereoModelParams coarse = params;
  coarse.blockPx = 5;
  const cv::Mat d = disparity(a, b, dMin, n, coarse.blockPx, coarse.uniquenessPercent);
  cv::Mat mask;
  cv::resize(rRegionL, mask, d.size(), 0, 0, cv::INTER_NEAREST);
  cv::dilate(mask, mask, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(9, 9)));
  std::vector<double> ds;
  for (int v = 0; v < d.rows; ++v)
    for (int u = 0; u < d.cols; ++u)
      if (mask.at<unsigned char>(v, u) && std::isfinite(d.at<float>(v, u)))
        ds.push_back(4.0 * d.at<float>(v, u));
  std::size_t maskArea = static_cast<std::size_t>(cv::countNonZero(mask));
  if (ds.size() < 20 || static_cast<double>(ds.size()) < 0.2 * static_cast<double>(maskArea))
    throw core::Error("stereo photo-model: the backdrop behind the target cannot be matched in the background pair (" +
                std::to_string(ds.size()) + " of " + std::to_string(maskArea) +
                " pixels matched; a plain backdrop has no texture): give its distance (--backdrop-mm)");
  const double backdrop = rect.depthAt(median(ds));
  if (!(backdrop > 0) || !std::isfinite(backdrop))
    throw core::Error("stereo photo-model: the backdrop's depth came out invalid; give its distance (--backdrop-mm)");
  return backdrop;
}

/*!
  Dense depth of the left region from the rectified disparities \e disp: the left camera's z (returned,
  NaN elsewhere; for S_out) and the hand's z (\e depthLeft, for depth.png).
*/
cv::Mat leftRegionDepth(const core::StereoRig &rig, const Rectification &rect, const cv::Mat &disp, const vpImage<unsigned char> &region,
                        const StereoModelParams &params, vpImage<float> &depthLeft)
{
  // A left pixel's position in the hand frame (mm) from its rectified disparity.
  const vpHomogeneousMatrix hMcL = rig.left.hMc;
  cv::Matx33d R1t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      R1t(i, j) = rect.R1.at<double>(j, i);
  auto leftCameraPoint = [&](const cv::Point2f &r, double d) {
    const double Z = rect.depthAt(d);
    const cv::Vec3d Xr((r.x - rect.cx1) * Z / rect.f, (r.y - rect.cy) * Z / rect.f, Z);
    return R1t * Xr;
  };
  auto toHand = [&](const cv::Vec3d &c) {
    cv::Vec3d h;
    for (unsigned i = 0; i < 3; ++i)
      h[static_cast<int>(i)] = hMcL[i][0] * c[0] + hMcL[i][1] * c[1] + hMcL[i][2] * c[2] + hMcL[i][3] * 1e3;
    return h;
  };

  const unsigned w = rig.left.width, h = rig.left.height;
  std::vector<cv::Point2f> regionPx;
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u)
      if (region[v][u])
        regionPx.emplace_back(static_cast<float>(u), static_cast<float>(v));
  const std::vector<cv::Point2f> regionRect = rect.rectifiedLeft(regionPx);
  cv::Mat camZ(static_cast<int>(h), static_cast<int>(w), CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  depthLeft.resize(h, w, std::numeric_limits<float>::quiet_NaN());
  for (std::size_t i = 0; i < regionPx.size(); ++i) {
    const float d = sampleDisparity(disp, regionRect[i].x, regionRect[i].y, params.maxDisparitySpreadPx);
    if (!std::isfinite(d))
      continue;
    const cv::Vec3d c = leftCameraPoint(regionRect[i], d);
    const int u = static_cast<int>(regionPx[i].x), v = static_cast<int>(regionPx[i].y);
    camZ.at<float>(v, u) = static_cast<float>(c[2]);
    depthLeft[static_cast<unsigned>(v)][static_cast<unsigned>(u)] = static_cast<float>(toHand(c)[2]);
  }

  return camZ;
}

} // namespace

StereoPhotoModelBuild buildStereoPhotoModel(const core::StereoRig &rig, const vpImage<vpRGBa> &bgL, const vpImage<vpRGBa> &bgR,
                                            const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R,
                                            const StereoModelParams &params)
{
  params.validate();
  rig.validate();
  if (rig.left.width != rig.right.width || rig.left.height != rig.right.height)
    throw core::Error("stereo photo-model: both cameras of the rig must have the same image size");
  checkSize(bgL, rig.left, "left background photo");
  checkSize(bgR, rig.right, "right background photo");
  checkSize(L, rig.left, "left photo");
  checkSize(R, rig.right, "right photo");
  if (!rig.left.distortion.isNone() || !rig.right.distortion.isNone()) {
    // A lens: the four photos undistorted once (bilinear), then built as a pinhole rig's.
    core::StereoRig ideal = rig;
    ideal.left.distortion = ideal.right.distortion = core::LensDistortion();
    const core::UndistortMap mapL(rig.left), mapR(rig.right);
    return buildStereoPhotoModel(ideal, mapL.undistorted(bgL), mapR.undistorted(bgR), mapL.undistorted(L), mapR.undistorted(R), params);
  }

  StereoPhotoModelBuild out;
  PhotoModelBuild left = viewRegion(bgL, L, rig.left, params);
  const PhotoModelBuild right = viewRegion(bgR, R, rig.right, params);
  std::size_t areaL = 0, areaR = 0;
  for (unsigned i = 0; i < left.region.getSize(); ++i) {
    areaL += left.region.bitmap[i] ? 1u : 0u;
    areaR += right.region.bitmap[i] ? 1u : 0u;
  }
  if (static_cast<double>(std::min(areaL, areaR)) < 0.5 * static_cast<double>(std::max(areaL, areaR)))
    throw core::Error("stereo photo-model: the target covers " + std::to_string(areaL) + " px in the left view but " +
                std::to_string(areaR) + " px in the right: it is hidden or cut in one view (both must see it whole)");

  const Rectification rect(rig);
  const cv::Mat regionL(left.region.getHeight(), left.region.getWidth(), CV_8U, left.region.bitmap);
  const cv::Mat rRegionL = rect.remap(regionL, 0, cv::INTER_NEAREST);

  // The backdrop's depth (rectified left z, mm): given, or matched on the background pair at a
  // quarter of the resolution over a wide range, the median over the target's region.
  double backdrop = params.backdropMm;
  out.backdropMeasured = backdrop <= 0;
  if (out.backdropMeasured) {
    backdrop = measuredBackdropMm(rect, bgL, bgR, rRegionL, params);
  }
  out.backdropMm = backdrop;

  // The photo pair at full resolution, disparities bounded by the backdrop.
  const double dFar = rect.disparityAt(backdrop + params.behindBackdropMm);
  const double dNear = rect.disparityAt(std::max(50.0, backdrop - params.maxReliefMm));
  const int dMin = static_cast<int>(std::floor(std::min(dFar, dNear)));
  const int n = std::max(16, ((static_cast<int>(std::ceil(std::fabs(dNear - dFar))) + 15) / 16) * 16);
  const cv::Mat disp = disparity(rect.remap(toBgr(L), 0), rect.remap(toBgr(R), 1), dMin, n, params.blockPx, params.uniquenessPercent);

  // Dense depth of the left region.
  const cv::Mat camZ = leftRegionDepth(rig, rect, disp, left.region, params, out.depthLeft);

  // S_in and S_out of the left view placed on their rays.
  core::PhotoModel &m = out.model;
  m = left.model;
  PlacedView pl = placeView(left.model, camZ, rig.left, params, backdrop);
  const std::size_t nSampled = left.model.inner.size();
  m.nInDropped = static_cast<int>(nSampled - pl.inner.size());
  out.dropped = pl.dropped;
  out.nOutFallback = pl.nOutFallback;
  const double matched = nSampled == 0 ? 0.0 : static_cast<double>(pl.inner.size()) / static_cast<double>(nSampled);
  if (pl.inner.empty() || matched < params.minMatchedFraction)
    throw core::Error("stereo photo-model: too little texture to match the two views: " + std::to_string(pl.inner.size()) +
                " of " + std::to_string(nSampled) + " S_in points matched (at least " +
                std::to_string(static_cast<int>(100 * params.minMatchedFraction)) +
                " % needed); refused rather than guessed: use the flat model (one photo pair, --background --photo --distance-mm) if you know the "
                "target's distance");

  // The model frame: origin at the 3-D centroid of S_in, axes of the hand frame.
  cv::Vec3d o(0, 0, 0);
  for (const core::ModelPoint &p : pl.inner)
    o += cv::Vec3d(p.x, p.y, p.z);
  o *= 1.0 / static_cast<double>(pl.inner.size());
  double zNear = 1e300, zFar = -1e300;
  for (const core::ModelPoint &p : pl.inner) {
    zNear = std::min(zNear, static_cast<double>(p.z));
    zFar = std::max(zFar, static_cast<double>(p.z));
  }
  std::vector<float> inHues;
  for (const core::ModelPoint &p : pl.inner)
    inHues.push_back(p.hue);
  m.inner = shifted(pl.inner, o);
  m.outer = shifted(pl.outer, o);
  m.targetHue = core::circularMeanHue(inHues);
  m.distanceMm = o[2];
  for (int i = 0; i < 3; ++i) {
    m.originInHandMm[i] = o[i];
    m.cameraMm[i] = rig.left.hMc[static_cast<unsigned>(i)][3] * 1e3 - o[i];
  }
  m.depthRangeMm[0] = zNear;
  m.depthRangeMm[1] = zFar;

  // The right camera's own view: its S_in and S_out sampled in its photo, placed at the depths the
  // left view's matches give where they land in the right image (the nearest surface wins).
  if (params.rightView) {
    const cv::Mat camZR = warpedDepth(camZ, rig.left, rig.right, right.region);
    PlacedView pr = placeView(right.model, camZR, rig.right, params, backdrop);
    if (!pr.inner.empty()) {
      core::ModelView v;
      v.inner = shifted(pr.inner, o);
      v.outer = shifted(pr.outer, o);
      for (int i = 0; i < 3; ++i)
        v.cameraMm[i] = rig.right.hMc[static_cast<unsigned>(i)][3] * 1e3 - o[i];
      m.views.push_back(std::move(v));
    }
  }
  m.validate("(stereo build)");
  out.hMm = vpHomogeneousMatrix(o[0] * 1e-3, o[1] * 1e-3, o[2] * 1e-3, 0, 0, 0);
  out.regionLeft = left.region;
  out.regionRight = right.region;
  return out;
}

StereoPhotoModelBuild buildStereoPhotoModel(const core::StereoRig &rig, const vpImage<vpRGBa> &bgL, const vpImage<vpRGBa> &bgR,
                                            const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R,
                                            const std::vector<StereoViewPair> &more, const StereoModelParams &params)
{
  StereoPhotoModelBuild out = buildStereoPhotoModel(rig, bgL, bgR, L, R, params);
  core::PhotoModel &m = out.model;
  for (std::size_t k = 0; k < more.size(); ++k) {
    const StereoViewPair &pair = more[k];
    StereoPhotoModelBuild b;
    try {
      b = buildStereoPhotoModel(rig, pair.backgroundLeft, pair.backgroundRight, pair.left, pair.right, params);
    } catch (const core::Error &e) {
      throw core::Error("view pair " + std::to_string(k + 2) + ": " + e.what());
    }
    // Model frame of pair k (origin ok, hand axes) -> its hand frame -> the first pair's hand frame -> the model frame.
    const vpHomogeneousMatrix h0Mh = pair.hMh0.inverse();
    const core::PhotoModel &mk = b.model;
    auto move = [&](const double p[3], double q[3]) {
      double hk[3];
      for (int i = 0; i < 3; ++i)
        hk[i] = (p[i] + mk.originInHandMm[i]) * 1e-3;
      for (unsigned i = 0; i < 3; ++i)
        q[i] = 1e3 * (h0Mh[i][0] * hk[0] + h0Mh[i][1] * hk[1] + h0Mh[i][2] * hk[2] + h0Mh[i][3]) - m.originInHandMm[i];
    };
    auto movePoints = [&](std::vector<core::ModelPoint> pts) {
      for (core::ModelPoint &pt : pts) {
        const double a[3] = {pt.x, pt.y, pt.z};
        double q[3];
        move(a, q);
        pt.x = static_cast<float>(q[0]);
        pt.y = static_cast<float>(q[1]);
        pt.z = static_cast<float>(q[2]);
      }
      return pts;
    };
    core::ModelView own;
    move(mk.cameraMm, own.cameraMm);
    own.inner = movePoints(mk.inner);
    own.outer = movePoints(mk.outer);
    m.views.push_back(std::move(own));
    for (const core::ModelView &v : mk.views) {
      core::ModelView mv;
      move(v.cameraMm, mv.cameraMm);
      mv.inner = movePoints(v.inner);
      mv.outer = movePoints(v.outer);
      m.views.push_back(std::move(mv));
    }
  }
  m.validate("(stereo build)");
  return out;
}

} // namespace pm::model
