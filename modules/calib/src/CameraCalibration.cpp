#include "pm/calib/CameraCalibration.h"

#include <cmath>
#include <sstream>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpImageDraw.h>

#include "CalibrationSteps.h"
#include "pm/calib/ChessBoard.h"
#include "pm/core/Error.h"

namespace pm::calib {

namespace detail {

std::vector<cv::Point2f> toCv(const std::vector<vpImagePoint> &p)
{
  std::vector<cv::Point2f> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    out[i] = cv::Point2f(static_cast<float>(p[i].get_u()), static_cast<float>(p[i].get_v()));
  return out;
}

cv::Point3f onBoard(const vpPoint &P)
{
  return cv::Point3f(static_cast<float>(P.get_oX() * 1e3), static_cast<float>(P.get_oY() * 1e3), 0.f);
}

vpCameraParameters vispCamera(const cv::Mat &K)
{
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(K.at<double>(0, 0), K.at<double>(1, 1), K.at<double>(0, 2), K.at<double>(1, 2));
  return cam;
}

double calibrateIntrinsics(const std::vector<std::vector<cv::Point3f>> &object, const std::vector<std::vector<cv::Point2f>> &image,
                           const cv::Size &size, cv::Mat &K, cv::Mat &D, std::vector<cv::Mat> &rvecs, std::vector<cv::Mat> &tvecs,
                           bool &k3Fixed)
{
  double rms = cv::calibrateCamera(object, image, size, K, D, rvecs, tvecs);
  // Too few views at the image's edges can leave k3 free to bend the lens model back on itself
  // there; the usual remedy is to fix k3 at 0.
  const core::LensDistortion lens{std::vector<double>(D.begin<double>(), D.end<double>())};
  try {
    lens.validate(vispCamera(K), static_cast<unsigned>(size.width), static_cast<unsigned>(size.height), "camera");
  } catch (const core::Error &) {
    rms = cv::calibrateCamera(object, image, size, K, D, rvecs, tvecs, cv::CALIB_FIX_K3);
    k3Fixed = true;
  }
  return rms;
}

} // namespace detail

void CameraCalibrationParams::validate() const
{
  if (minViews < 3)
    throw core::Error("camera calibration: at least 3 views are needed (minViews = " + std::to_string(minViews) + ")");
  if (!(maxEdgeWidthPx > 0) || !std::isfinite(maxEdgeWidthPx))
    throw core::Error("camera calibration: the blur limit must be a positive number of pixels");
}

PatternDetection detectCalibrationBoard(const vpImage<vpRGBa> &image, const std::string &who, const Pattern &board,
                                        double maxEdgeWidthPx, unsigned w, unsigned h, double &edgeWidthPx)
{
  if (image.getWidth() != w || image.getHeight() != h)
    throw core::Error(who + " image is " + std::to_string(image.getWidth()) + "x" + std::to_string(image.getHeight()) +
                      ", the first one's is " + std::to_string(w) + "x" + std::to_string(h));
  PatternDetection det = board.detect(image, who);
  if (det.pixels.size() < 6)
    throw core::Error("only " + std::to_string(det.pixels.size()) + " features in the " + who + " image (6 needed)");
  if (const ChessBoard *chess = dynamic_cast<const ChessBoard *>(&board)) {
    vpImage<unsigned char> g;
    vpImageConvert::convert(image, g);
    const cv::Mat m(static_cast<int>(g.getHeight()), static_cast<int>(g.getWidth()), CV_8UC1, g.bitmap);
    const cv::Scalar sh = cv::estimateChessboardSharpness(m, cv::Size(chess->innerCols, chess->innerRows), detail::toCv(det.pixels));
    edgeWidthPx = sh[0];
    if (!(sh[0] <= maxEdgeWidthPx)) {
      std::ostringstream os;
      os.precision(2);
      os << std::fixed << "blurred: the " << who << " board's edges are " << sh[0] << " px wide (limit " << maxEdgeWidthPx << ")";
      throw core::Error(os.str());
    }
  }
  return det;
}

namespace {

//! The views' board points and pixels for OpenCV, and each used view's index among them.
struct UsableViews
{
  std::vector<std::vector<cv::Point3f>> object; //!< per used view, the board points found (mm)
  std::vector<std::vector<cv::Point2f>> image;  //!< ... and where
  std::vector<std::size_t> index;               //!< per used view, its index in CameraCalibration::views
};

UsableViews detectAll(const std::vector<CalibrationView> &views, const Pattern &board, const CameraCalibrationParams &params,
                      const std::string &name, CameraCalibration &result)
{
  UsableViews u;
  const unsigned w = views.front().image.getWidth(), h = views.front().image.getHeight();
  for (const CalibrationView &v : views) {
    ViewReport rep;
    rep.name = v.name;
    try {
      const PatternDetection det = detectCalibrationBoard(v.image, name, board, params.maxEdgeWidthPx, w, h, rep.edgeWidthPx);
      std::vector<cv::Point3f> o;
      for (const vpPoint &P : det.points)
        o.push_back(detail::onBoard(P));
      u.object.push_back(o);
      u.image.push_back(detail::toCv(det.pixels));
      u.index.push_back(result.views.size());
      rep.corners = det.pixels;
      rep.used = true;
    } catch (const core::Error &e) {
      rep.reason = e.what();
    }
    result.views.push_back(std::move(rep));
  }
  result.viewsUsed = static_cast<int>(u.index.size());
  if (result.viewsUsed < params.minViews) {
    std::ostringstream os;
    os << "camera calibration: " << result.viewsUsed << " usable view" << (result.viewsUsed == 1 ? "" : "s") << " of "
       << views.size() << ", at least " << params.minViews << " needed";
    for (const ViewReport &r : result.views)
      if (!r.used)
        os << "\n  " << r.name << ": " << r.reason;
    throw core::Error(os.str());
  }
  return u;
}

//! Each used view's board pose (metres), its reprojected corners and its rms.
void reportViews(const UsableViews &u, const cv::Mat &K, const cv::Mat &D, const std::vector<cv::Mat> &rvecs,
                 const std::vector<cv::Mat> &tvecs, CameraCalibration &result)
{
  for (std::size_t i = 0; i < u.index.size(); ++i) {
    ViewReport &rep = result.views[u.index[i]];
    cv::Mat R;
    cv::Rodrigues(rvecs[i], R);
    for (unsigned r = 0; r < 3; ++r) {
      for (unsigned c = 0; c < 3; ++c)
        rep.cMo[r][c] = R.at<double>(static_cast<int>(r), static_cast<int>(c));
      rep.cMo[r][3] = tvecs[i].at<double>(static_cast<int>(r)) * 1e-3;
    }
    std::vector<cv::Point2f> proj;
    cv::projectPoints(u.object[i], rvecs[i], tvecs[i], K, D, proj);
    double s2 = 0;
    rep.projected.resize(proj.size());
    for (std::size_t j = 0; j < proj.size(); ++j) {
      rep.projected[j] = vpImagePoint(proj[j].y, proj[j].x);
      const double du = proj[j].x - u.image[i][j].x, dv = proj[j].y - u.image[i][j].y;
      s2 += du * du + dv * dv;
    }
    rep.rmsPx = std::sqrt(s2 / static_cast<double>(proj.size()));
  }
}

} // namespace

CameraCalibration calibrateCamera(const std::vector<CalibrationView> &views, const Pattern &board, const CameraCalibrationParams &params,
                                  const std::string &name)
{
  board.validate();
  params.validate();
  if (views.empty())
    throw core::Error("camera calibration: no image was given");
  CameraCalibration result;
  const UsableViews u = detectAll(views, board, params, name, result);
  const unsigned w = views.front().image.getWidth(), h = views.front().image.getHeight();
  const cv::Size size(static_cast<int>(w), static_cast<int>(h));
  cv::Mat K, D;
  std::vector<cv::Mat> rvecs, tvecs;
  result.rmsPx = detail::calibrateIntrinsics(u.object, u.image, size, K, D, rvecs, tvecs, result.k3Fixed);
  result.camera.name = name;
  result.camera.cam = detail::vispCamera(K);
  result.camera.distortion.coefficients.assign(D.begin<double>(), D.end<double>());
  result.camera.width = w;
  result.camera.height = h;
  result.camera.validate();
  reportViews(u, K, D, rvecs, tvecs, result);
  return result;
}

vpImage<vpRGBa> coverageImage(const CameraCalibration &c, double gain)
{
  const unsigned w = c.camera.width, h = c.camera.height;
  vpImage<vpRGBa> out(h, w, vpRGBa(40, 40, 40));
  static const vpColor palette[] = {vpColor::green, vpColor::cyan, vpColor::yellow, vpColor::orange, vpColor::purple,
                                    vpColor::lightBlue, vpColor::lightGreen, vpColor::lightRed};
  vpImageDraw::drawRectangle(out, vpRect(0, 0, w - 1, h - 1), vpColor::white, false, 1);
  int n = 0;
  for (const ViewReport &v : c.views) {
    if (!v.used)
      continue;
    const vpColor col = palette[n++ % 8];
    for (std::size_t j = 0; j < v.corners.size(); ++j) {
      const vpImagePoint &a = v.corners[j];
      vpImageDraw::drawCircle(out, a, 2, col, 1);
      if (j < v.projected.size()) {
        const vpImagePoint b(a.get_v() + gain * (v.projected[j].get_v() - a.get_v()), a.get_u() + gain * (v.projected[j].get_u() - a.get_u()));
        vpImageDraw::drawLine(out, a, b, vpColor::red, 1);
      }
    }
  }
  return out;
}

} // namespace pm::calib
