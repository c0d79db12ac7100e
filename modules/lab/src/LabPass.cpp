#include "pm/lab/LabPass.h"

#include "pm/lab/ModelCache.h"
#include "pm/lab/TrustCache.h"

#include "pm/model/PassRig.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/ArmPassPlan.h"
#include "pm/robot/SteppedArm.h"
#include "pm/sim/Rasterizer.h"

namespace pm::lab {

LabPass runLabPass(const sim::Scene &inScene, const core::CameraRig &cameras, const model::PassPlan &inPlan, robot::Arm &arm,
                   const vpHomogeneousMatrix &h0Mo, bool backgrounds)
{
  const sim::Scene scene = inScene.targetAlone(); // as a user would make the pass
  const core::StereoRig rig = model::passRig(cameras);
  model::PassPlan plan = inPlan;
  plan.distanceMm = 1e3 * h0Mo[2][3];
  LabPass out;
  const vpColVector q0 = arm.q();
  out.fMh0 = arm.fMh(q0);
  out.fMo = out.fMh0 * h0Mo;
  const std::vector<robot::ArmPassView> planned = robot::planArmPass(arm.model(), q0, arm.eMh(), plan, plan.distanceMm, &out.leftOut);
  sim::Rasterizer r;
  // No reallocation: a view without backgrounds would be copied, and ViSP 3.5 copies an empty
  // vpImage with memcpy(nullptr) (its move constructor is not noexcept).
  out.views.reserve(planned.size());
  for (std::size_t k = 0; k < planned.size(); ++k) {
    const robot::ArmPassView &pv = planned[k];
    out.directions.push_back(pv.direction);
    arm.moveTo(pv.q);
    const vpColVector q = arm.q();
    model::PassView v;
    v.name = pv.name;
    v.fMh = arm.fMh(q); // where the arm is, as it reports
    const vpHomogeneousMatrix hMo = v.fMh.inverse() * out.fMo;
    const std::uint64_t frame = 1000 + k;
    if (backgrounds) {
      scene.render(r, rig.left, hMo, frame, 4, v.backgroundLeft, false);
      scene.render(r, rig.right, hMo, frame, 5, v.backgroundRight, false);
    }
    scene.render(r, rig.left, hMo, frame, 6, v.left, true);
    scene.render(r, rig.right, hMo, frame, 7, v.right, true);
    out.views.push_back(std::move(v));
    out.joints.push_back(q);
  }
  return out;
}

namespace {

//! The build of \e pass (its trust calibrated from it when asked); the whole build into \e build when given.
CachedModel labBuild(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                     bool calibrateTrust, model::AllAroundBuild *build)
{
  model::PassMeasurements measured;
  const core::StereoRig pair = model::passRig(rig);
  model::AllAroundBuild b = calibrateTrust ? model::buildAllAroundModel(pair, pass, params, measured) : model::buildAllAroundModel(pair, pass, params);
  if (calibrateTrust)
    b.model.trust = calibrateLabTrust(rig, pass, params, measured, b.model).trust;
  CachedModel m{b.model, b.fMm, b.silhouettes[0]};
  if (build)
    *build = std::move(b);
  return m;
}

//! labBuild() through the cache of the environment (ModelCache.h): each pass built once in a run of the suite.
CachedModel cachedLabBuild(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                           bool calibrateTrust)
{
  const ModelCache cache = ModelCache::fromEnvironment();
  const std::string key = cache.folder().enabled() ? ModelCache::keyOf(rig, pass, params, calibrateTrust) : "";
  return findOrMake<CachedModel>(
      cache.folder(), key, [&](const std::string &k) { return cache.find(k); },
      [&] { return labBuild(rig, pass, params, calibrateTrust, nullptr); },
      [&](const std::string &k, const CachedModel &m) { cache.store(k, m); });
}

} // namespace

sim::SimulatedPhotoModel makeSimulatedAllAroundModel(const sim::Scene &scene, const core::CameraRig &rig, const model::PassPlan &plan,
                                                     const std::string &armName, double distanceMm, const model::AllAroundParams &params,
                                                     model::AllAroundBuild *build, bool calibrateTrust)
{
  robot::SteppedArm arm(robot::makeArmModel(armName));
  const LabPass pass = runLabPass(scene, rig, plan, arm, vpHomogeneousMatrix(0, 0, distanceMm * 1e-3, 0, 0, 0), params.backdropHueDeg < 0);
  const CachedModel m = build ? labBuild(rig, pass.views, params, calibrateTrust, build) : cachedLabBuild(rig, pass.views, params, calibrateTrust);
  sim::SimulatedPhotoModel s;
  s.stereo = true;
  s.oMm = pass.fMo.inverse() * m.fMm;
  s.photoHMo = pass.fMh0.inverse() * pass.fMo;
  s.background = params.backdropHueDeg < 0 ? pass.views[0].backgroundLeft : pass.views[0].left;
  s.photo = pass.views[0].left;
  s.build.region = m.region;
  s.build.model = m.model;
  return s;
}

} // namespace pm::lab
