#include "pm/robot/ViSPRobotArm.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpException.h>
#include <visp3/core/vpTime.h>
#include <visp3/robot/vpRobotWireFrameSimulator.h>

#include "pm/core/Error.h"
#include "pm/io/QuietStdout.h"

namespace pm::robot {

ViSPRobotArm::ViSPRobotArm(vpRobot &robot, std::unique_ptr<ArmModel> model, const vpHomogeneousMatrix &eMh,
                           const ViSPRobotArmParams &params)
    : Arm(std::move(model), eMh), m_robot(robot), m_params(params)
{
  // ViSP's simulators' setPosition() in joint space races their own thread: always our velocity loop.
  m_params.moveByVelocity = params.moveByVelocity || dynamic_cast<vpRobotWireFrameSimulator *>(&robot) != nullptr;
  if (!(params.stallS > 0 && params.positionTolerance > 0 && params.limitHorizonS > 0))
    throw core::Error(m_model->title() + ": the stall time, the position tolerance and the limits' horizon must be positive");
  m_command.resize(m_model->dof(), true);
  m_asked = m_command;
}

ViSPRobotArm::~ViSPRobotArm()
{
  try {
    stop();
  } catch (...) {
  }
}

void ViSPRobotArm::fail(const std::string &what)
{
  try {
    stop();
  } catch (...) {
  }
  throw core::Error(m_model->title() + " (" + describe() + "): " + what + "; the arm was told to stop");
}

vpColVector ViSPRobotArm::q()
{
  vpColVector q;
  try {
    m_robot.getPosition(vpRobot::JOINT_STATE, q);
  } catch (const vpException &e) {
    fail("the robot does not answer: reading its joints failed (" + e.getStringMessage() + ")");
  }
  if (q.size() != m_model->dof())
    fail("the robot does not answer: it gave " + std::to_string(q.size()) + " joint values, its model has " +
         std::to_string(m_model->dof()));
  for (unsigned i = 0; i < q.size(); ++i)
    if (!std::isfinite(q[i]))
      fail("the robot does not answer: joint " + std::to_string(i + 1) + " reads as not finite");
  return q;
}

void ViSPRobotArm::setJointVelocity(const vpColVector &qdot)
{
  if (qdot.size() != m_model->dof())
    fail(std::to_string(m_model->dof()) + " joint velocities expected, got " + std::to_string(qdot.size()));
  for (unsigned i = 0; i < qdot.size(); ++i)
    if (!std::isfinite(qdot[i]))
      fail("the commanded velocity of joint " + std::to_string(i + 1) + " is not finite");
  const vpColVector sent = boundedNearLimits(qdot, q());
  try {
    if (m_robot.getRobotState() != vpRobot::STATE_VELOCITY_CONTROL) {
      io::QuietStdout quiet; // ViSP's robots say so on std::cout
      m_robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
    }
    m_robot.setVelocity(vpRobot::JOINT_STATE, sent);
  } catch (const vpException &e) {
    fail("the robot refused the velocity command (" + e.getStringMessage() + ")");
  }
  m_command = sent;
  m_asked = qdot;
  if (m_tickMs < 0)
    m_tickMs = vpTime::measureTimeMs();
}

vpColVector ViSPRobotArm::boundedNearLimits(const vpColVector &qdot, const vpColVector &q) const
{
  // Toward a limit at most the distance to it over the horizon: the joint would take the horizon
  // (at least) to reach it under this command, and slows down as it nears it.
  const vpColVector lo = m_model->jointMin(), hi = m_model->jointMax();
  vpColVector v = qdot;
  for (unsigned i = 0; i < v.size(); ++i) {
    if (v[i] > 0)
      v[i] = std::min(v[i], std::max(hi[i] - q[i], 0.0) / m_params.limitHorizonS);
    else if (v[i] < 0)
      v[i] = std::max(v[i], -std::max(q[i] - lo[i], 0.0) / m_params.limitHorizonS);
  }
  return v;
}

std::string ViSPRobotArm::stallReason(const vpColVector &q) const
{
  // A robot's controller stops the whole arm when a joint reaches its limit (ViSP's simulators do):
  // name it when one is there (within a degree or a millimetre) and is driven on.
  const vpColVector lo = m_model->jointMin(), hi = m_model->jointMax();
  for (unsigned i = 0; i < q.size(); ++i) {
    const double margin = m_model->prismatic(i) ? 1e-3 : M_PI / 180;
    if ((q[i] <= lo[i] + margin && m_asked[i] < 0) || (q[i] >= hi[i] - margin && m_asked[i] > 0))
      return "the robot stopped: " + m_model->describeJoint(i, q) + " is on its limit, and the servo drove it on";
  }
  return "the robot does not answer: its joints have not moved for " + std::to_string(m_stillS) + " s under a velocity command";
}

void ViSPRobotArm::advance(double dt)
{
  if (!(dt >= 0))
    fail("time runs forward only");
  if (m_tickMs < 0)
    m_tickMs = vpTime::measureTimeMs();
  vpTime::wait(m_tickMs, 1e3 * dt);
  m_tickMs += 1e3 * dt;
  // A commanded motion must move the joints: otherwise the robot does not answer.
  const vpColVector now = q();
  const bool commanding = m_asked.frobeniusNorm() > 1e-6; // asked: a joint held at its limit while the servo drives it on stalls too
  if (commanding && m_lastQ.size() == now.size() && (now - m_lastQ).frobeniusNorm() == 0.0) {
    m_stillS += dt;
    if (m_stillS >= m_params.stallS)
      fail(stallReason(now));
  } else {
    m_stillS = 0;
  }
  m_lastQ = now;
}

void ViSPRobotArm::moveTo(const vpColVector &goal)
{
  m_model->requireJoints(goal, "joint values to move to");
  const vpColVector lo = m_model->jointMin(), hi = m_model->jointMax();
  for (unsigned i = 0; i < goal.size(); ++i)
    if (goal[i] < lo[i] || goal[i] > hi[i])
      throw core::Error(m_model->title() + ": cannot move to " + m_model->describeJoint(i, goal) + ": out of its limits");
  if (m_params.moveByVelocity)
    driveTo(goal);
  else
    setPosition(goal);
  const vpColVector reached = q();
  for (unsigned i = 0; i < goal.size(); ++i)
    if (std::fabs(reached[i] - goal[i]) > m_params.positionTolerance)
      fail("it stopped at " + m_model->describeJoint(i, reached) + " short of the position asked");
  m_command = 0;
  m_asked = 0;
  m_lastQ = reached;
  m_tickMs = -1;
  m_stillS = 0;
}

void ViSPRobotArm::setPosition(const vpColVector &goal)
{
  try {
    {
      io::QuietStdout quiet;
      m_robot.setRobotState(vpRobot::STATE_POSITION_CONTROL);
    }
    m_robot.setPosition(vpRobot::JOINT_STATE, goal); // ViSP's robots return when the position is reached
  } catch (const vpException &e) {
    fail("the robot refused to move to the joints asked (" + e.getStringMessage() + ")");
  }
}

void ViSPRobotArm::driveTo(const vpColVector &goal)
{
  // Each joint at its speed limit (80 % of it), then exponentially onto its goal (5 /s): a
  // tenth of the tolerance is reached within a few seconds of the slowest joint's travel.
  constexpr double gain = 5.0, dt = 0.01, share = 0.8;
  const vpColVector vmax = m_model->speedLimits();
  const double precision = 0.1 * m_params.positionTolerance;
  vpColVector e = goal - q();
  double travelS = 0;
  for (unsigned i = 0; i < e.size(); ++i)
    travelS = std::max(travelS, std::fabs(e[i]) / (share * vmax[i]));
  const double deadlineS = 3.0 * (travelS + std::log(1.0 + e.infinityNorm() / precision) / gain) + 5.0;
  vpColVector qdot(e.size());
  for (double t = 0; e.infinityNorm() > precision; t += dt) {
    if (t > deadlineS)
      fail("it did not reach the position asked within " + std::to_string(deadlineS) + " s");
    for (unsigned i = 0; i < e.size(); ++i)
      qdot[i] = std::clamp(gain * e[i], -share * vmax[i], share * vmax[i]);
    setJointVelocity(qdot);
    advance(dt);
    e = goal - q();
  }
  stop();
}

void ViSPRobotArm::stop()
{
  m_command = 0;
  m_asked = 0;
  try {
    if (m_robot.getRobotState() == vpRobot::STATE_VELOCITY_CONTROL)
      m_robot.setVelocity(vpRobot::JOINT_STATE, m_command);
    io::QuietStdout quiet;
    m_robot.setRobotState(vpRobot::STATE_STOP);
  } catch (const vpException &e) {
    throw core::Error(m_model->title() + ": the robot did not take the stop (" + e.getStringMessage() + ")");
  }
}

std::string ViSPRobotArm::describe() const { return "a ViSP vpRobot driven in real time"; }

} // namespace pm::robot
