#pragma once
/*!
  \file Patterns.h
  The calibration pattern a program's --pattern and --board name (pm-calib-baseline, pm-calibrate-rig).
*/
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "pm/calib/ChessBoard.h"
#include "pm/calib/TagBoard.h"

namespace pm::app {

/*!
  \e kind "chessboard" (layout inner_rows,inner_cols,square_mm) or "tags" (rows,cols,tag_mm,pitch_mm);
  \e layout empty: the pattern's default. Throws CLI::ValidationError for a layout that is not
  numbers or not whole counts, pm::core::Error for one that cannot be used.
*/
std::unique_ptr<calib::Pattern> makePattern(const std::string &kind, const std::string &layout);

} // namespace pm::app
