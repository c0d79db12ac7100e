#include "ServoLoop.h"

#include "pm/io/PoseTableFile.h"
#include "pm/lab/LabModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/TcRobot.h"
#include "pm/sim/Trajectory.h"

namespace pmpy {

ServoLoop::ServoLoop(const std::string &target, const pm::core::StereoRig &rig, const std::string &trajectory, int steps, long seed,
                     long gaSeed, const std::string &arm)
    : m_rig(rig)
{
  pm::sim::SceneParams sp;
  sp.seed = static_cast<std::uint64_t>(seed);
  m_scene = std::make_unique<pm::sim::Scene>(pm::sim::makeTarget(target), sp);
  pm::lab::LabModelChoice choice;
  choice.arm = arm; // the same arm makes the pass and servoes (as pm-servo)
  m_model = pm::lab::makeLabModel(*m_scene, m_rig, choice);
  const std::vector<pm::core::Phi> waypoints = pm::io::readWaypoints(trajectory, steps);
  constexpr double holdS = 1.5, moveS = 2.0; // pm-servo's
  m_durationS = pm::sim::Trajectory(waypoints, holdS, moveS).duration();
  pm::tracker::TrackerParams tp;
  tp.search.ga.seed = static_cast<std::uint64_t>(gaSeed);
  pm::lab::LoopParams lp;
  lp.arm = arm;
  auto makeTc = [waypoints](const vpHomogeneousMatrix &wMh0) {
    return std::make_unique<pm::sim::TcRobot>(wMh0, pm::sim::Trajectory(waypoints, holdS, moveS));
  };
  m_loop = std::make_unique<pm::lab::ClosedLoop>(m_rig, *m_scene, m_model, tp, pm::servo::ServoParams(), lp, makeTc);
}

} // namespace pmpy
