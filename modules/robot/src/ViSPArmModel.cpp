#include "pm/robot/ViSPArmModel.h"

#include <visp3/robot/vpAfma6.h>
#include <visp3/robot/vpViper850.h>

namespace pm::robot {

template <class Kinematics>
vpHomogeneousMatrix ViSPArmModel<Kinematics>::fMe(const vpColVector &q) const
{
  requireJoints(q);
  vpHomogeneousMatrix M;
  m_kinematics.get_fMe(q, M);
  return M;
}

template <class Kinematics>
vpMatrix ViSPArmModel<Kinematics>::eJe(const vpColVector &q) const
{
  requireJoints(q);
  vpMatrix J;
  m_kinematics.get_eJe(q, J);
  return J;
}

template class ViSPArmModel<vpViper850>;
template class ViSPArmModel<vpAfma6>;

} // namespace pm::robot
