#include "pm/sim/RobotPA10.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpThetaUVector.h>
#include <visp3/core/vpVelocityTwistMatrix.h>

#include "pm/core/Error.h"
#include "pm/robot/InverseKinematics.h"
#include "pm/robot/Pa10Model.h"

namespace pm::sim {

RobotPA10::RobotPA10() : m_prevQ(kDof, 0.0)
{
  nDof = kDof;
  eJeAvailable = true;
  fJeAvailable = true;
  areJointLimitsAvailable = true;
  qmin = new double[kDof];
  qmax = new double[kDof];
  const robot::Pa10Model model;
  const vpColVector lo = model.jointMin(), hi = model.jointMax();
  for (int i = 0; i < kDof; ++i) {
    qmin[i] = lo[i];
    qmax[i] = hi[i];
  }
  setSamplingTime(0.002); // the PA-10's servo cycle
  init();
}

void RobotPA10::init()
{
  m_arm = std::make_unique<robot::SteppedArm>(std::make_unique<robot::Pa10Model>());
  m_arm->moveTo(vpColVector(kDof, 0.0));
  m_prevQ = 0;
}

vpHomogeneousMatrix RobotPA10::forward(const vpColVector &q) { return robot::Pa10Model::forward(q); }

bool RobotPA10::inverse(const vpHomogeneousMatrix &fMe, const vpColVector &seed, vpColVector &q, double marginDeg)
{
  const robot::IkResult r = robot::inverseKinematics(robot::Pa10Model(), fMe, seed, marginDeg);
  q = r.q;
  return r.reached;
}

vpMatrix RobotPA10::jacobianBase(const vpColVector &q) { return robot::Pa10Model::jacobianBase(q); }

void RobotPA10::get_fJe(vpMatrix &fJe_) { fJe_ = jacobianBase(q()); }

void RobotPA10::get_eJe(vpMatrix &eJe_) { eJe_ = m_arm->model().eJe(q()); }

void RobotPA10::getPosition(const vpRobot::vpControlFrameType frame, vpColVector &q)
{
  if (frame == vpRobot::JOINT_STATE) {
    q = this->q();
    return;
  }
  const vpHomogeneousMatrix M = fMe();
  const vpTranslationVector t = M.getTranslationVector();
  const vpThetaUVector tu = M.getThetaUVector();
  q.resize(6);
  for (unsigned i = 0; i < 3; ++i) {
    q[i] = t[i];
    q[i + 3] = tu[i];
  }
}

void RobotPA10::setPosition(const vpRobot::vpControlFrameType frame, const vpColVector &q)
{
  if (frame != vpRobot::JOINT_STATE)
    throw core::Error("PA-10: setPosition takes joint values (JOINT_STATE)");
  if (q.size() != kDof)
    throw core::Error("PA-10: 7 joint values expected");
  vpColVector clamped(kDof);
  for (unsigned i = 0; i < kDof; ++i) {
    if (!std::isfinite(q[i]))
      throw core::Error("PA-10: joint value not finite");
    clamped[i] = std::min(qmax[i], std::max(qmin[i], q[i]));
  }
  m_arm->moveTo(clamped);
  m_prevQ = clamped;
}

void RobotPA10::setVelocity(const vpRobot::vpControlFrameType frame, const vpColVector &vel)
{
  vpColVector qd;
  if (frame == vpRobot::JOINT_STATE) {
    if (vel.size() != kDof)
      throw core::Error("PA-10: 7 joint velocities expected");
    qd = vel;
  } else if (frame == vpRobot::END_EFFECTOR_FRAME || frame == vpRobot::CAMERA_FRAME) {
    if (vel.size() != 6)
      throw core::Error("PA-10: a 6-component twist expected");
    vpMatrix J;
    get_eJe(J);
    qd = J.pseudoInverse() * vel;
  } else {
    throw core::Error("PA-10: velocity in joint space or in the end-effector frame only");
  }
  m_arm->setJointVelocity(qd); // scaled down as a whole to the speed limits
}

void RobotPA10::step(double dt) { m_arm->advance(dt); }

void RobotPA10::getDisplacement(const vpRobot::vpControlFrameType frame, vpColVector &d)
{
  if (frame != vpRobot::JOINT_STATE)
    throw core::Error("PA-10: displacement in joint space only");
  d = q() - m_prevQ;
  m_prevQ = q();
}

vpColVector RobotPA10::jointMin() const
{
  vpColVector v(kDof);
  for (unsigned i = 0; i < kDof; ++i)
    v[i] = qmin[i];
  return v;
}

vpColVector RobotPA10::jointMax() const
{
  vpColVector v(kDof);
  for (unsigned i = 0; i < kDof; ++i)
    v[i] = qmax[i];
  return v;
}

vpColVector RobotPA10::speedLimits() const { return m_arm->model().speedLimits(); }

vpColVector RobotPA10::accelerationLimits() const { return m_arm->model().accelerationLimits(); }

} // namespace pm::sim
