#include "pm/calib/RigCalibration.h"

#include <cmath>
#include <sstream>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>

#include "CalibrationSteps.h"
#include "pm/calib/CameraCalibration.h"
#include "pm/core/Error.h"

namespace pm::calib {

using detail::onBoard;
using detail::toCv;
using detail::vispCamera;
using detail::calibrateIntrinsics;

void RigCalibrationParams::validate() const
{
  if (minPairs < 3)
    throw core::Error("rig calibration: at least 3 pairs are needed (minPairs = " + std::to_string(minPairs) + ")");
  if (!(maxEdgeWidthPx > 0) || !std::isfinite(maxEdgeWidthPx))
    throw core::Error("rig calibration: the blur limit must be a positive number of pixels");
}

void handFrameOf(const vpHomogeneousMatrix &cLMcR, vpHomogeneousMatrix &hMcL, vpHomogeneousMatrix &hMcR)
{
  vpThetaUVector tu = cLMcR.getThetaUVector();
  vpThetaUVector half(0.5 * tu[0], 0.5 * tu[1], 0.5 * tu[2]);
  const vpRotationMatrix cLRh(half); // the hand's axes in the left camera: halfway to the right camera's
  const vpTranslationVector mid = cLMcR.getTranslationVector() * 0.5;
  const vpHomogeneousMatrix cLMh(mid, cLRh);
  hMcL = cLMh.inverse();
  hMcR = hMcL * cLMcR;
}

namespace {

//! The views the calibration uses: each camera's own (intrinsics) and the pairs both cameras saw (the stereo pose).
struct CalibrationViews
{
  std::vector<std::vector<cv::Point3f>> object;          //!< per stereo pair, the board points both cameras found (mm)
  std::vector<std::vector<cv::Point2f>> image[2];        //!< ... and where each camera saw them
  std::vector<std::vector<cv::Point3f>> monoObject[2];   //!< per camera's own view, the board points it found
  std::vector<std::vector<cv::Point2f>> monoImage[2];    //!< ... and where
  std::vector<std::size_t> usedIndex;                    //!< per stereo pair, its index in RigCalibration::pairs
  std::vector<int> monoOfStereo[2];                      //!< per stereo pair, its index among the camera's own views
};

//! The board in camera \e k's image of \e p (checked for size and blur), or empty with the reason in \e why.
PatternDetection detectInCamera(const StereoImagePair &p, int k, const Pattern &board, const RigCalibrationParams &params, unsigned w,
                                unsigned h, PairReport &rep, std::string &why)
{
  const vpImage<vpRGBa> &im = k ? p.right : p.left;
  try {
    PatternDetection det = detectCalibrationBoard(im, k ? "right" : "left", board, params.maxEdgeWidthPx, w, h, rep.edgeWidthPx[k]);
    rep.usedBy[k] = true;
    return det;
  } catch (const core::Error &e) {
    why = e.what();
    return PatternDetection();
  }
}

//! Pair \e p's views into \e v and its report into \e result.
void addPair(const StereoImagePair &p, const Pattern &board, const RigCalibrationParams &params, unsigned w, unsigned h,
             CalibrationViews &v, RigCalibration &result)
{
  PairReport rep;
  rep.name = p.name;
  std::string why[2];
  PatternDetection det[2];
  for (int k = 0; k < 2; ++k)
    det[k] = detectInCamera(p, k, board, params, w, h, rep, why[k]);
  for (int k = 0; k < 2; ++k)
    if (rep.usedBy[k]) {
      std::vector<cv::Point3f> o;
      for (const vpPoint &P : det[k].points)
        o.push_back(onBoard(P));
      v.monoObject[k].push_back(o);
      v.monoImage[k].push_back(toCv(det[k].pixels));
      result.viewsUsed[k]++;
      rep.corners[k] = det[k].pixels;
    }
  if (rep.usedBy[0] && rep.usedBy[1]) {
    // The features both cameras found (a tag board may be seen in part), in the left camera's order.
    std::vector<cv::Point3f> o;
    std::vector<vpImagePoint> common[2];
    for (std::size_t i = 0; i < det[0].ids.size(); ++i)
      for (std::size_t j = 0; j < det[1].ids.size(); ++j)
        if (det[0].ids[i] == det[1].ids[j]) {
          o.push_back(onBoard(det[0].points[i]));
          common[0].push_back(det[0].pixels[i]);
          common[1].push_back(det[1].pixels[j]);
        }
    if (o.size() >= 6) {
      rep.used = true;
      v.object.push_back(o);
      for (int k = 0; k < 2; ++k) {
        v.image[k].push_back(toCv(common[k]));
        rep.corners[k] = common[k];
        v.monoOfStereo[k].push_back(static_cast<int>(v.monoImage[k].size()) - 1);
      }
      v.usedIndex.push_back(result.pairs.size());
    } else {
      why[0] = "only " + std::to_string(o.size()) + " features seen by both cameras (6 needed)";
    }
  }
  rep.reason = rep.used ? "" : (!why[0].empty() ? why[0] : why[1]);
  result.pairs.push_back(std::move(rep));
}

//! Throws pm::core::Error naming every pair left out when too few pairs or views remain.
void requireEnoughPairs(const RigCalibration &result, std::size_t given, const RigCalibrationParams &params)
{
  if (result.pairsUsed >= params.minPairs && result.viewsUsed[0] >= params.minPairs && result.viewsUsed[1] >= params.minPairs)
    return;
  std::ostringstream os;
  os << "rig calibration: " << result.pairsUsed << " usable pair" << (result.pairsUsed == 1 ? "" : "s") << " of " << given
     << ", at least " << params.minPairs << " needed";
  for (const PairReport &r : result.pairs)
    if (!r.used)
      os << "\n  " << r.name << ": " << r.reason;
  throw core::Error(os.str());
}

//! The rig of the stereo pose cRMcL = [R T] (mm) and the cameras' intrinsics, its hand frame halfway between them.
void setRig(const cv::Mat &R, const cv::Mat &T, const cv::Mat K[2], const cv::Mat D[2], unsigned w, unsigned h, RigCalibration &result)
{
  // The right camera in the left one: cRMcL = [R T], so cLMcR is its inverse (metres: the unit / 1000).
  vpHomogeneousMatrix cRMcL;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j)
      cRMcL[i][j] = R.at<double>(static_cast<int>(i), static_cast<int>(j));
    cRMcL[i][3] = T.at<double>(static_cast<int>(i)) * 1e-3;
  }
  const vpHomogeneousMatrix cLMcR = cRMcL.inverse();
  core::PinholeCamera *cams[2] = {&result.rig.left, &result.rig.right};
  vpHomogeneousMatrix hMc[2];
  handFrameOf(cLMcR, hMc[0], hMc[1]);
  for (int k = 0; k < 2; ++k) {
    cams[k]->name = k ? "right" : "left";
    cams[k]->cam = vispCamera(K[k]);
    cams[k]->distortion.coefficients.assign(D[k].begin<double>(), D[k].end<double>());
    cams[k]->width = w;
    cams[k]->height = h;
    cams[k]->hMc = hMc[k];
  }
  result.rig.validate();
}

