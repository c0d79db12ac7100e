#pragma once
/*!
  \file PassPlanner.h
  The hand poses of a pass around the target: the hand turned about a pivot on its viewing axis
  (the point \e distanceMm ahead of the hand at rest, where the target sits), by the smallest
  rotation that brings the axis to each direction of a cap: one view at rest, then rings at
  ringsDeg from the rest axis, all around. The pivot stays on the hand's z axis at the same
  distance, so the target stays in view at the tracking distance.

  \code
      const std::vector<vpHomogeneousMatrix> h0Mh = pm::model::planPass(pm::model::PassPlan());  // 16 poses
      // a robot: fMh_k = fMh0 * h0Mh[k], reached (and refused if not) by its own kinematics
  \endcode
*/
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::model {

//! What planPass() plans: how many views, on which rings, around a pivot how far ahead (see the file).
struct PassPlan
{
  int views = 16;                 //!< in all, the rest view included
  std::vector<double> ringsDeg{20, 40}; //!< the rings' angles from the rest axis (views spread over them in proportion to the angle)
  double distanceMm = 500;        //!< the pivot ahead of the hand at rest (mm)

  //! Throws pm::core::Error naming the first value out of range.
  void validate() const;
};

//! One direction of a pass: the hand's axis turned by \e tiltDeg from rest, toward azimuth \e azimuthDeg (0: the hand's +x, 90: its +y).
struct PassDirection
{
  //! The axis's tilt from rest (deg).
  double tiltDeg = 0, azimuthDeg = 0; //!< the azimuth it tilts toward (deg)
  double rollDeg = 0; //!< the hand then turned about its own axis (deg; where an arm's wrist cannot reach the pose unturned)
};

//! The directions of the plan: the rest one, then each ring's, evenly around (rings staggered by half a step).
std::vector<PassDirection> passDirections(const PassPlan &plan);
//! The hand pose looking from \e d at the pivot \e distanceMm ahead, in the frame of the hand at rest (metres).
vpHomogeneousMatrix passPose(const PassDirection &d, double distanceMm);
//! The hand poses of the pass in the frame of the hand at rest (metres): h0Mh[0] is the identity.
std::vector<vpHomogeneousMatrix> planPass(const PassPlan &plan);

} // namespace pm::model
