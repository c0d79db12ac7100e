#pragma once
/*!
  \file Options.h
  Option groups shared by several programs, so that the same knob has the same name, range and
  help everywhere.
*/
#include <CLI/CLI.hpp>

#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PhotoModelBuilder.h"
#include "pm/core/StereoFitness.h"
#include "pm/sim/Scene.h"
#include "pm/lab/LabModel.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::app {

//! --step-px, --strip-gap-px, --strip-width-px, --strip-rows, --region-colour-tol, --min-saturation
void addModelOptions(CLI::App &app, model::PhotoModelParams &p);
//! --noise, --exposure, --occluder, --supersampling, --seed
void addSceneOptions(CLI::App &app, sim::SceneParams &p);
//! --distractor CODE, --distractor-at X,Y: a look-alike toy beside the target (lab::DistractorChoice).
using lab::DistractorChoice;
void addDistractorOptions(CLI::App &app, DistractorChoice &c);

//! The lab's model (lab::LabModelChoice): all-around by default, --flat or --stereo for the older ones; --distance-mm, the pass's options.
using lab::LabModelChoice;
using lab::makeLabModel;
void addLabModelOptions(CLI::App &app, LabModelChoice &c);
//! --robot NAME: the simulated arm that carries the rig (pm::robot::armNames(): pa10, viper850, afma6).
void addRobotOption(CLI::App &app, std::string &arm);

//! --in-tol-deg, --in-bg-tol-deg, --out-bg-tol-deg
void addFitnessOptions(CLI::App &app, core::FitnessParams &p);


/*!
  The tracker's options: --config FILE (JSON, see TrackerConfigFile.h), then --budget-ms,
  --budget-evals, --population, --elite, --tournament, --crossover-rate, --mutation-per-bit,
  --predict / --no-predict, --restart-generations, --ga-seed, --lock-quality,
  --lost-quality; an option given on the command line overrides the file.
*/
class TrackerOptions
{
public:
  explicit TrackerOptions(CLI::App &app, const tracker::TrackerParams &defaults = tracker::TrackerParams());
  //! The parameters: defaults, then the file, then the command line. Throws pm::core::Error.
  tracker::TrackerParams resolve() const;

private:
  tracker::TrackerParams m_defaults, m_cli;
  std::string m_config;
  std::vector<std::pair<CLI::Option *, std::function<void(tracker::TrackerParams &, const tracker::TrackerParams &)>>> m_set;
};

} // namespace pm::app