/*!
  Per pair: each camera's rms in the stereo calibration and the reprojected corners (the left
  camera's board pose from its own calibration; the right one's through the stereo pose).
*/
void reportPairs(const CalibrationViews &v, const cv::Mat &R, const cv::Mat &T, const cv::Mat K[2], const cv::Mat D[2],
                 const std::vector<cv::Mat> &rvecsLeft, const std::vector<cv::Mat> &tvecsLeft, const cv::Mat &perView, RigCalibration &result)
{
  for (std::size_t i = 0; i < v.usedIndex.size(); ++i) {
    PairReport &rep = result.pairs[v.usedIndex[i]];
    cv::Mat Rl;
    const std::size_t li = static_cast<std::size_t>(v.monoOfStereo[0][i]);
    cv::Rodrigues(rvecsLeft[li], Rl);
    const cv::Mat Rr = R * Rl, tr = R * tvecsLeft[li] + T;
    cv::Mat rvr;
    cv::Rodrigues(Rr, rvr);
    const cv::Mat rv2[2] = {rvecsLeft[li], rvr}, tv2[2] = {tvecsLeft[li], tr};
    for (int k = 0; k < 2; ++k) {
      std::vector<cv::Point2f> proj;
      cv::projectPoints(v.object[i], rv2[k], tv2[k], K[k], D[k], proj);
      double s2 = 0;
      rep.projected[k].resize(proj.size());
      for (std::size_t j = 0; j < proj.size(); ++j) {
        rep.projected[k][j] = vpImagePoint(proj[j].y, proj[j].x);
        const double du = proj[j].x - rep.corners[k][j].get_u(), dv = proj[j].y - rep.corners[k][j].get_v();
        s2 += du * du + dv * dv;
      }
      rep.rmsPx[k] = perView.empty() ? std::sqrt(s2 / static_cast<double>(proj.size())) : perView.at<double>(static_cast<int>(i), k);
    }
  }
}

} // namespace

