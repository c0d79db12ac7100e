#include "Tracker.h"

#include "Arrays.h"
#include "pm/tracker/TrackerConfigFile.h"

namespace pmpy {

namespace {

pm::tracker::TrackerParams paramsOf(const std::string &config, const std::string &keys, long seed, long budgetEvaluations)
{
  pm::tracker::TrackerParams p = config.empty() ? pm::tracker::TrackerParams() : pm::tracker::loadTrackerConfig(config);
  if (!keys.empty())
    p = pm::tracker::trackerParamsFromJson(keys, p);
  if (seed >= 0)
    p.search.ga.seed = static_cast<std::uint64_t>(seed);
  if (budgetEvaluations >= 0)
    p.search.budgetEvaluations = budgetEvaluations;
  return p;
}

} // namespace

Tracker::Tracker(const pm::core::CameraRig &rig, const pm::core::PhotoModel &model, const std::string &config, const std::string &keys,
                 long seed, long budgetEvaluations)
    : m_tracker(rig, model, paramsOf(config, keys, seed, budgetEvaluations))
{
}

pm::tracker::TrackResult Tracker::track(const std::vector<pybind11::array> &images)
{
  const std::size_t n = images.size();
  pm::core::CameraImages::checkCount(n, static_cast<std::size_t>(m_tracker.cameraCount()), "tracker"); // before the per-camera buffers
  const char *names[kMax] = {"image 0", "image 1", "image 2", "image 3"};
  const char *stereoNames[2] = {"left image", "right image"};
  std::array<PixelLayout, kMax> layout{};
  for (std::size_t k = 0; k < n; ++k)
    layout[k] = checkImage(images[k], n == 2 ? stereoNames[k] : names[k]);
  pybind11::gil_scoped_release free; // the caller's arrays stay alive: they are this call's arguments
  pm::core::CameraImages frame;
  for (std::size_t k = 0; k < n; ++k) {
    const vpImage<vpRGBa> &I = imageOf(images[k], layout[k], m_view[k], m_converted[k]);
    m_read[k] = I.bitmap;
    frame.add(I);
  }
  m_count = n;
  return m_tracker.track(frame);
}

} // namespace pmpy
