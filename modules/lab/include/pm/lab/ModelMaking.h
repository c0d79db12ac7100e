#pragma once
/*!
  \file ModelMaking.h
  pm-make-model's runner: a photo-model built from what the user gives, with what pm::report
  draws it on. Three sources: a flat model from two photos of one camera (its lens corrected
  first), a stereo model from the rig's backdrop pair and photo pair (files or live cameras,
  capture::grabModelPairs), and the simulator's photos of a lab target or of a user's image.
  Each returns a report::ModelOutputs ready for report::writeModelOutputs().

  \code
      const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
      pm::capture::ModelPairs pairs;
      pairs.background = {pm::io::readColorImage("bgL.png"), pm::io::readColorImage("bgR.png")};
      pairs.photo = {pm::io::readColorImage("toyL.png"), pm::io::readColorImage("toyR.png")};
      pm::report::ModelOutputs m = pm::lab::stereoModelFromPhotos(rig, pairs, pm::model::StereoModelParams(), "my toy");
      pm::report::writeModelOutputs("model", m, 0);
  \endcode
*/
#include <string>

#include "pm/capture/StereoSource.h"
#include "pm/model/StereoPhotoModelBuilder.h"
#include "pm/report/ModelOutputs.h"
#include "pm/sim/Scene.h"

namespace pm::lab {

/*!
  The flat model (the paper's) from \e background and \e photo, raw images of \e camera with the
  target at \e distanceMm (mm). A lens is corrected first: the model is the ideal camera's, and
  the outputs' photos are the corrected ones. Throws pm::core::Error if the photos differ in size
  (naming \e backgroundName and \e photoName) or the builder refuses them.
*/
report::ModelOutputs flatModelFromPhotos(vpImage<vpRGBa> background, vpImage<vpRGBa> photo, const core::PinholeCamera &camera,
                                         double distanceMm, const model::PhotoModelParams &params,
                                         const std::string &backgroundName, const std::string &photoName);

/*!
  The stereo model from the rig's backdrop pair and photo pair (raw images, one hand pose).
  The outputs' photo is the left one, its lens corrected (the region and depths are the ideal
  image's). \e source names the photos in summary.json. Throws pm::core::Error.
*/
report::ModelOutputs stereoModelFromPhotos(const core::StereoRig &rig, const capture::ModelPairs &pairs,
                                           const model::StereoModelParams &params, const std::string &source);

/*!
  The simulator's model of \e scene's target seen from \e distanceMm (mm): flat (the left camera)
  or, with \e stereo, the stereo model (plus four pairs with the hand turned by \e viewTurnDeg
  when it is not 0). \e params.photo is the flat model's parameters. Throws pm::core::Error.
*/
report::ModelOutputs simulatedModel(const sim::Scene &scene, const core::StereoRig &rig, double distanceMm, bool stereo,
                                    const model::StereoModelParams &params, double viewTurnDeg, const std::string &source);

} // namespace pm::lab
