#pragma once
/*!
  \file StereoDepth.h
  Depth from the rig's two cameras, for the model builders: the pair rectified (cv::stereoRectify,
  each view keeping its principal point, so that a toed-in rig's target stays in both images),
  matched by OpenCV's semi-global matcher (cv::StereoSGBM, uniqueness and left-right checks), and
  each pixel of a region of the left (ideal) image given the left camera's depth where its
  neighbouring disparities agree. The stereo photo-model (StereoPhotoModelBuilder.h) and the
  all-around model's surface (SurfaceFusion.h) both measure with it.

  \code
      const pm::model::stereo::Rectification rect(rig);                  // once per rig (pinhole cameras)
      const cv::Mat z = pm::model::stereo::leftDepth(rect, L, R, region, 400, 600, pm::model::stereo::MatchParams());
  \endcode
*/
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/StereoRig.h"

namespace pm::model::stereo {

//! An image as OpenCV's 8-bit BGR.
cv::Mat toBgr(const vpImage<vpRGBa> &im);
//! The intrinsic matrix of \e c.
cv::Matx33d intrinsics(const vpCameraParameters &c);

/*!
  The rectified geometry of the rig (pinhole cameras) and the maps of both views.
  \code
  const pm::model::stereo::Rectification rect(rig);
  const cv::Mat left = rect.remap(pm::model::stereo::toBgr(L), 0);   // the rectified left image
  std::cout << "500 mm lies at a disparity of " << rect.disparityAt(500) << " px\n";
  \endcode
*/
struct Rectification
{
  cv::Matx33d K[2]; //!< the intrinsic matrices of the left and right cameras
  /*! \var Rectification::R1
      \brief the left camera's rectifying rotation (OpenCV's stereoRectify)
      \var Rectification::R2
      \brief the right camera's
      \var Rectification::P1
      \brief the left camera's rectified projection
      \var Rectification::P2
      \brief the right camera's
      \var Rectification::Q
      \brief disparity-to-depth matrix */
  cv::Mat R1, R2, P1, P2, Q, map[2][2]; //!< the remap tables of both views (x, y)
  /*! \var Rectification::f
      \brief the rectified focal length (px)
      \var Rectification::cx1
      \brief the rectified left principal point's column (px)
      \var Rectification::cx2
      \brief the rectified right principal point's column (px)
      \var Rectification::cy
      \brief the rectified principal point's row (px) */
  double f = 0, cx1 = 0, cx2 = 0, cy = 0, Tx = 0; //!< the right camera's x in the rectified left frame (mm)
  cv::Size size; //!< the images' size

  //! The rig's rectification (pinhole cameras of the same size).
  explicit Rectification(const core::StereoRig &rig)
  {
    size = cv::Size(static_cast<int>(rig.left.width), static_cast<int>(rig.left.height));
    K[0] = intrinsics(rig.left.cam);
    K[1] = intrinsics(rig.right.cam);
    const vpHomogeneousMatrix cRMcL = rig.cLMcR().inverse(); // X_R = R X_L + T (OpenCV's convention)
    cv::Matx33d R;
    cv::Vec3d T;
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned j = 0; j < 3; ++j)
        R(static_cast<int>(i), static_cast<int>(j)) = cRMcL[i][j];
      T[static_cast<int>(i)] = cRMcL[i][3] * 1e3;
    }
    const cv::Mat noDistortion = cv::Mat::zeros(1, 5, CV_64F);
    // Each view keeps its own principal point (no CALIB_ZERO_DISPARITY): a toed-in rig's target
    // stays in both rectified images; alpha 0 keeps only valid pixels at the original size.
    cv::stereoRectify(K[0], noDistortion, K[1], noDistortion, size, R, T, R1, R2, P1, P2, Q, 0, 0, size);
    for (int k = 0; k < 2; ++k)
      cv::initUndistortRectifyMap(K[k], noDistortion, k ? R2 : R1, k ? P2 : P1, size, CV_32FC1, map[k][0], map[k][1]);
    f = P1.at<double>(0, 0);
    cx1 = P1.at<double>(0, 2);
    cx2 = P2.at<double>(0, 2);
    cy = P1.at<double>(1, 2);
    Tx = P2.at<double>(0, 3) / P2.at<double>(0, 0);
  }
  //! Image \e im of camera \e k (0 left, 1 right) rectified.
  cv::Mat remap(const cv::Mat &im, int k, int interpolation = cv::INTER_LINEAR) const
  {
    cv::Mat out;
    cv::remap(im, out, map[k][0], map[k][1], interpolation, cv::BORDER_CONSTANT);
    return out;
  }
  //! Disparity (px) of a point at depth Z (mm) along the rectified axis, and back.
  double disparityAt(double Z) const { return -f * Tx / Z + cx1 - cx2; }
  double depthAt(double d) const { return -f * Tx / (d - (cx1 - cx2)); } //!< the depth (mm) of disparity \e d
  //! Where original left pixels land in the rectified left image.
  std::vector<cv::Point2f> rectifiedLeft(const std::vector<cv::Point2f> &pts) const
  {
    std::vector<cv::Point2f> out;
    if (!pts.empty())
      cv::undistortPoints(pts, out, K[0], cv::noArray(), R1, P1);
    return out;
  }
};


/*!
  SGBM disparity (px, float; NaN where invalid) of a rectified pair over [\e dMin, \e dMin + \e n),
  blocks of \e blockPx, OpenCV's uniqueness ratio \e uniquenessPercent; \e fast: three paths instead of
  eight (MODE_SGBM_3WAY, on every core), else MODE_HH.
*/
cv::Mat disparity(const cv::Mat &L, const cv::Mat &R, int dMin, int n, int blockPx, int uniquenessPercent, bool fast = false);
//! Bilinear disparity at (\e x, \e y) when its four neighbours are valid and agree within \e spread px; NaN otherwise.
float sampleDisparity(const cv::Mat &d, float x, float y, double spread);

//! How leftDepth() matches.
struct MatchParams
{
  int blockPx = 5;                   //!< SGBM block size (odd)
  int uniquenessPercent = 5;         //!< SGBM uniqueness ratio
  double maxDisparitySpreadPx = 1.5; //!< a pixel's four neighbouring disparities must agree within this (px)
  bool fast = false;                 //!< three paths (MODE_SGBM_3WAY) instead of eight
  double minTexture = 0;             //!< a pixel whose block's mean horizontal gradient is under this (grey levels per px) is left unmatched (0: all kept)
};

/*!
  The left camera's depth (z, mm; CV_32F, NaN where unmatched) at each pixel of \e region (non-zero)
  of the ideal left image \e L, matched in \e R over depths [\e zNearMm, \e zFarMm] of the
  rectified left camera. Throws pm::core::Error for images of another size than the rectification's.
*/
cv::Mat leftDepth(const Rectification &rect, const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R, const vpImage<unsigned char> &region,
                  double zNearMm, double zFarMm, const MatchParams &params);

} // namespace pm::model::stereo
