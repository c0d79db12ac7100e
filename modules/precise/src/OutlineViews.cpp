#include "pm/precise/OutlineViews.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::precise {

OutlineViews::OutlineViews(const core::PhotoModel &model)
{
  if (!model.hasContours())
    throw core::Error("the precise stage needs a model with outlines (an all-around model of version 5; remake older models "
                "with pm-make-model)");
  auto add = [&](const double c[3], const std::vector<core::ContourPoint> &pts) {
    View v;
    const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (int k = 0; k < 3; ++k)
      v.dir[k] = c[k] / n;
    v.begin = m_points.size();
    m_points.insert(m_points.end(), pts.begin(), pts.end());
    v.end = m_points.size();
    m_maxPoints = std::max(m_maxPoints, pts.size());
    m_views.push_back(v);
  };
  add(model.cameraMm, model.contour);
  for (const core::ModelView &mv : model.views)
    add(mv.cameraMm, mv.contour);
}

std::size_t OutlineViews::nearest(const double c[3]) const
{
  std::size_t best = 0;
  double bestDot = -2;
  for (std::size_t k = 0; k < m_views.size(); ++k) {
    const double d = m_views[k].dir[0] * c[0] + m_views[k].dir[1] * c[1] + m_views[k].dir[2] * c[2];
    if (d > bestDot) {
      bestDot = d;
      best = k;
    }
  }
  return best;
}

} // namespace pm::precise
