#include "pm/robot/ArmModel.h"

#include <cmath>
#include <cstdio>

#include "pm/core/Error.h"

namespace pm::robot {

vpMatrix rotateJacobian(const vpRotationMatrix &R, const vpMatrix &J)
{
  vpMatrix out(6, J.getCols());
  for (unsigned c = 0; c < J.getCols(); ++c)
    for (unsigned blk = 0; blk < 2; ++blk)
      for (unsigned r = 0; r < 3; ++r) {
        double s = 0;
        for (unsigned k = 0; k < 3; ++k)
          s += R[r][k] * J[3 * blk + k][c];
        out[3 * blk + r][c] = s;
      }
  return out;
}

vpMatrix ArmModel::fJe(const vpColVector &q) const { return rotateJacobian(fMe(q).getRotationMatrix(), eJe(q)); }

vpColVector ArmModel::values(std::initializer_list<double> v)
{
  vpColVector out(static_cast<unsigned>(v.size()));
  unsigned i = 0;
  for (double x : v)
    out[i++] = x;
  return out;
}

vpColVector ArmModel::degrees(std::initializer_list<double> deg)
{
  vpColVector out(static_cast<unsigned>(deg.size()));
  unsigned i = 0;
  for (double d : deg)
    out[i++] = d * M_PI / 180;
  return out;
}

void ArmModel::requireJoints(const vpColVector &q, const std::string &what) const
{
  if (q.size() != dof())
    throw core::Error(title() + ": " + std::to_string(dof()) + " " + what + " expected, got " + std::to_string(q.size()));
  for (unsigned i = 0; i < q.size(); ++i)
    if (!std::isfinite(q[i]))
      throw core::Error(title() + ": " + what + ": joint " + std::to_string(i + 1) + " is not finite");
}

std::string ArmModel::describeJoint(unsigned i, const vpColVector &q) const
{
  const double s = prismatic(i) ? 1e3 : 180 / M_PI;
  const char *unit = prismatic(i) ? "mm" : "deg";
  char buf[128];
  std::snprintf(buf, sizeof buf, "joint %u (%.1f %s, limits %.1f..%.1f %s)", i + 1, i < q.size() ? q[i] * s : NAN, unit,
                jointMin()[i] * s, jointMax()[i] * s, unit);
  return buf;
}

} // namespace pm::robot
