#pragma once
/*!
  \file Trajectory.h
  A target's motion as the TC-robot makes it: a list of poses (waypoints), each held for
  \e holdS seconds, with a move of \e moveS seconds to the next along a quintic profile (zero
  velocity and acceleration at both ends: peak velocity 1.875 d / moveS, peak acceleration
  5.77 d / moveS^2 for a step of d). Poses are interpolated component-wise in phi.
*/
#include <string>
#include <vector>

#include "pm/core/Pose.h"

namespace pm::sim {

/*!
  A timed list of poses phi (mm, quaternion vector part; see Trajectory.h): what the TC-robot
  (TcRobot) and the simulated scenarios play. Time t is in seconds from the start of the first hold.
  \code
  const std::vector<pm::core::Phi> steps = {{0, 0, 500, 0, 0, 0}, {80, 0, 500, 0, 0, 0}, {80, 60, 520, 0, 0, 0.05}};
  const pm::sim::Trajectory traj(steps, 1.5, 1.0);  // each held 1.5 s, moves of 1 s: 6.5 s in all
  for (double t = 0; t <= traj.duration(); t += 1.0 / 30) {
    const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(traj.at(t)); // metres
    if (traj.moving(t))
      std::cout << "t = " << t << " s: moving to step " << traj.stepAt(t) + 1 << "\n";
  }
  \endcode
*/
class Trajectory
{
public:
  /*!
    The poses \e waypoints, each held \e holdS seconds (>= 0), moves of \e moveS seconds (> 0)
    between them. Throws pm::core::Error for no waypoint, a time out of range or an invalid pose.
  */
  Trajectory(std::vector<core::Phi> waypoints, double holdS, double moveS);

  core::Phi at(double t) const;           //!< the pose at time t (s), held at the ends
  double duration() const;          //!< the last hold ends here
  int stepAt(double t) const;       //!< index of the waypoint being held or left
  bool moving(double t) const;      //!< between two waypoints
  const std::vector<core::Phi> &waypoints() const { return m_points; } //!< the poses, in order

private:
  std::vector<core::Phi> m_points;
  double m_hold, m_move;
};

} // namespace pm::sim
