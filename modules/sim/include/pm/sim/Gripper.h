#pragma once
/*!
  \file Gripper.h
  A parallel gripper's two fingers on the hand, below the stereo rig, pointing forward: at the end
  of a grasp approach they enter the bottom of both images and hide the lower part of the target
  (SceneParams::gripper). They are fixed in the hand frame, so they stand still in the images
  while the target and the background move behind them.
*/
#include "pm/sim/Mesh.h"

namespace pm::sim {

/*!
  The fingers' shape and place in the hand frame (x right, y down, z forward, as the cameras';
  mm). Each finger is a box fingerWidthMm along x, fingerThicknessMm along y and running along z
  from baseMm to tipMm; their centres stand at x = +-spacingMm / 2 and y = belowMm.
*/
struct GripperParams
{
  double spacingMm = 100;        //!< between the fingers' centres (the gripper's opening)
  double belowMm = 38;           //!< how far below the rig's axis they run (hand y)
  double baseMm = 100;           //!< where they leave the gripper's body (hand z) ...
  double tipMm = 260;            //!< ... and where their tips stand (hand z)
  double fingerWidthMm = 22;     //!< each finger's width (x) ...
  double fingerThicknessMm = 12; //!< ... and thickness (y)

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

/*!
  The two fingers as one mesh in the hand frame (metres): brushed dark-grey aluminium (a colour of
  little saturation, as most grippers are), a little glossy, with black rubber pads on the inner
  faces' last 30 mm. Throws pm::core::Error if \e params is invalid.
  \code
  pm::sim::SceneParams sp;
  sp.gripper = true; // the scene draws makeGripperMesh(sp.gripperShape) at the hand in every image
  \endcode
*/
Mesh makeGripperMesh(const GripperParams &params);

} // namespace pm::sim
