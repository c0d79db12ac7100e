#include "pm/lab/LabPass.h"

#include <cstdio>

#include "pm/core/Error.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/RobotPA10.h"

namespace pm::lab {

LabPass runLabPass(const sim::Scene &inScene, const StereoRig &rig, const PassPlan &inPlan, const vpColVector &q0,
                   const vpHomogeneousMatrix &h0Mo, bool backgrounds)
{
  sim::Scene scene = inScene;
  scene.params().distractor = false; // the target alone, as a user would make the pass
  PassPlan plan = inPlan;
  plan.distanceMm = 1e3 * h0Mo[2][3];
  const std::vector<PassDirection> dirs = passDirections(plan);
  LabPass out;
  out.fMh0 = sim::RobotPA10::forward(q0);
  out.fMo = out.fMh0 * h0Mo;
  vpColVector q = q0;
  sim::Rasterizer r;
  // No reallocation: a view without backgrounds would be copied, and ViSP 3.5 copies an empty
  // vpImage with memcpy(nullptr) (its move constructor is not noexcept).
  out.views.reserve(dirs.size());
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "view %02zu", k);
    vpColVector qk;
    // From the rest joints first (the arm stays near its rest shape), else from the last view's; a
    // direction out of reach is tilted less, 5 deg at a time down to half its ring's angle.
    PassDirection d = dirs[k];
    bool reached = false;
    for (; !reached && d.tiltDeg >= 0.5 * dirs[k].tiltDeg - 1e-9; d.tiltDeg -= 5) {
      const vpHomogeneousMatrix goal = out.fMh0 * passPose(d, plan.distanceMm);
      reached = sim::RobotPA10::inverse(goal, q0, qk) || sim::RobotPA10::inverse(goal, q, qk);
      if (reached)
        break;
    }
    if (!reached)
      throw Error(std::string(name) + " of the pass (" + std::to_string(static_cast<int>(dirs[k].tiltDeg)) + " deg toward " +
                  std::to_string(static_cast<int>(dirs[k].azimuthDeg)) +
                  " deg) is out of the PA-10's reach within its joint limits, also tilted down to half");
    out.directions.push_back(d);
    q = qk;
    PassView v;
    v.name = name;
    v.fMh = sim::RobotPA10::forward(q);
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

sim::SimulatedPhotoModel makeSimulatedAllAroundModel(const sim::Scene &scene, const StereoRig &rig, const PassPlan &plan,
                                                     const vpColVector &q0, double distanceMm, const AllAroundParams &params,
                                                     AllAroundBuild *build)
{
  const LabPass pass = runLabPass(scene, rig, plan, q0, vpHomogeneousMatrix(0, 0, distanceMm * 1e-3, 0, 0, 0), params.backdropHueDeg < 0);
  AllAroundBuild b = buildAllAroundModel(rig, pass.views, params);
  sim::SimulatedPhotoModel s;
  s.stereo = true;
  s.oMm = pass.fMo.inverse() * b.fMm;
  s.photoHMo = pass.fMh0.inverse() * pass.fMo;
  s.background = params.backdropHueDeg < 0 ? pass.views[0].backgroundLeft : pass.views[0].left;
  s.photo = pass.views[0].left;
  s.build.region = b.silhouettes[0];
  s.build.model = b.model;
  if (build)
    *build = std::move(b);
  return s;
}

} // namespace pm::lab
