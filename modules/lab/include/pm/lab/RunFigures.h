#pragma once
/*!
  \file RunFigures.h
  The figures of the lab's runs, as pm-track and pm-servo write them: a tracking run's estimate
  against its truth and its errors after convergence (the paper's Figs. 13 and 14), and a
  closed-loop run's relative pose error, relative pose and joints over time (drawn from RunLog's
  decimated record, each sample the largest error of the frames it stands for).
*/
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/lab/RunLog.h"
#include "pm/lab/TrackingReport.h"

namespace pm::lab {

/*!
  The six pose variables of a tracking run over time: the estimate (red) against the truth
  (dashed), the convergence time marked; \e source names the run in the title.

  \code
    const pm::lab::TrackingReport r = pm::lab::reportTracking(frames, 30.0, pm::lab::table2Goals());
    pm::io::writeImage(pm::lab::drawTrackingTrajectory(frames, r, "simulator, C12"), "trajectory.png");
    if (r.haveTruth)
      pm::io::writeImage(pm::lab::drawTrackingErrors(frames, r), "errors.png");
  \endcode
*/
vpImage<vpRGBa> drawTrackingTrajectory(const std::vector<TrackedFrame> &frames, const TrackingReport &report,
                                       const std::string &source);
//! The errors of the six variables after convergence, each goal as a band (needs report.haveTruth; throws pm::core::Error otherwise).
vpImage<vpRGBa> drawTrackingErrors(const std::vector<TrackedFrame> &frames, const TrackingReport &report);

//! A closed-loop run's relative pose error over time, translation (mm) and rotation (deg); \e title above.
vpImage<vpRGBa> drawRunErrors(const RunLog &log, const std::string &title);
//! The target's pose in the hand frame over time: the one the servo used against the truth.
vpImage<vpRGBa> drawRunRelativePose(const RunLog &log);
//! The arm's joints over time (deg; a prismatic one in mm, in a panel of its own).
vpImage<vpRGBa> drawRunJoints(const RunLog &log, const robot::ArmModel &arm);

} // namespace pm::lab
