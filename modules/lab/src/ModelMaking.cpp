#include "pm/lab/ModelMaking.h"

#include <utility>

#include "pm/core/Error.h"
#include "pm/core/UndistortMap.h"
#include "pm/model/PhotoModelBuilder.h"
#include "pm/sim/SimulatedPhotoModel.h"

namespace pm::lab {

report::ModelOutputs flatModelFromPhotos(vpImage<vpRGBa> background, vpImage<vpRGBa> photo, const core::PinholeCamera &camera,
                                         double distanceMm, const model::PhotoModelParams &params,
                                         const std::string &backgroundName, const std::string &photoName)
{
  if (background.getWidth() != photo.getWidth() || background.getHeight() != photo.getHeight())
    throw core::Error("the background photo '" + backgroundName + "' is " + std::to_string(background.getWidth()) + "x" +
                std::to_string(background.getHeight()) + " but the target photo '" + photoName + "' is " +
                std::to_string(photo.getWidth()) + "x" + std::to_string(photo.getHeight()) +
                "; take both with the same camera at the same size");
  if (!camera.distortion.isNone()) { // the lens corrected first: the model is the ideal camera's
    const core::UndistortMap map(camera);
    background = map.undistorted(background);
    photo = map.undistorted(photo);
  }
  report::ModelOutputs o;
  o.build = model::buildPhotoModel(background, photo, camera.cam, distanceMm, params);
  o.source = "photos " + backgroundName + " + " + photoName;
  o.photo = std::move(photo);
  o.background = std::move(background);
  o.writePhotos = false; // the user's own files
  o.stepPx = params.stepPx;
  return o;
}

report::ModelOutputs stereoModelFromPhotos(const core::StereoRig &rig, const capture::ModelPairs &pairs,
                                           const model::StereoModelParams &params, const std::string &source)
{
  model::StereoPhotoModelBuild b = model::buildStereoPhotoModel(rig, pairs.background.left, pairs.background.right, pairs.photo.left,
                                                  pairs.photo.right, params);
  report::ModelOutputs o;
  o.source = source;
  o.build.model = std::move(b.model);
  o.build.region = std::move(b.regionLeft);
  o.depth = std::move(b.depthLeft);
  o.dropped = std::move(b.dropped);
  o.backdropMm = b.backdropMm;
  o.background = pairs.background.left;
  // The region and depths are the ideal image's: draw on it.
  o.photo = rig.left.distortion.isNone() ? pairs.photo.left : core::UndistortMap(rig.left).undistorted(pairs.photo.left);
  o.stepPx = params.photo.stepPx;
  return o;
}

report::ModelOutputs simulatedModel(const sim::Scene &scene, const core::StereoRig &rig, double distanceMm, bool stereo,
                                    const model::StereoModelParams &params, double viewTurnDeg, const std::string &source)
{
  sim::SimulatedPhotoModel sm =
      stereo ? sim::makeSimulatedStereoPhotoModel(scene, rig, distanceMm, params, viewTurnDeg)
             : sim::makeSimulatedPhotoModel(scene, rig.left.cam, rig.left.width, rig.left.height, distanceMm, params.photo);
  report::ModelOutputs o;
  o.source = stereo ? source + ", stereo" : source;
  o.build = std::move(sm.build);
  o.background = std::move(sm.background);
  o.photo = stereo && !rig.left.distortion.isNone() ? core::UndistortMap(rig.left).undistorted(sm.photo) : std::move(sm.photo);
  o.depth = std::move(sm.depth);
  o.dropped = std::move(sm.dropped);
  o.backdropMm = sm.backdropMm;
  o.stepPx = params.photo.stepPx;
  return o;
}

} // namespace pm::lab
