#pragma once
/*!
  \file TcRobot.h
  The TC-robot of the paper: it moves the target (the sea-bottom panel and the toy on it) in the
  world, with no link to the tracking robot. Its motion is given in the frame h0 of the tracking
  robot's hand at the start (so that Table 2's steps read as in the paper): the target is at
  wMo(t) = wMh0 * hMo(phi(t)), with phi(t) either Table 2's waypoints (smooth moves, see
  Trajectory) or a sinusoid phi0 + A sin(2 pi f t) on one variable, faded in over its first period.
*/
#include <memory>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/sim/Trajectory.h"

namespace pm::sim {

/*!
  The TC-robot that moves the target (see TcRobot.h): the target's pose at time t (seconds from
  the start), in the world (wMo) or in the hand frame h0 at the start (phi). It owns a copy of
  its trajectory.
*/
class TcRobot
{
public:
  //! Waypoints \e steps (the target's pose in h0 at each step); \e wMh0: h0 in the world (metres).
  TcRobot(const vpHomogeneousMatrix &wMh0, const Trajectory &steps);
  /*!
    A sinusoid of \e amplitude on variable \e axis (0..5: x, y, z in mm, eps1..3) around \e phi0,
    at \e frequencyHz (\> 0). Throws pm::core::Error if its peak velocity or acceleration exceeds the
    limits (mm/s and mm/s^2 for positions, 1/s and 1/s^2 for eps), for an axis out of range, or
    if phi0 + |amplitude| on that axis is not a valid pose.
  */
  TcRobot(const vpHomogeneousMatrix &wMh0, const core::Phi &phi0, int axis, double amplitude, double frequencyHz,
          double maxVelocity, double maxAcceleration);

  core::Phi phi(double t) const;                  //!< the target's pose in h0
  vpHomogeneousMatrix wMo(double t) const;  //!< the target's pose in the world
  bool moving(double t) const;              //!< between two waypoints at \e t; always true for a sinusoid
  double duration() const;                  //!< of the steps; 0 for a sinusoid (endless)

private:
  vpHomogeneousMatrix m_wMh0;
  std::unique_ptr<Trajectory> m_steps;
  core::Phi m_phi0;
  int m_axis = 0;
  double m_amp = 0, m_freq = 0;
};

} // namespace pm::sim
