#pragma once
// The steps calibrateCamera() and calibrateRig() share, in OpenCV's types (private to the module).
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImagePoint.h>
#include <visp3/core/vpPoint.h>

namespace pm::calib::detail {

//! Pixels as OpenCV's points.
std::vector<cv::Point2f> toCv(const std::vector<vpImagePoint> &p);

//! A board point (metres on the board) in mm, OpenCV's object point.
cv::Point3f onBoard(const vpPoint &P);

//! ViSP's camera of OpenCV's K (no distortion).
vpCameraParameters vispCamera(const cv::Mat &K);

/*!
  cv::calibrateCamera on the board points \e object (mm) and where one camera saw them
  (\e image), for an image of \e size: K, the five coefficients D and each view's rvec / tvec. When
  the five-coefficient model folds the image (LensDistortion::validate) it calibrates again with k3
  held at 0 and sets \e k3Fixed. Returns the reprojection rms (px).
*/
double calibrateIntrinsics(const std::vector<std::vector<cv::Point3f>> &object, const std::vector<std::vector<cv::Point2f>> &image,
                           const cv::Size &size, cv::Mat &K, cv::Mat &D, std::vector<cv::Mat> &rvecs, std::vector<cv::Mat> &tvecs,
                           bool &k3Fixed);

} // namespace pm::calib::detail
