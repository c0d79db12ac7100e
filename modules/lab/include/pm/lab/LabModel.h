#pragma once
/*!
  \file LabModel.h
  The lab's photo-model of a simulated toy, made as a user would make it: by default the
  all-around model (an arm, the PA-10 by default, walks the rig around the toy, LabPass.h), or the paper's flat model
  (two photos face-on) or the stereo snapshot; and a look-alike toy put beside the target.
*/
#include <string>
#include <vector>

#include "pm/core/CameraRig.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PhotoModelBuilder.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"

namespace pm::lab {

//! Which photo-model the lab makes of its toy, and how (the programs' --flat, --stereo, --pass-views, ...).
struct LabModelChoice
{
  bool flat = false;        //!< the paper's flat model (two photos face-on)
  bool stereo = false;      //!< the stereo snapshot: the rig's two cameras take the photos, every point gets its relief
  double distanceMm = 500;  //!< where the toy is when its photos are taken (and, flat, the photo distance; mm)
  model::PhotoModelParams photo;   //!< region and sampling of the flat and stereo models
  bool rightView = false;   //!< the stereo model adds the right camera's own views
  double viewTurnDeg = 0;   //!< the stereo model's four further photo pairs, the hand turned by this about x and y (deg; 0: one pair)
  bool allAroundAsked = false; //!< --all-around given: the default anyway (neither flat nor stereo), kept for older command lines
  std::string arm = "pa10"; //!< the arm that makes the all-around model's pass (pm::robot::makeArmModel(); --robot)
  int passViews = 16;       //!< hand poses of the all-around model's pass
  std::vector<double> passRingsDeg{20, 40}; //!< its rings' angles from the rest axis (deg; PassPlan::ringsDeg)
  model::AllAroundParams allAroundParams; //!< the all-around build (refinement depth, viewpoints, backdrop)
  bool calibrateTrust = true; //!< the all-around model's trust calibrated from its pass (pm::trust; off: the shipped confidence and sigmas)
};

/*!
  The lab's model of \e scene's toy, as chosen, with its true frame (SimulatedPhotoModel::oMm).
  Throws pm::core::Error.

  \code
    const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
    const pm::sim::SimulatedPhotoModel m = pm::lab::makeLabModel(scene, rig, pm::lab::LabModelChoice());
    pm::tracker::PhotoModelTracker tracker(rig, m.build.model);
  \endcode
*/
sim::SimulatedPhotoModel makeLabModel(const sim::Scene &scene, const core::CameraRig &rig, const LabModelChoice &c);

//! A look-alike toy beside the target (the programs' --distractor, --distractor-at).
struct DistractorChoice
{
  std::string target;                 //!< its catalogue code (empty: none)
  std::vector<double> atMm{-190, 0};  //!< its position on the backdrop, x, y in the target frame (mm)
  //! Puts it in \e scene (nothing when no target was given). Throws pm::core::Error for an unknown code.
  void apply(sim::Scene &scene) const;
};

} // namespace pm::lab
