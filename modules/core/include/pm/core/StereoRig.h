#pragma once
/*!
  \file StereoRig.h
  The stereo rig on the robot's hand: two cameras (ViSP's vpCameraParameters for the pinhole
  part, a LensDistortion for the lens) and where each sits on the hand.

  Frames: the hand frame H has z pointing forward (toward the target), x to the right and
  y down, like a camera frame, with its origin midway between the two optical centres.
  hMc is the pose of a camera in the hand frame, cMh its inverse; for a model at hMo
  the camera sees cMo = cMh * hMo.
*/
#include <string>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include "pm/core/LensDistortion.h"

namespace pm::core {

/*!
  One camera of the rig: its intrinsics, image size, pose on the hand (hMc) and lens.
*/
struct RigCamera
{
  std::string name;             //!< "left" / "right"
  vpCameraParameters cam;       //!< intrinsics of the ideal (pinhole) image: px, py, u0, v0
  unsigned width = 0;           //!< image width in pixels
  unsigned height = 0;          //!< image height in pixels
  vpHomogeneousMatrix hMc;      //!< camera pose in the hand frame (metres)
  LensDistortion distortion;    //!< the lens (none: a pinhole camera, the raw image is the ideal one)
  /*! The hand frame's pose in the camera frame, hMc's inverse (metres). */
  vpHomogeneousMatrix cMh() const { return hMc.inverse(); }
};

/*!
  The two cameras on the robot's hand (see StereoRig.h for the frames). A plain value: StereoFitness
  and UndistortMap copy what they need from it.
  \code
  const vpCameraParameters cam(800, 800, 320, 240);            // px, py, u0, v0 (pixels)
  const double baseline = 0.1;                                 // metres
  pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 640, 480, baseline, pm::core::StereoRig::toeInFor(baseline, 0.5));
  rig.left.distortion.coefficients = {-0.27, 0.05, 0.001, 0.0, 0.0}; // the left lens (OpenCV's order)
  rig.validate();                                              // throws pm::core::Error naming what is wrong
  const vpHomogeneousMatrix cLMcR = rig.cLMcR();               // the right camera in the left one
  \endcode
*/
class StereoRig
{
public:
  /*! \var StereoRig::left
      \brief the left camera (camera 0 of StereoFitness) */
  RigCamera left, right; //!< the right camera (camera 1 of StereoFitness)

  /*!
    The lab's symmetric rig: both cameras with intrinsics \e cam and size w x h, optical
    centres at x = -baseline/2 (left) and +baseline/2 (right) of the hand frame, each turned
    about its y axis by \e toeInRad toward the hand's z axis (0: parallel cameras). \e baselineM in
    metres, \e toeInRad in radians; named "left" and "right", no lens distortion.
  */
  static StereoRig symmetric(const vpCameraParameters &cam, unsigned w, unsigned h, double baselineM,
                             double toeInRad);
  //! Toe-in angle (rad) that puts a point \e distanceM (metres) straight ahead of the hand at both image centres.
  static double toeInFor(double baselineM, double distanceM);

  //! Distance between the optical centres (metres).
  double baseline() const;
  //! Pose of the right camera in the left camera frame, cLMcR in the paper's wording.
  vpHomogeneousMatrix cLMcR() const { return left.hMc.inverse() * right.hMc; }

  /*!
    Throws pm::core::Error naming the camera and the value if a focal length px, py is not positive, a
    principal point u0, v0 is negative, an intrinsic is not finite, an image size is zero, a pose
    is not rigid, or a lens distortion is invalid (LensDistortion::validate()).
  */
  void validate() const;
};

} // namespace pm::core
