#pragma once
/*!
  \file PoseTableFile.h
  Tables of poses (CSV): a header "<key>,x,y,z,e1,e2,e3", then one row per pose: an integer key
  (a step, a frame number), the position in mm and the quaternion vector part. Lines starting
  with # are comments. Used for Table 2's waypoints (key "step") and ground truth (key "frame").
*/
#include <string>
#include <utility>
#include <vector>

#include "pm/core/Pose.h"

namespace pm::io {

/*!
  Reads the rows in file order; \e key is the header's first column ("step", "frame"). Throws pm::core::Error naming the file and the line for a missing or
  wrong header, a cell that is not a number, a row without 7 values, an invalid pose (|eps| > 1),
  or a table with no row.
*/
std::vector<std::pair<int, core::Phi>> readPoseTable(const std::string &path, const std::string &key);

/*!
  The waypoints of a trajectory file (key "step", e.g. data/trajectories/table2.csv), in file
  order; only the first \e maxSteps when it is positive. Throws pm::core::Error as readPoseTable().
*/
std::vector<core::Phi> readWaypoints(const std::string &path, int maxSteps = 0);

} // namespace pm::io