RigCalibration calibrateRig(const std::vector<StereoImagePair> &pairs, const Pattern &board, const RigCalibrationParams &params)
{
  board.validate();
  params.validate();
  if (pairs.empty())
    throw core::Error("rig calibration: no image pair was given");
  RigCalibration result;
  const unsigned w = pairs.front().left.getWidth(), h = pairs.front().left.getHeight();
  CalibrationViews v;
  for (const StereoImagePair &p : pairs)
    addPair(p, board, params, w, h, v, result);
  result.pairsUsed = static_cast<int>(v.usedIndex.size());
  requireEnoughPairs(result, pairs.size(), params);

  const cv::Size size(static_cast<int>(w), static_cast<int>(h));
  cv::Mat K[2], D[2];
  std::vector<cv::Mat> rvecs[2], tvecs[2];
  result.rmsLeftPx = calibrateIntrinsics(v.monoObject[0], v.monoImage[0], size, K[0], D[0], rvecs[0], tvecs[0], result.k3Fixed[0]);
  result.rmsRightPx = calibrateIntrinsics(v.monoObject[1], v.monoImage[1], size, K[1], D[1], rvecs[1], tvecs[1], result.k3Fixed[1]);
  cv::Mat R, T, E, F, perView;
  result.rmsStereoPx = cv::stereoCalibrate(v.object, v.image[0], v.image[1], K[0], D[0], K[1], D[1], size, R, T, E, F, perView,
                                           cv::CALIB_FIX_INTRINSIC);
  result.baselineMm = cv::norm(T);
  cv::Mat rv;
  cv::Rodrigues(R, rv);
  result.rotationDeg = cv::norm(rv) * 180.0 / CV_PI;
  setRig(R, T, K, D, w, h, result);
  reportPairs(v, R, T, K, D, rvecs[0], tvecs[0], perView, result);
  return result;
}

vpImage<vpRGBa> coverageImage(const RigCalibration &c, double gain)
{
  const unsigned w = c.rig.left.width, h = c.rig.left.height;
  vpImage<vpRGBa> out(h, 2 * w + 8, vpRGBa(40, 40, 40));
  static const vpColor palette[] = {vpColor::green, vpColor::cyan, vpColor::yellow, vpColor::orange, vpColor::purple,
                                    vpColor::lightBlue, vpColor::lightGreen, vpColor::lightRed};
  for (int k = 0; k < 2; ++k) {
    const double du = k ? w + 8.0 : 0.0;
    vpImageDraw::drawRectangle(out, vpRect(du, 0, w - 1, h - 1), vpColor::white, false, 1);
    int n = 0;
    for (const PairReport &p : c.pairs) {
      if (!p.usedBy[k])
        continue;
      const vpColor col = palette[n++ % 8];
      for (std::size_t j = 0; j < p.corners[k].size(); ++j) {
        const vpImagePoint a(p.corners[k][j].get_v(), p.corners[k][j].get_u() + du);
        vpImageDraw::drawCircle(out, a, 2, col, 1);
        if (j < p.projected[k].size()) {
          const vpImagePoint b(a.get_v() + gain * (p.projected[k][j].get_v() - p.corners[k][j].get_v()),
                               a.get_u() + gain * (p.projected[k][j].get_u() - p.corners[k][j].get_u()));
          vpImageDraw::drawLine(out, a, b, vpColor::red, 1);
        }
      }
    }
  }
  return out;
}

} // namespace pm::calib
