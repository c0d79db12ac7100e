#pragma once
/*!
  \file TrackerConfigFile.h
  Tracker configuration files (JSON): every key of TrackerParams, each optional, in a section per
  part of the tracker (version 2). A missing key keeps the default (TrackerParams(), the measured
  defaults every program uses, unless the caller gives others); an unknown or misspelt key is an
  error. trackerConfigToJson() writes every key, so a file written by it and read back gives the
  same parameters. A file of version 1 (the flat keys of earlier releases) still loads, with a
  one-line notice; the keys of the refiners that were removed (smooth_refine_evaluations,
  smooth_refine_max_drop, rmga.refine_evaluations) are then ignored.

      {
        "format": "visp-photomodel-tracker", "version": 2,
        "search": { "budget_evaluations": 800, "budget_ms": 24, "rmga": { "population": 20, "seed": 1 } },
        "lock": { "quality": 0.35, "lost_quality": 0.2 },
        "steady": { "budget_fraction": 0.15, "hue_margin_px": 24 },
        "verifier": { "evaluations": 3000 },
        "refinement": { "precise": { "enabled": true }, "tilt_filter": { "alpha": 0.2, "beta": 0.02, "gate_deg": 5 } },
        "judgement": { "confidence": { "threshold": 0.95 } },
        "fitness": { "in_tol_deg": 30, "in_bg_tol_deg": 30, "out_bg_tol_deg": 20 }
      }

  \code
    std::string notice;
    pm::tracker::TrackerParams p = pm::tracker::loadTrackerConfig("tracker.json", pm::tracker::TrackerParams(), &notice);
    if (!notice.empty())
      std::cerr << "notice: " << notice << "\n";   // a file of version 1
    p.search.ga.seed = 7;
    std::ofstream("mine.json") << pm::tracker::trackerConfigToJson(p);
  \endcode
*/
#include <string>

#include "pm/tracker/TrackerParams.h"

namespace pm::tracker {

/*!
  Reads a configuration over \e defaults; throws core::Error naming the file and the key. \e notice
  (when given) receives one line for a file of version 1, else an empty string.
*/
TrackerParams loadTrackerConfig(const std::string &path, const TrackerParams &defaults = TrackerParams(), std::string *notice = nullptr);
/*!
  The keys of a configuration given as JSON text (as a file holds them; "format" and "version" may
  be left out: the current version's keys) over \e defaults: the one key list of files, the
  programs and Python's Tracker(params=...). Throws core::Error naming the key.
*/
TrackerParams trackerParamsFromJson(const std::string &text, const TrackerParams &defaults = TrackerParams());
//! Every key of \e p, as loadTrackerConfig reads them (version 2).
std::string trackerConfigToJson(const TrackerParams &p);

} // namespace pm::tracker
