#include "pm/robot/Afma6Model.h"

#include <cmath>

namespace pm::robot {

vpColVector Afma6Model::speedLimits() const { return values({0.25, 0.25, 0.25, 1, 1, 1}); }

vpColVector Afma6Model::restJoints() const
{
  return values({0, 0, -0.1, 0, M_PI / 4, 0}); // m, m, m, rad, rad, rad
}

} // namespace pm::robot
