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

namespace pm {

struct RigCamera
{
  std::string name;             //!< "left" / "right"
  vpCameraParameters cam;       //!< intrinsics of the ideal (pinhole) image: px, py, u0, v0
  unsigned width = 0;           //!< image width in pixels
  unsigned height = 0;          //!< image height in pixels
  vpHomogeneousMatrix hMc;      //!< camera pose in the hand frame (metres)
  LensDistortion distortion;    //!< the lens (none: a pinhole camera, the raw image is the ideal one)
  vpHomogeneousMatrix cMh() const { return hMc.inverse(); }
};

class StereoRig
{
public:
  RigCamera left, right;

  /*!
    The lab's symmetric rig: both cameras with intrinsics \e cam and size w x h, optical
    centres at x = -baseline/2 (left) and +baseline/2 (right) of the hand frame, each turned
    about its y axis by \e toeInRad toward the hand's z axis (0: parallel cameras).
  */
  static StereoRig symmetric(const vpCameraParameters &cam, unsigned w, unsigned h, double baselineM,
                             double toeInRad);
  //! Toe-in angle that puts a point \e distanceM straight ahead of the hand at both image centres.
  static double toeInFor(double baselineM, double distanceM);

  //! Distance between the optical centres (metres).
  double baseline() const;
  //! Pose of the right camera in the left camera frame, cLMcR in the paper's wording.
  vpHomogeneousMatrix cLMcR() const { return left.hMc.inverse() * right.hMc; }

  /*!
    Throws pm::Error naming the camera and the value if an intrinsic is non-positive or not
    finite, an image size is zero, or a pose is not rigid.
  */
  void validate() const;
};

} // namespace pm
