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

Tracker::Tracker(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const std::string &config, const std::string &keys,
                 long seed, long budgetEvaluations)
    : m_tracker(rig, model, paramsOf(config, keys, seed, budgetEvaluations))
{
}

pm::tracker::TrackResult Tracker::track(const pybind11::array &left, const pybind11::array &right)
{
  const PixelLayout l = checkImage(left, "left image"), r = checkImage(right, "right image");
  pybind11::gil_scoped_release free; // the caller's arrays stay alive: they are this call's arguments
  const vpImage<vpRGBa> &L = imageOf(left, l, m_view[0], m_converted[0]), &R = imageOf(right, r, m_view[1], m_converted[1]);
  m_read = {L.bitmap, R.bitmap};
  return m_tracker.track(L, R);
}

} // namespace pmpy
