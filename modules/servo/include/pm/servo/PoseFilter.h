#pragma once
/*!
  \file PoseFilter.h
  An alpha-beta (constant-velocity) filter of a pose in a fixed frame: it smooths the pose
  estimates and estimates the twist (linear and angular velocity) that a feed-forward needs,
  without the lag of a plain low-pass. Rotations are handled on the manifold (theta-u residuals).
*/
#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::servo {

//! The gains of PoseFilter, for the translation and for the rotation.
struct PoseFilterParams
{
  //! Translation gain alpha: the share of the position residual taken into the position, in (0, 1].
  double alphaT = 0.7, betaT = 0.2; //!< translation gain beta: the position residual / dt taken into the velocity, in [0, 2)
  //! Rotation gain alpha: the share of the theta-u residual taken into the rotation, in (0, 1] (low: the tilts of the estimate are noisy).
  double alphaR = 0.3, betaR = 0.05; //!< rotation gain beta: the theta-u residual / dt taken into the angular velocity, in [0, 2)
  void validate() const;             //!< throws pm::core::Error unless 0 < alpha <= 1 and 0 <= beta < 2
};

/*!
  Alpha-beta filter of a pose in a fixed frame, with the twist it estimates (see PoseFilter.h).
  In the closed loop it filters fMo, the target in the robot's base frame, and its twist feeds
  PbvsServo forward.

  \code
    pm::servo::PoseFilter filter; // default gains
    const double dt = 1.0 / 30;
    // fMh: the hand in the base frame; hMo: the estimated target in the hand frame.
    filter.update(fMh * hMo, dt);
    const vpColVector twist = filter.twist(); // v (m/s), w (rad/s), base frame
    const vpColVector qdot = servo.computeJointVelocity(fMh.inverse() * filter.pose(), fMh, eJe, q, qmin, qmax, dt, &twist);
  \endcode
*/
class PoseFilter
{
public:
  //! Throws pm::core::Error if PoseFilterParams::validate() does.
  explicit PoseFilter(const PoseFilterParams &p = PoseFilterParams());
  /*!
    Takes a measurement \e z, \e dt seconds after the previous one; returns the filtered pose.
    The first measurement (and any after reset(), or with dt <= 0) is taken as is, with a zero twist.
  */
  const vpHomogeneousMatrix &update(const vpHomogeneousMatrix &z, double dt);
  //! The next update() starts the filter again from its measurement.
  void reset() { m_init = false; }
  //! update() has taken a measurement since the construction or the last reset().
  bool initialised() const { return m_init; }
  //! The filtered pose (as update() returned it last).
  const vpHomogeneousMatrix &pose() const { return m_pose; }
  //! (vx, vy, vz, wx, wy, wz) in the fixed frame: velocity of the pose's origin (m/s when the pose is in metres) and angular velocity (rad/s).
  vpColVector twist() const;

private:
  PoseFilterParams m_p;
  bool m_init = false;
  vpHomogeneousMatrix m_pose;
  double m_v[3] = {0, 0, 0}, m_w[3] = {0, 0, 0};
};

} // namespace pm::servo
