#pragma once
/*!
  \file GraspApproach.h
  A grasp approach: the hand closes in on the target it servoes on, from the servo's distance
  (500 mm) to the grasp's (300 mm), at a steady speed and only while the servo runs on a trusted
  estimate: when the arm is held (the target lost, an estimate refused), the approach waits where
  it is. GuardedServo::moveDesired() takes its pose every frame.
*/
#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::hand {

//! Settings of GraspApproach; validate() checks them.
struct GraspApproachParams
{
  double fromMm = 500;  //!< the distance it starts from (the servo's; along the hand's z)
  double toMm = 300;    //!< the distance it stops at
  double mmPerS = 25;   //!< how fast it closes in while servoed (mm/s)
  double settleS = 1;   //!< servoed this long (in all) at fromMm before it starts (s)

  //! Throws pm::core::Error unless 0 < toMm < fromMm <= 5000, mmPerS > 0 and settleS >= 0.
  void validate() const;
};

/*!
  The desired pose of the target in the hand frame during a grasp approach (see GraspApproach.h):
  hdMo0 with its distance along z brought from fromMm to toMm, advance() after every frame.
  \code
  pm::hand::GraspApproach approach(pm::hand::GraspApproachParams(), vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0));
  // each frame, after the command (guard: a pm::hand::GuardedServo, c: its GuardedCommand):
  approach.advance(c.servoing, 1.0 / 30);
  guard.moveDesired(approach.hdMo());
  \endcode
*/
class GraspApproach
{
public:
  //! Starts at \e hdMo0 with its distance set to params.fromMm. Throws pm::core::Error for invalid \e params.
  GraspApproach(const GraspApproachParams &params, const vpHomogeneousMatrix &hdMo0);
  //! After a frame of \e dt seconds: closes in if it was \e servoed (once servoed for settleS at fromMm).
  void advance(bool servoed, double dt);
  const vpHomogeneousMatrix &hdMo() const { return m_hdMo; } //!< the desired pose now
  double distanceMm() const { return m_distanceMm; }         //!< its distance along z now (mm)
  bool done() const { return m_distanceMm <= m_params.toMm; } //!< true once at toMm

private:
  GraspApproachParams m_params;
  vpHomogeneousMatrix m_hdMo;
  double m_distanceMm;
  double m_settledS = 0; //!< how long it has been servoed at fromMm (s)
};

} // namespace pm::hand
