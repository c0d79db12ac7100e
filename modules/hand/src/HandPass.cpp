#include "pm/hand/HandPass.h"

#include "pm/core/Error.h"
#include "pm/robot/ArmPassPlan.h"

namespace pm::hand {

namespace {

//! The pair at a stop: the buffered and settling ones dropped.
capture::StereoFrame pairAtStop(capture::StereoSource &source, int settlePairs, const std::string &view)
{
  capture::StereoFrame f;
  for (int k = 0; k <= settlePairs; ++k)
    if (!source.next(f))
      throw core::Error("pass: the cameras (" + source.describe() + ") ended at " + view);
  return f;
}

} // namespace

std::vector<model::PassView> recordPass(robot::Arm &arm, capture::StereoSource &source, const model::PassPlan &plan,
                                 const PassRecording &recording)
{
  if (recording.settlePairs < 0)
    throw core::Error("pass: the pairs dropped at each stop cannot be negative");
  if (recording.backgrounds && !recording.ask)
    throw core::Error("pass: the backgrounds need someone to remove the target (PassRecording::ask)");
  const vpColVector q0 = arm.q();
  std::vector<model::PassDirection> leftOut;
  const std::vector<robot::ArmPassView> planned = robot::planArmPass(arm.model(), q0, arm.eMh(), plan, plan.distanceMm, &leftOut);
  if (recording.note)
    for (const model::PassDirection &d : leftOut)
      recording.note(robot::describeLeftOut(d, arm.model().title()));
  const std::size_t total = planned.size() * (recording.backgrounds ? 2 : 1);
  std::vector<model::PassView> views(planned.size());
  std::size_t done = 0;
  auto take = [&](std::size_t k, bool background) {
    arm.moveTo(planned[k].q);
    capture::StereoFrame f = pairAtStop(source, recording.settlePairs, planned[k].name);
    model::PassView &v = views[k];
    v.name = planned[k].name;
    const vpHomogeneousMatrix fMh = arm.fMh(arm.q()); // where the arm is, as it reports
    if (background) {
      v.backgroundLeft = std::move(f.left);
      v.backgroundRight = std::move(f.right);
    } else {
      v.fMh = fMh;
      v.left = std::move(f.left);
      v.right = std::move(f.right);
    }
    if (recording.progress)
      recording.progress(++done, total);
  };
  for (std::size_t k = 0; k < planned.size(); ++k)
    take(k, false);
  if (recording.backgrounds) {
    arm.moveTo(q0);
    recording.ask("remove the target (leave everything else as it is), then press Enter");
    for (std::size_t k = planned.size(); k-- > 0;) // back the way it came
      take(k, true);
  }
  arm.moveTo(q0);
  return views;
}

} // namespace pm::hand
