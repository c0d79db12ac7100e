#include "pm/calib/RigCalibration.h"

#include <cmath>
#include <sstream>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>

#include "pm/core/Error.h"

namespace pm::calib {

namespace {

std::vector<cv::Point2f> toCv(const std::vector<vpImagePoint> &p)
{
  std::vector<cv::Point2f> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    out[i] = cv::Point2f(static_cast<float>(p[i].get_u()), static_cast<float>(p[i].get_v()));
  return out;
}

cv::Mat grey(const vpImage<vpRGBa> &I, vpImage<unsigned char> &store)
{
  vpImageConvert::convert(I, store);
  return cv::Mat(static_cast<int>(store.getHeight()), static_cast<int>(store.getWidth()), CV_8UC1, store.bitmap);
}

vpCameraParameters vispCamera(const cv::Mat &K)
{
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(K.at<double>(0, 0), K.at<double>(1, 1), K.at<double>(0, 2), K.at<double>(1, 2));
  return cam;
}

template <class F> bool errorFree(F &&f)
{
  try {
    f();
    return true;
  } catch (const Error &) {
    return false;
  }
}

} // namespace

void RigCalibrationParams::validate() const
{
  if (minPairs < 3)
    throw Error("rig calibration: at least 3 pairs are needed (minPairs = " + std::to_string(minPairs) + ")");
  if (!(maxEdgeWidthPx > 0) || !std::isfinite(maxEdgeWidthPx))
    throw Error("rig calibration: the blur limit must be a positive number of pixels");
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

RigCalibration calibrateRig(const std::vector<StereoImagePair> &pairs, const Pattern &board, const RigCalibrationParams &params)
{
  board.validate();
  params.validate();
  if (pairs.empty())
    throw Error("rig calibration: no image pair was given");
  RigCalibration result;
  const unsigned w = pairs.front().left.getWidth(), h = pairs.front().left.getHeight();
  std::vector<std::vector<cv::Point3f>> object, monoObject[2];
  std::vector<std::vector<cv::Point2f>> image[2], monoImage[2];
  std::vector<std::size_t> usedIndex;
  std::vector<int> monoOfStereo[2]; // for each stereo pair, its index among the camera's views
  const auto onBoard = [](const vpPoint &P) {
    return cv::Point3f(static_cast<float>(P.get_oX() * 1e3), static_cast<float>(P.get_oY() * 1e3), 0.f);
  };
  const ChessBoard *chess = dynamic_cast<const ChessBoard *>(&board);
  for (const StereoImagePair &p : pairs) {
    PairReport rep;
    rep.name = p.name;
    const vpImage<vpRGBa> *im[2] = {&p.left, &p.right};
    std::string why[2];
    PatternDetection det[2];
    for (int k = 0; k < 2; ++k) {
      const char *side = k ? "right" : "left";
      try {
        if (im[k]->getWidth() != w || im[k]->getHeight() != h)
          throw Error(std::string(side) + " image is " + std::to_string(im[k]->getWidth()) + "x" +
                      std::to_string(im[k]->getHeight()) + ", the first pair's are " + std::to_string(w) + "x" + std::to_string(h));
        det[k] = board.detect(*im[k], side);
        if (det[k].pixels.size() < 6)
          throw Error(std::string("only ") + std::to_string(det[k].pixels.size()) + " features in the " + side + " image (6 needed)");
        if (chess) {
          vpImage<unsigned char> g;
          const cv::Scalar sh = cv::estimateChessboardSharpness(grey(*im[k], g), cv::Size(chess->innerCols, chess->innerRows),
                                                                toCv(det[k].pixels));
          rep.edgeWidthPx[k] = sh[0];
          if (!(sh[0] <= params.maxEdgeWidthPx)) {
            std::ostringstream os;
            os.precision(2);
            os << std::fixed << "blurred: the " << side << " board's edges are " << sh[0] << " px wide (limit "
               << params.maxEdgeWidthPx << ")";
            throw Error(os.str());
          }
        }
        rep.usedBy[k] = true;
      } catch (const Error &e) {
        why[k] = e.what();
        det[k] = PatternDetection();
      }
    }
    for (int k = 0; k < 2; ++k)
      if (rep.usedBy[k]) {
        std::vector<cv::Point3f> o;
        for (const vpPoint &P : det[k].points)
          o.push_back(onBoard(P));
        monoObject[k].push_back(o);
        monoImage[k].push_back(toCv(det[k].pixels));
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
        object.push_back(o);
        for (int k = 0; k < 2; ++k) {
          image[k].push_back(toCv(common[k]));
          rep.corners[k] = common[k];
          monoOfStereo[k].push_back(static_cast<int>(monoImage[k].size()) - 1);
        }
        usedIndex.push_back(result.pairs.size());
      } else {
        why[0] = "only " + std::to_string(o.size()) + " features seen by both cameras (6 needed)";
      }
    }
    rep.reason = rep.used ? "" : (!why[0].empty() ? why[0] : why[1]);
    result.pairs.push_back(std::move(rep));
  }
  result.pairsUsed = static_cast<int>(usedIndex.size());
  if (result.pairsUsed < params.minPairs || result.viewsUsed[0] < params.minPairs || result.viewsUsed[1] < params.minPairs) {
    std::ostringstream os;
    os << "rig calibration: " << result.pairsUsed << " usable pair" << (result.pairsUsed == 1 ? "" : "s") << " of "
       << pairs.size() << ", at least " << params.minPairs << " needed";
    for (const PairReport &r : result.pairs)
      if (!r.used)
        os << "\n  " << r.name << ": " << r.reason;
    throw Error(os.str());
  }

  const cv::Size size(static_cast<int>(w), static_cast<int>(h));
  cv::Mat K[2], D[2];
  std::vector<cv::Mat> rvecs[2], tvecs[2];
  double rms[2];
  for (int k = 0; k < 2; ++k) {
    rms[k] = cv::calibrateCamera(monoObject[k], monoImage[k], size, K[k], D[k], rvecs[k], tvecs[k]);
    // Too few views at the image's edges can leave k3 free to bend the lens model back on itself
    // there; the usual remedy is to fix k3 at 0.
    const LensDistortion lens{std::vector<double>(D[k].begin<double>(), D[k].end<double>())};
    if (!errorFree([&] { lens.validate(vispCamera(K[k]), w, h, "camera"); })) {
      rms[k] = cv::calibrateCamera(monoObject[k], monoImage[k], size, K[k], D[k], rvecs[k], tvecs[k], cv::CALIB_FIX_K3);
      result.k3Fixed[k] = true;
    }
  }
  cv::Mat R, T, E, F, perView;
  const double stereoRms = cv::stereoCalibrate(object, image[0], image[1], K[0], D[0], K[1], D[1], size, R, T, E, F,
                                               perView, cv::CALIB_FIX_INTRINSIC);
  result.rmsLeftPx = rms[0];
  result.rmsRightPx = rms[1];
  result.rmsStereoPx = stereoRms;
  result.baselineMm = cv::norm(T);
  cv::Mat rv;
  cv::Rodrigues(R, rv);
  result.rotationDeg = cv::norm(rv) * 180.0 / CV_PI;

  // The right camera in the left one: cRMcL = [R T], so cLMcR is its inverse (metres: the unit / 1000).
  vpHomogeneousMatrix cRMcL;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j)
      cRMcL[i][j] = R.at<double>(static_cast<int>(i), static_cast<int>(j));
    cRMcL[i][3] = T.at<double>(static_cast<int>(i)) * 1e-3;
  }
  const vpHomogeneousMatrix cLMcR = cRMcL.inverse();
  RigCamera *cams[2] = {&result.rig.left, &result.rig.right};
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

  // Per pair: each camera's rms in the stereo calibration and the reprojected corners (the left
  // camera's board pose from calibrateCamera; the right one's through the stereo pose).
  for (std::size_t i = 0; i < usedIndex.size(); ++i) {
    PairReport &rep = result.pairs[usedIndex[i]];
    cv::Mat Rl;
    const std::size_t li = static_cast<std::size_t>(monoOfStereo[0][i]);
    cv::Rodrigues(rvecs[0][li], Rl);
    const cv::Mat Rr = R * Rl, tr = R * tvecs[0][li] + T;
    cv::Mat rvr;
    cv::Rodrigues(Rr, rvr);
    const cv::Mat rv2[2] = {rvecs[0][li], rvr}, tv2[2] = {tvecs[0][li], tr};
    for (int k = 0; k < 2; ++k) {
      std::vector<cv::Point2f> proj;
      cv::projectPoints(object[i], rv2[k], tv2[k], K[k], D[k], proj);
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
