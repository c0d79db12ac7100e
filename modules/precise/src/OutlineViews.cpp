#include "pm/precise/OutlineViews.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::precise {

OutlineViews::OutlineViews(const core::PhotoModel &model)
{
  if (!model.hasContours())
    throw core::Error("the precise stage needs a model with outlines (an all-around model of version 5; remake older models "
                "with pm-make-model)");
  auto add = [&](const std::vector<core::ContourPoint> &pts) {
    View v;
    v.begin = m_points.size();
    m_points.insert(m_points.end(), pts.begin(), pts.end());
    v.end = m_points.size();
    m_maxPoints = std::max(m_maxPoints, pts.size());
    m_views.push_back(v);
  };
  add(model.contour);
  for (const core::ModelView &mv : model.views)
    add(mv.contour);
  m_index = core::ViewpointIndex(model);
}

} // namespace pm::precise
