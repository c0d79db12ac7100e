#include "pm/robot/Arm.h"

#include <visp3/core/vpVelocityTwistMatrix.h>

#include "pm/core/Error.h"

namespace pm::robot {

Arm::Arm(std::unique_ptr<ArmModel> model, const vpHomogeneousMatrix &eMh) : m_model(std::move(model)), m_eMh(eMh)
{
  if (!m_model)
    throw core::Error("an arm needs its model");
  if (!eMh.isAnHomogeneousMatrix())
    throw core::Error(m_model->title() + ": the rig's mounting eMh is not a rigid transformation");
}

vpMatrix Arm::hJe(const vpColVector &q) const
{
  const vpVelocityTwistMatrix hVe(m_eMh.inverse());
  return hVe * m_model->eJe(q);
}

} // namespace pm::robot
