#include "pm/robot/SteppedArm.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::robot {

SteppedArm::SteppedArm(std::unique_ptr<ArmModel> model, const vpHomogeneousMatrix &eMh, double cycle)
    : Arm(std::move(model), eMh), m_cycle(cycle)
{
  if (!(cycle > 0))
    throw core::Error(m_model->title() + ": the servo cycle must be positive");
  m_qmin = m_model->jointMin();
  m_qmax = m_model->jointMax();
  m_speed = m_model->speedLimits();
  m_q = m_model->restJoints();
  m_qdot.resize(m_model->dof(), true);
}

void SteppedArm::setJointVelocity(const vpColVector &qd)
{
  if (qd.size() != m_model->dof()) {
    stop();
    throw core::Error(m_model->title() + ": " + std::to_string(m_model->dof()) + " joint velocities expected, got " + std::to_string(qd.size()));
  }
  // Over a joint's speed limit, the whole command is scaled down: the motion keeps its direction.
  double scale = 1.0;
  for (unsigned i = 0; i < qd.size(); ++i) {
    if (!std::isfinite(qd[i])) {
      stop();
      throw core::Error(m_model->title() + ": the commanded velocity of joint " + std::to_string(i + 1) + " is not finite");
    }
    scale = std::min(scale, m_speed[i] / std::max(std::fabs(qd[i]), 1e-12));
  }
  m_qdot = qd * scale;
}

void SteppedArm::integrate(double dt)
{
  for (unsigned i = 0; i < m_q.size(); ++i) {
    double q = m_q[i] + m_qdot[i] * dt;
    if (q > m_qmax[i] || q < m_qmin[i]) {
      q = std::min(m_qmax[i], std::max(m_qmin[i], q));
      m_qdot[i] = 0;
      ++m_limitHits;
    }
    m_q[i] = q;
  }
}

void SteppedArm::advance(double dt)
{
  if (!(dt >= 0))
    throw core::Error(m_model->title() + ": time runs forward only");
  const int n = std::max(1, static_cast<int>(std::lround(dt / m_cycle)));
  for (int i = 0; i < n; ++i)
    integrate(dt / n);
}

void SteppedArm::moveTo(const vpColVector &q)
{
  m_model->requireJoints(q, "joint values to move to");
  for (unsigned i = 0; i < q.size(); ++i)
    if (q[i] < m_qmin[i] || q[i] > m_qmax[i])
      throw core::Error(m_model->title() + ": cannot move to " + m_model->describeJoint(i, q) + ": out of its limits");
  m_q = q;
  m_qdot = 0;
}

std::string SteppedArm::describe() const { return m_model->title() + ", its model stepped in our own loop (repeatable)"; }

} // namespace pm::robot
