#include "pm/lab/LabModel.h"

#include "pm/lab/ClosedLoop.h"
#include "pm/lab/LabPass.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::lab {

sim::SimulatedPhotoModel makeLabModel(const sim::Scene &scene, const core::StereoRig &rig, const LabModelChoice &c)
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
    return sim::makeSimulatedStereoPhotoModel(scene, rig, c.distanceMm, sp, c.viewTurnDeg);
  }
  return sim::makeSimulatedPhotoModel(scene, rig.left.cam, rig.left.width, rig.left.height, c.distanceMm, c.photo);
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
