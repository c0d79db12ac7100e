#include "pm/tracker/RangeCorrection.h"

#include "pm/core/Vec3.h"

namespace pm::tracker {

std::array<double, 3> cameraCentreMm(const core::CameraRig &rig)
{
  std::array<double, 3> c{0, 0, 0};
  if (rig.size() == 0)
    return c;
  for (std::size_t k = 0; k < rig.size(); ++k)
    for (unsigned i = 0; i < 3; ++i)
      c[i] += 1e3 * rig[k].hMc[i][3];
  for (double &x : c)
    x /= static_cast<double>(rig.size());
  return c;
}

RangeCorrection::RangeCorrection(const core::CameraRig &rig, const core::TrustCalibration &trust)
{
  if (!trust.measured || trust.rangeCameras != static_cast<int>(rig.size()) || !(trust.rangeScale > 0))
    return;
  m_scale = trust.rangeScale;
  m_centreMm = cameraCentreMm(rig);
}

core::Phi RangeCorrection::corrected(const core::Phi &phi) const
{
  if (!active())
    return phi;
  const core::Vec3 at = core::add(m_centreMm, core::scaled(core::sub({phi.x, phi.y, phi.z}, m_centreMm), m_scale));
  core::Phi p = phi;
  p.x = at[0], p.y = at[1], p.z = at[2];
  return p;
}

} // namespace pm::tracker
