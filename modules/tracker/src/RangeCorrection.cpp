#include "pm/tracker/RangeCorrection.h"

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
  core::Phi p = phi;
  p.x = m_centreMm[0] + (phi.x - m_centreMm[0]) * m_scale;
  p.y = m_centreMm[1] + (phi.y - m_centreMm[1]) * m_scale;
  p.z = m_centreMm[2] + (phi.z - m_centreMm[2]) * m_scale;
  return p;
}

} // namespace pm::tracker
