#pragma once
/*!
  \file TrackerConfigFile.h
  Tracker configuration files (JSON). Every key is optional; a missing key keeps the default.

      {
        "format": "visp-photomodel-tracker", "version": 1,
        "budget_ms": 24, "budget_evaluations": 0,
        "lock_quality": 0.35, "lost_quality": 0.2, "lost_frames": 3, "init_spread": 0.02,
        "steady_budget_fraction": 1, "steady_after_frames": 15, "steady_quality_drop": 0.03,
        "search_space": { "lo": [-180, -180, 320, -0.37, -0.37, -0.37], "hi": [180, 180, 680, 0.37, 0.37, 0.37] },
        "rmga": { "population": 20, "elite": 2, "tournament": 2, "crossover_rate": 0.9,
                  "mutation_per_bit": 0.0278, "predict_motion": true, "refine_evaluations": 0,
                  "restart_generations": 0, "seed": 1 },
        "fitness": { "in_tol_deg": 30, "in_bg_tol_deg": 30, "out_bg_tol_deg": 20, "in_match": 2,
                     "in_background": -0.005, "in_other": 0, "out_background": 0.1, "out_other": -0.5,
                     "off_image": 0, "min_saturation": 0 }
      }
*/
#include <string>

#include "pm/tracker/PhotoModelTracker.h"

namespace pm::io {

//! Reads a configuration over \e defaults; throws pm::Error naming the file and the key.
TrackerParams loadTrackerConfig(const std::string &path, const TrackerParams &defaults = TrackerParams());
std::string trackerConfigToJson(const TrackerParams &p);

} // namespace pm::io
