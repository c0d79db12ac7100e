#include "pm/lab/LabModel.h"

#include "pm/lab/ClosedLoop.h"
#include "pm/lab/LabPass.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::lab {

sim::SimulatedPhotoModel makeLabModel(const sim::Scene &scene, const core::CameraRig &rig, const LabModelChoice &c)
{
  if (!c.flat && !c.stereo) {
    model::PassPlan plan;
    plan.views = c.passViews;
    plan.ringsDeg = c.passRingsDeg;
    return makeSimulatedAllAroundModel(scene, rig, plan, c.arm, c.distanceMm, c.allAroundParams, nullptr, c.calibrateTrust);
  }
  if (c.stereo) {
    model::StereoModelParams sp;
    sp.photo = c.photo;
    sp.rightView = c.rightView;
    return sim::makeSimulatedStereoPhotoModel(scene, rig.stereo(), c.distanceMm, sp, c.viewTurnDeg); // two cameras, or it says how many
  }
  return sim::makeSimulatedPhotoModel(scene, rig[0].cam, rig[0].width, rig[0].height, c.distanceMm, c.photo);
}

void DistractorChoice::apply(sim::Scene &scene) const
{
  if (target.empty())
    return;
  scene.setDistractor(sim::makeTarget(target));
  scene.params().distractor = true;
  scene.params().distractorPose[0] = atMm.at(0);
  scene.params().distractorPose[1] = atMm.at(1);
  scene.params().validate();
}

} // namespace pm::lab
