#pragma once
/*!
  \file HullGeometry.h
  The geometry the all-around model's stages share (AllAroundModelBuilder.h): 3-vectors in
  millimetres, a pinhole camera placed in the world (or model) frame, and one camera of one pass view
  as the hull sees it (its ideal photo and its silhouette's signed distance).

      const pm::model::hull::Pinhole cam(wMc, rig.left.cam, 640, 480);   // wMc in metres
      double u, v, z;
      if (cam.project({0, 0, 500}, u, v, z)) std::cout << u << " " << v << "\n";
*/
#include <array>
#include <cmath>

#include <opencv2/core.hpp>
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model::hull {

using Vec3 = std::array<double, 3>; //!< a point or direction (mm)

inline Vec3 sub(const Vec3 &a, const Vec3 &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }   //!< a - b
inline Vec3 add(const Vec3 &a, const Vec3 &b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }   //!< a + b
inline Vec3 scaled(const Vec3 &a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }              //!< s a
inline double dot(const Vec3 &a, const Vec3 &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; } //!< a . b
//! a x b
inline Vec3 cross(const Vec3 &a, const Vec3 &b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
//! a / |a| (z when a is 0)
inline Vec3 unit(const Vec3 &a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec3{a[0] / n, a[1] / n, a[2] / n} : Vec3{0, 0, 1};
}

/*!
  A pinhole camera placed in a frame (the world's or the model's): cMw in mm, intrinsics, size.
*/
struct Pinhole
{
  double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; //!< cMw's rotation, row-major
  double t[3] = {0, 0, 0};                    //!< cMw's translation (mm)
  /*! \var Pinhole::px
      \brief focal length along u (px)
      \var Pinhole::py
      \brief focal length along v (px)
      \var Pinhole::u0
      \brief principal point, column (px) */
  double px = 1, py = 1, u0 = 0, v0 = 0;       //!< principal point, row (px)
  /*! \var Pinhole::w
      \brief image width (px) */
  int w = 0, h = 0;                            //!< image height (px)
  Vec3 centre{0, 0, 0};                        //!< the camera's centre in the frame (mm)

  Pinhole() = default;
  //! The camera at \e wMc (metres) with intrinsics \e cam and size \e width x \e height.
  Pinhole(const vpHomogeneousMatrix &wMc, const vpCameraParameters &cam, unsigned width, unsigned height);
  /*!
    A camera at \e centreMm looking at the frame's origin: z toward it, x across (perpendicular to
    the frame's y axis, or its x axis when looking along y), y down-ish. The viewpoints' cameras.
  */
  static Pinhole lookingAtOrigin(const Vec3 &centreMm, const vpCameraParameters &cam, unsigned width, unsigned height);
  //! Camera-frame position of \e X (mm).
  Vec3 toCam(const Vec3 &X) const
  {
    return {R[0] * X[0] + R[1] * X[1] + R[2] * X[2] + t[0], R[3] * X[0] + R[4] * X[1] + R[5] * X[2] + t[1],
            R[6] * X[0] + R[7] * X[1] + R[8] * X[2] + t[2]};
  }
  //! The image position (\e u, \e v) and depth \e z (mm) of \e X; false behind the camera (z <= 1 mm).
  bool project(const Vec3 &X, double &u, double &v, double &z) const
  {
    const Vec3 c = toCam(X);
    z = c[2];
    if (!(z > 1))
      return false;
    u = px * c[0] / z + u0;
    v = py * c[1] / z + v0;
    return true;
  }
  //! The frame's direction of camera axis \e k (0 x, 1 y, 2 z).
  Vec3 axis(int k) const { return {R[k], R[3 + k], R[6 + k]}; }
  //! The unit ray direction (in the frame) through pixel (\e u, \e v).
  Vec3 ray(double u, double v) const
  {
    const Vec3 d{(u - u0) / px, (v - v0) / py, 1.0};
    return unit({R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2], R[2] * d[0] + R[5] * d[1] + R[8] * d[2]});
  }
  //! The point at depth \e z (mm) on the ray through pixel (\e u, \e v).
  Vec3 backProject(double u, double v, double z) const
  {
    const Vec3 c{(u - u0) / px * z, (v - v0) / py * z, z};
    const Vec3 d = sub(c, {t[0], t[1], t[2]});
    return {R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2], R[2] * d[0] + R[5] * d[1] + R[8] * d[2]};
  }
};

/*!
  One camera of one pass view as the hull sees it: where it was, its ideal photo, and its
  silhouette's signed distance (px; positive inside, the outline midway between the last pixel in and
  the first out).
*/
struct HullCamera
{
  Pinhole cam;            //!< in the world frame of the pass
  vpImage<vpRGBa> photo;  //!< the ideal (undistorted) photo
  cv::Mat signedDist;     //!< CV_32F, the silhouette's signed distance (px)
  int view = 0;           //!< the pass view it belongs to
  //! The signed distance at the pixel nearest (\e u, \e v); -1e6 off the image.
  double sd(double u, double v) const
  {
    const int ui = static_cast<int>(std::lround(u)), vi = static_cast<int>(std::lround(v));
    if (ui < 0 || vi < 0 || ui >= cam.w || vi >= cam.h)
      return -1e6;
    return signedDist.at<float>(vi, ui);
  }
  //! The signed distance interpolated bilinearly at (\e u, \e v); off the image, the border's minus the distance to it.
  double sdSmooth(double u, double v) const;
};

//! The signed distance (CV_32F, px, positive inside) of a binary \e mask (255 inside).
cv::Mat signedDistance(const vpImage<unsigned char> &mask);

} // namespace pm::model::hull
