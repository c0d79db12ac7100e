#include "pm/robot/Viper850Model.h"

#include <algorithm>
#include <cmath>

namespace pm::robot {

vpColVector Viper850Model::jointMin() const
{
  vpColVector q = ViSPArmModel::jointMin();
  const vpColVector sim = degrees({-50, -135, -40, -190, -110, -184});
  for (unsigned i = 0; i < q.size(); ++i)
    q[i] = std::max(q[i], sim[i]);
  return q;
}

vpColVector Viper850Model::jointMax() const
{
  vpColVector q = ViSPArmModel::jointMax();
  const vpColVector sim = degrees({50, -40, 215, 190, 110, 184});
  for (unsigned i = 0; i < q.size(); ++i)
    q[i] = std::min(q[i], sim[i]);
  return q;
}

vpColVector Viper850Model::speedLimits() const { return values({2, 2, 2, 3, 3, 5}); }

vpColVector Viper850Model::restJoints() const { return degrees({0, -85, 200, 0, -65, 0}); }

} // namespace pm::robot
