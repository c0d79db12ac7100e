#include "pm/lab/ArmCameraSource.h"

#include <cstdint>
#include <utility>

#include "pm/core/Error.h"

namespace pm::lab {

ArmCameraSource::ArmCameraSource(const sim::Scene &scene, const core::StereoRig &rig, robot::Arm &arm, const vpHomogeneousMatrix &fMo,
                                 double fps, long maxPairs)
    : ArmCameraSource(scene, rig, arm, [fMo](double) { return fMo; }, fps, maxPairs)
{
}

ArmCameraSource::ArmCameraSource(const sim::Scene &scene, const core::StereoRig &rig, robot::Arm &arm,
                                 std::function<vpHomogeneousMatrix(double)> fMoAt, double fps, long maxPairs)
    : m_scene(scene), m_rig(rig), m_arm(arm), m_fMoAt(std::move(fMoAt)), m_fps(fps), m_maxPairs(maxPairs)
{
  if (!(fps > 0) || maxPairs < 0)
    throw core::Error("the lab's cameras: the frame rate must be positive and the number of pairs not negative");
}

bool ArmCameraSource::next(capture::StereoFrame &f)
{
  if (m_maxPairs > 0 && m_next >= m_maxPairs)
    return false;
  const vpHomogeneousMatrix h = hMo();
  const long k = m_next++;
  f.index = k;
  f.timeS = static_cast<double>(k) / m_fps;
  f.skewMs = 0;
  const auto frame = static_cast<std::uint64_t>(k);
  m_scene.render(m_raster, m_rig.left, h, frame, 0, f.left, m_present);
  m_scene.render(m_raster, m_rig.right, h, frame, 1, f.right, m_present);
  ++m_stats.pairs;
  ++m_stats.framesRead[0];
  ++m_stats.framesRead[1];
  return true;
}

std::string ArmCameraSource::describe() const
{
  return "simulator on the " + m_arm.model().title() + "'s hand, target " + m_scene.target().info.code + " (" +
         m_scene.target().info.name + ")";
}

} // namespace pm::lab
