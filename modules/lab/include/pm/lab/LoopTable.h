#pragma once
/*!
  \file LoopTable.h
  pm-servo's frames.csv, one row per closed-loop frame (LoopFrame), written as the frames come:
  time, moving, the true relative pose and the one the servo used (mm, quaternion vector), the
  relative pose error (mm, deg), the tracker's fitness and state ("oracle" in oracle mode),
  servoing, compute time (ms), the raw and used estimates' errors, confidence, verified, trusted,
  then the seven joints q1..q7 (rad) and their commanded speeds qdot1..qdot7 (rad/s).
*/
#include <iosfwd>

#include "pm/lab/ClosedLoop.h"

namespace pm::lab {

/*!
  Writes the header line, and sets the stream to 8 significant digits.

  \code
    std::ofstream csv("frames.csv");
    pm::lab::writeLoopCsvHeader(csv);
    for (long k = 0; k < n; ++k)
      pm::lab::writeLoopCsvRow(csv, loop.step(), false);
  \endcode
*/
void writeLoopCsvHeader(std::ostream &csv);
//! Writes the row of \e f; \e oracle: the run servoed on the true pose (the state column says "oracle").
void writeLoopCsvRow(std::ostream &csv, const LoopFrame &f, bool oracle);

} // namespace pm::lab
