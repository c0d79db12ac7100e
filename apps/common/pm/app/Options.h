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
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::app {

//! --step-px, --strip-gap-px, --strip-width-px, --strip-rows, --region-hue-tol-deg, --min-saturation
void addModelOptions(CLI::App &app, PhotoModelParams &p);
//! --noise, --exposure, --occluder, --supersampling, --seed
void addSceneOptions(CLI::App &app, sim::SceneParams &p);
//! Which photo-model the lab makes of its target: the paper's flat one or the stereo one (with depth).
//! --distractor CODE, --distractor-at X,Y: a look-alike toy beside the target (see SceneParams::distractor).
struct DistractorChoice
{
  std::string target;                 //!< its catalogue code (empty: none)
  std::vector<double> atMm{-190, 0};  //!< its position on the backdrop, target frame (mm)
  //! Puts it in \e scene (nothing when no target was given). Throws pm::Error for an unknown code.
  void apply(sim::Scene &scene) const;
};
void addDistractorOptions(CLI::App &app, DistractorChoice &c);

struct LabModelChoice
{
  bool flat = false;        //!< --flat: the paper's flat model (two photos face-on)
  bool stereo = false;      //!< --stereo: the rig's two cameras take the photos, every point gets its relief
  double distanceMm = 500;  //!< --distance-mm: where the toy is when its photos are taken (and, flat, the photo distance)
  PhotoModelParams photo;   //!< region and sampling (addModelOptions)
  bool rightView = false;   //!< --right-view: the stereo model adds the right camera's own views
  double viewTurnDeg = 0;   //!< --view-turn-deg: four further photo pairs, the hand turned by this about x and y (0: one pair)
  bool allAroundAsked = false; //!< --all-around given: the default anyway (neither --flat nor --stereo), kept for older command lines
  int passViews = 16;       //!< --pass-views: hand poses of that pass
  AllAroundParams allAroundParams; //!< --refine-depth-mm, --viewpoints: the all-around build
};
//! The lab's model: all-around by default (the PA-10 walks the rig around the toy first), --flat or --stereo for the older ones; --distance-mm, the pass's options

void addLabModelOptions(CLI::App &app, LabModelChoice &c);
//! The lab's model of \e scene's toy, as chosen, with its true frame. Throws pm::Error.
sim::SimulatedPhotoModel makeLabModel(const sim::Scene &scene, const StereoRig &rig, const LabModelChoice &c);

//! --in-tol-deg, --in-bg-tol-deg, --out-bg-tol-deg
void addFitnessOptions(CLI::App &app, FitnessParams &p);


/*!
  The tracker's options: --config FILE (JSON, see TrackerConfigFile.h), then --budget-ms,
  --budget-evals, --population, --elite, --tournament, --crossover-rate, --mutation-per-bit,
  --predict / --no-predict, --refine-evals, --restart-generations, --ga-seed, --lock-quality,
  --lost-quality; an option given on the command line overrides the file.
*/
class TrackerOptions
{
public:
  explicit TrackerOptions(CLI::App &app, const TrackerParams &defaults = TrackerParams());
  //! The parameters: defaults, then the file, then the command line. Throws pm::Error.
  TrackerParams resolve() const;

private:
  TrackerParams m_defaults, m_cli;
  std::string m_config;
  std::vector<std::pair<CLI::Option *, std::function<void(TrackerParams &, const TrackerParams &)>>> m_set;
};

} // namespace pm::app
