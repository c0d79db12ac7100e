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

class Trajectory
{
public:
  Trajectory(std::vector<Phi> waypoints, double holdS, double moveS);

  Phi at(double t) const;           //!< the pose at time t (s), held at the ends
  double duration() const;          //!< the last hold ends here
  int stepAt(double t) const;       //!< index of the waypoint being held or left
  bool moving(double t) const;      //!< between two waypoints
  const std::vector<Phi> &waypoints() const { return m_points; }

private:
  std::vector<Phi> m_points;
  double m_hold, m_move;
};

} // namespace pm::sim
