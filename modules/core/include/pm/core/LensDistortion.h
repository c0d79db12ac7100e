#pragma once
/*!
  \file LensDistortion.h
  A camera's lens distortion in OpenCV's model (the one cv::calibrateCamera estimates and every
  calibration file of OpenCV or ROS carries): coefficients k1, k2, p1, p2 [, k3 [, k4, k5, k6
  [, s1, s2, s3, s4 [, tauX, tauY]]]] acting on the normalized coordinates of a pinhole camera
  (the intrinsics px, py, u0, v0 of vpCameraParameters). ViSP's own model
  (perspectiveProjWithDistortion, kud) is the case k1 = kud, every other coefficient 0.

  The project works in the \e ideal (pinhole) image of each camera: the fitness reads hue
  planes resampled into it (UndistortMap), the model builders undistort their photos, the
  calibration check undistorts its corners. The raw image is what the camera delivers. With no
  coefficients (or all zero) nothing is resampled: a pinhole rig keeps its results bit for bit.

  \code
      pm::core::LensDistortion d{{-0.27, 0.05, 0.001, 0.0, 0.0}};
      d.validate(cam, 640, 480, "left camera");            // throws if it folds the image
      const vpImagePoint raw = d.distort(cam, ideal);     // where an ideal pixel lands in the raw image
      const vpImagePoint back = d.undistort(cam, raw);    // and back
  \endcode
*/
#include <string>
#include <vector>
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImagePoint.h>

namespace pm::core {

/*!
  A camera's lens distortion in OpenCV's model, acting on the normalized coordinates of the camera's
  pinhole intrinsics (see LensDistortion.h for the model and an example). Pixels are (u, v) in
  vpImagePoint; the default, with no coefficient, is a pinhole camera.
*/
struct LensDistortion
{
  //! OpenCV's order; empty, or 4, 5, 8, 12 or 14 values.
  std::vector<double> coefficients;

  //! True when there is nothing to correct (no coefficient, or all zero).
  bool isNone() const;
  /*!
    Throws pm::core::Error naming \e who when the count is not 4, 5, 8, 12 or 14, a value is not finite,
    or the distortion folds the image of size w x h: the radial map must grow with the radius out
    to the image's farthest corner, or two rays would land on one pixel.
  */
  void validate(const vpCameraParameters &cam, unsigned w, unsigned h, const std::string &who) const;
  //! The raw pixel where the ideal pixel \e ideal of \e cam is seen.
  vpImagePoint distort(const vpCameraParameters &cam, const vpImagePoint &ideal) const;
  //! The ideal pixel of the raw pixel \e raw (OpenCV's iterative undistortPoints, to 1e-9).
  vpImagePoint undistort(const vpCameraParameters &cam, const vpImagePoint &raw) const;
  //! undistort() of many points at once (faster).
  std::vector<vpImagePoint> undistort(const vpCameraParameters &cam, const std::vector<vpImagePoint> &raw) const;
  //! True when ViSP's model (kud = k1) holds this distortion exactly: every coefficient but k1 is 0, or there is none.
  bool isVispModel() const;
  //! "none", or e.g. "k1 -0.27, k2 0.05, p1 0.001, p2 0, k3 0".
  std::string describe() const;
};

} // namespace pm::core
