#include "pm/tracker/BackgroundLearning.h"

#include <cmath>

#include "pm/core/Error.h"
#include "pm/core/Hue.h"

namespace pm::tracker {

void BackgroundParams::validate() const
{
  if (!(rate > 0 && rate <= 1))
    throw core::Error("tracker: the background's learning rate must lie in (0, 1]");
  if (!(windowDeg > 0 && windowDeg <= 90))
    throw core::Error("tracker: the background's hue window must lie in (0, 90] degrees");
  if (!(switchDeg >= 0 && switchDeg < windowDeg))
    throw core::Error("tracker: the background's switch must lie in [0, its window) degrees");
  if (minSamples < 1)
    throw core::Error("tracker: the background's least samples must be at least 1");
}

BackgroundLearning::BackgroundLearning(const BackgroundParams &params, const core::StereoScorer &scorer)
    : m_p((params.validate(), params)), m_scorer(scorer), m_model(scorer.modelBackgroundHue()), m_learnt(m_model), m_used(m_model),
      m_hues(scorer.outerPointsMax())
{
}

std::optional<double> BackgroundLearning::learn(const core::HueFrame &frame, const core::Phi &phi, bool trusted)
{
  if (!m_p.learn || !trusted)
    return std::nullopt;
  // The circular mean of the background's hues, as offsets from the hue used now (within the window).
  double sum = 0;
  int n = 0;
  for (int cam = 0; cam < m_scorer.cameraCount(); ++cam) {
    const std::size_t k = m_scorer.outerHues(frame, phi, cam, m_hues.data(), m_hues.size());
    for (std::size_t i = 0; i < k; ++i) {
      const double d = core::hueDifference(m_hues[i], m_used);
      if (std::fabs(d) <= m_p.windowDeg) {
        sum += d;
        ++n;
      }
    }
  }
  if (n < m_p.minSamples)
    return std::nullopt;
  const double seen = m_used + sum / n;
  m_learnt = core::hueOnCircle(m_learnt + m_p.rate * core::hueDifference(seen, m_learnt));
  if (std::fabs(core::hueDifference(m_learnt, m_used)) <= m_p.switchDeg)
    return std::nullopt;
  m_used = m_learnt;
  return m_used;
}

double BackgroundLearning::reset()
{
  m_learnt = m_used = m_model;
  return m_model;
}

} // namespace pm::tracker
