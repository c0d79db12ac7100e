#include "pm/core/TargetHues.h"

#include <algorithm>
#include <cmath>

namespace pm::core {

TargetHues::TargetHues(const PhotoModel &model)
{
  // A histogram of the S_in hues of every view by degree, then each tenth of a degree marked when
  // the points within kSpanDeg of it reach kShare of them.
  std::vector<double> perDegree(360, 0.0);
  double n = 0;
  auto add = [&](const std::vector<ModelPoint> &in) {
    for (const ModelPoint &p : in) {
      const long deci = std::lround(p.hue * 10.0) % 3600;
      perDegree[static_cast<std::size_t>(deci / 10) % 360] += 1;
      n += 1;
    }
  };
  add(model.inner);
  for (const ModelView &v : model.views)
    add(v.inner);
  const int span = static_cast<int>(kSpanDeg);
  for (int d = 0; d < 360; ++d) {
    double near = 0;
    for (int k = -span; k <= span; ++k)
      near += perDegree[static_cast<std::size_t>((d + k + 360) % 360)];
    if (n > 0 && near >= kShare * n)
      std::fill_n(m_table.begin() + 10 * d, 10, std::uint8_t{1});
  }
}

} // namespace pm::core
