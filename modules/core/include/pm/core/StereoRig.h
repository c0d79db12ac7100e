#pragma once
/*!
  \file StereoRig.h
  The stereo rig on the robot's hand: two cameras (PinholeCamera.h: the intrinsics, the image size,
  the lens) and where each sits on the hand.

  Frames: the hand frame H has z pointing forward (toward the target), x to the right and
  y down, like a camera frame, with its origin midway between the two optical centres.
  hMc is the pose of a camera in the hand frame, cMh its inverse; for a model at hMo
  the camera sees cMo = cMh * hMo.
*/
#include <string>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include "pm/core/PinholeCamera.h"

namespace pm::core {

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
  PinholeCamera left, right; //!< the right camera (camera 1 of StereoFitness)

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
    Throws pm::core::Error naming the camera and the value if either camera is invalid
    (PinholeCamera::validate()).
  */
  void validate() const;
};

} // namespace pm::core
