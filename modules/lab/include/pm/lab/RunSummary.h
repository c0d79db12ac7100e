#pragma once
/*!
  \file RunSummary.h
  What pm-servo reports of a closed-loop run, from its RunLog: summary.json (convergence, errors
  at rest and while moving, by tenth of the run, joints, frames servoed, held and servoed on a
  wrong pose, time, memory) and the same figures as a few lines of text.
*/
#include <map>
#include <string>
#include <vector>

#include "pm/lab/RunLog.h"

namespace pm::lab {

//! What RunLog does not know of the run.
struct RunInfo
{
  std::string arm = "PA-10";         //!< the arm that carries the rig (ArmModel::title())
  std::string targetCode;            //!< the toy followed (catalogue code)
  std::string targetName;            //!< its name
  std::string trajectory;            //!< the TC-robot's motion, in words (e.g. "steps (20)")
  bool oracle = false;               //!< the servo used the true pose
  int jointLimitViolations = 0;      //!< the robot's limit hits plus RunLog's
  std::vector<double> memoryMb;      //!< resident memory at each tenth of the run and at its end (MB; NaN: unknown)
  int overlays = 0;                  //!< overlay PNGs written
  std::string video;                 //!< the video's file name (empty: none)
};

/*!
  summary.json of the run (indented JSON text).

  \code
    log.finish();
    pm::lab::RunInfo info;
    info.targetCode = "C12";
    pm::io::writeTextFile("summary.json", pm::lab::runSummaryJson(log, info));
    std::cout << pm::lab::runSummaryText(log, info);
  \endcode
*/
std::string runSummaryJson(const RunLog &log, const RunInfo &info);
//! The figures as text, one line each (what pm-servo prints).
std::string runSummaryText(const RunLog &log, const RunInfo &info);

//! The frames held by why, most first: "verification 8, precise_residual_px 3" ("none" for none).
std::string heldByText(const std::map<std::string, long> &heldBy);

} // namespace pm::lab
