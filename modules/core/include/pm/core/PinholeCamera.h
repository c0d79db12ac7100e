#pragma once
/*!
  \file PinholeCamera.h
  The one camera type of the project: a pinhole camera, the intrinsics of its ideal image (ViSP's
  vpCameraParameters: px, py, u0, v0), its image size, its lens (LensDistortion: OpenCV's model; none
  for a pinhole) and its pose. A rig's cameras (StereoRig.h), a camera file's (io::readCameraFile),
  the simulator's and the model builders' are all of this type. Its Projection is the same camera
  placed in a frame, in the form the hot loops read (the fitness kernels, the visual hull, the
  precise stage's lines): its pose as cMf in millimetres and its intrinsics as doubles, with the
  projection of a point of that frame into its ideal image.

  \code
  pm::core::PinholeCamera c;
  c.cam.initPersProjWithoutDistortion(754, 754, 320, 240); // px, py, u0, v0
  c.width = 640;
  c.height = 480;
  c.hMc.buildFrom(0.16, 0, 0, 0, -0.31, 0);                // on the hand: 160 mm to the right, toed in
  c.validate();
  const pm::core::PinholeCamera::Projection p = c.projection(); // placed in the hand frame
  double u, v, z;
  if (p.project({0, 0, 500}, u, v, z))                     // a point 500 mm ahead of the hand
    std::cout << u << " " << v << " at depth " << z << " mm\n";
  \endcode
*/
#include <string>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/LensDistortion.h"
#include "pm/core/Vec3.h"

namespace pm::core {

//! A pinhole camera (see the file's description).
struct PinholeCamera
{
  std::string name;           //!< "left" / "right" on a rig
  vpCameraParameters cam;     //!< intrinsics of the ideal (pinhole) image: px, py, u0, v0
  unsigned width = 0;         //!< image width in pixels
  unsigned height = 0;        //!< image height in pixels
  /*!
    Its pose on the hand (metres): the camera frame in the hand frame H of StereoRig.h, as a rig file
    gives it; the identity for a camera read alone (io::readCameraFile).
  */
  vpHomogeneousMatrix hMc;
  LensDistortion distortion;  //!< the lens (none: a pinhole camera, the raw image is the ideal one)

  //! The hand frame's pose in the camera frame, hMc's inverse (metres).
  vpHomogeneousMatrix cMh() const { return hMc.inverse(); }
  /*!
    Throws core::Error naming the camera and the value if a focal length is not positive, a principal
    point is negative, an intrinsic is not finite, the image size is zero, hMc is not rigid, or the
    lens is invalid (LensDistortion::validate()).
  */
  void validate() const;

  /*!
    The camera placed in a frame F (the hand's, a pass's world, a model's), as the hot loops read it:
    cMf's rotation and translation (mm), the intrinsics, the size. Allocates nothing.
  */
  struct Projection
  {
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; //!< cMf's rotation, row-major
    double t[3] = {0, 0, 0};                    //!< cMf's translation (mm)
    /*! \var Projection::px
        \brief focal length along u (px)
        \var Projection::py
        \brief focal length along v (px)
        \var Projection::u0
        \brief principal point, column (px) */
    double px = 1, py = 1, u0 = 0, v0 = 0;       //!< principal point, row (px)
    /*! \var Projection::w
        \brief image width (px) */
    int w = 0, h = 0;                            //!< image height (px)
    Vec3 centre{0, 0, 0};                        //!< the camera's centre in F (mm)

    Projection() = default;
    //! The camera at \e fMc (metres) in F with intrinsics \e cam and size \e width x \e height.
    Projection(const vpHomogeneousMatrix &fMc, const vpCameraParameters &cam, unsigned width, unsigned height);
    /*!
      A camera at \e centreMm looking at F's origin: z toward it, x across (perpendicular to F's y
      axis, or its x axis when looking along y), y down-ish. The all-around model's viewpoints.
    */
    static Projection lookingAtOrigin(const Vec3 &centreMm, const vpCameraParameters &cam, unsigned width, unsigned height);
    //! Camera-frame position of \e X (mm).
    Vec3 toCam(const Vec3 &X) const
    {
      return {R[0] * X[0] + R[1] * X[1] + R[2] * X[2] + t[0], R[3] * X[0] + R[4] * X[1] + R[5] * X[2] + t[1],
              R[6] * X[0] + R[7] * X[1] + R[8] * X[2] + t[2]};
    }
    //! The ideal image position (\e u, \e v) and depth \e z (mm) of \e X; false behind the camera (z <= 1 mm).
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
    //! F's direction of camera axis \e k (0 x, 1 y, 2 z).
    Vec3 axis(int k) const { return {R[k], R[3 + k], R[6 + k]}; }
    //! The unit ray direction (in F) through ideal pixel (\e u, \e v).
    Vec3 ray(double u, double v) const
    {
      const Vec3 d{(u - u0) / px, (v - v0) / py, 1.0};
      return unit({R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2], R[2] * d[0] + R[5] * d[1] + R[8] * d[2]});
    }
    //! The point (in F) at depth \e z (mm) on the ray through ideal pixel (\e u, \e v).
    Vec3 backProject(double u, double v, double z) const
    {
      const Vec3 c{(u - u0) / px * z, (v - v0) / py * z, z};
      const Vec3 d = sub(c, {t[0], t[1], t[2]});
      return {R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2], R[2] * d[0] + R[5] * d[1] + R[8] * d[2]};
    }
  };
  //! This camera placed in the hand frame (at hMc).
  Projection projection() const { return Projection(hMc, cam, width, height); }
};

} // namespace pm::core
