#pragma once
/*!
  \file LoopTable.h
  pm-servo's frames.csv, one row per closed-loop frame (LoopFrame), written as the frames come:
  time, moving, the true relative pose and the one the servo used (mm, quaternion vector), the
  relative pose error (mm, deg), the tracker's fitness and state ("oracle" in oracle mode),
  servoing, compute time (ms), the raw and used estimates' errors, confidence, verified, trusted,
  then the arm's joints q1..qN (rad, or m for a slide) and their commanded speeds qdot1..qdotN
  (rad/s or m/s): N = 7 for the PA-10, 6 for ViSP's Viper850 and Afma6.
*/
#include <iosfwd>

#include "pm/lab/ClosedLoop.h"

namespace pm::lab {

/*!
  Writes the header line for an arm of \e dof joints, and sets the stream to 8 significant digits.

  \code
    std::ofstream csv("frames.csv");
    pm::lab::writeLoopCsvHeader(csv, loop.arm().model().dof());
    for (long k = 0; k < n; ++k)
      pm::lab::writeLoopCsvRow(csv, loop.step(), false);
  \endcode
*/
void writeLoopCsvHeader(std::ostream &csv, unsigned dof = 7);
//! Writes the row of \e f (as many joints as it has); \e oracle: the run servoed on the true pose (the state column says "oracle").
void writeLoopCsvRow(std::ostream &csv, const LoopFrame &f, bool oracle);

} // namespace pm::lab
