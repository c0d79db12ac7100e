#pragma once
/*!
  \file PoseFilter.h
  An alpha-beta (constant-velocity) filter of a pose in a fixed frame: it smooths the pose
  estimates and estimates the twist (linear and angular velocity) that a feed-forward needs,
  without the lag of a plain low-pass. Rotations are handled on the manifold (theta-u residuals).
*/
#include <visp3/core/vpColVector.h>
#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm {

struct PoseFilterParams
{
  double alphaT = 0.7, betaT = 0.2; //!< translation gains (alpha: position, beta: velocity)
  double alphaR = 0.3, betaR = 0.05; //!< rotation gains (the tilts of the estimate are noisy)
  void validate() const;             //!< throws pm::Error unless 0 < alpha <= 1 and 0 <= beta < 2
};

class PoseFilter
{
public:
  explicit PoseFilter(const PoseFilterParams &p = PoseFilterParams());
  //! Takes a measurement \e z, \e dt seconds after the previous one; returns the filtered pose.
  const vpHomogeneousMatrix &update(const vpHomogeneousMatrix &z, double dt);
  void reset() { m_init = false; }
  bool initialised() const { return m_init; }
  const vpHomogeneousMatrix &pose() const { return m_pose; }
  //! (vx, vy, vz, wx, wy, wz) in the fixed frame.
  vpColVector twist() const;

private:
  PoseFilterParams m_p;
  bool m_init = false;
  vpHomogeneousMatrix m_pose;
  double m_v[3] = {0, 0, 0}, m_w[3] = {0, 0, 0};
};

} // namespace pm
