#include "pm/lab/LabSequence.h"

#include <cstdint>

#include "pm/core/Error.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::lab {

LabSequence::LabSequence(const sim::Scene &scene, const core::CameraRig &rig, const sim::Trajectory &trajectory,
                         const vpHomogeneousMatrix &oMm, double fps, long frames)
  : m_scene(scene), m_rig(rig), m_trajectory(trajectory), m_oMm(oMm), m_fps(fps), m_frames(frames)
{
  if (!(fps > 0) || frames < 1)
    throw core::Error("LabSequence: the frame rate must be positive and the sequence hold a frame");
  m_rig.validate();
  m_stats.streams = m_rig.size();
}

bool LabSequence::next(capture::StereoFrame &f) { return pairThroughFrame(f); }

bool LabSequence::nextFrame(capture::CameraFrame &f)
{
  if (m_next >= m_frames)
    return false;
  const long k = m_next++;
  f.index = k;
  f.timeS = static_cast<double>(k) / m_fps;
  f.skewMs = 0;
  const vpHomogeneousMatrix hMo = core::toHomogeneousMatrix(m_trajectory.at(f.timeS));
  // The hand stands still: a still backdrop stays where it stood at the start.
  const vpHomogeneousMatrix oMb =
      m_scene.params().stillBackdrop ? hMo.inverse() * core::toHomogeneousMatrix(m_trajectory.at(0)) : vpHomogeneousMatrix();
  std::vector<vpImage<vpRGBa>> im = m_scene.renderRig(m_rig, hMo, static_cast<std::uint64_t>(k), oMb);
  f.images.resize(im.size());
  for (std::size_t c = 0; c < im.size(); ++c) {
    swap(f.images[c], im[c]); // ViSP's swap trades the pixel buffers (no copy, no moved-from image reused)
    ++m_stats.framesRead[c];
  }
  ++m_stats.pairs;
  return true;
}

std::string LabSequence::describe() const
{
  return "simulator, target " + m_scene.target().info.code + " (" + m_scene.target().info.name + ")";
}

core::Phi LabSequence::truth(long k) const
{
  return core::fromHomogeneousMatrix(core::toHomogeneousMatrix(m_trajectory.at(static_cast<double>(k) / m_fps)) * m_oMm);
}

bool LabSequence::moving(long k) const { return m_trajectory.moving(static_cast<double>(k) / m_fps); }

} // namespace pm::lab
