#pragma once
/*!
  \file TrackerConfigFile.h
  Tracker configuration files (JSON): every key of TrackerParams, each optional. A missing key
  keeps the default (TrackerParams(), the measured defaults every program uses, unless the
  caller gives others); an unknown or misspelt key is an error. trackerConfigToJson() writes
  every key, so a file written by it and read back gives the same parameters.

      {
        "format": "visp-photomodel-tracker", "version": 1,
        "budget_evaluations": 800, "budget_ms": 24,
        "steady_budget_fraction": 0.15, "steady_hue_margin_px": 24, "verify_evaluations": 3000,
        "rmga": { "population": 20, "predict_motion": true, "restart_generations": 30, "seed": 1 },
        "tilt_filter": { "alpha": 0.2, "beta": 0.02, "gate_deg": 5 },
        "fitness": { "in_tol_deg": 30, "in_bg_tol_deg": 30, "out_bg_tol_deg": 20 }
      }

  \code
    pm::tracker::TrackerParams p = pm::tracker::loadTrackerConfig("tracker.json");   // over TrackerParams()
    p.ga.seed = 7;
    std::ofstream("mine.json") << pm::tracker::trackerConfigToJson(p);
  \endcode
*/
#include <string>

#include "pm/tracker/PhotoModelTracker.h"

namespace pm::tracker {

//! Reads a configuration over \e defaults; throws pm::core::Error naming the file and the key.
TrackerParams loadTrackerConfig(const std::string &path, const TrackerParams &defaults = TrackerParams());
//! Every key of \e p, as loadTrackerConfig reads them.
std::string trackerConfigToJson(const TrackerParams &p);

} // namespace pm::tracker
