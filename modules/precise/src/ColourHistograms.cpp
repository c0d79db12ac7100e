#include "pm/precise/ColourHistograms.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::precise {

ColourHistograms::ColourHistograms()
    : m_f(kSize, 0.f), m_b(kSize, 0.f), m_countF(kSize, 0.f), m_countB(kSize, 0.f), m_posterior(kSize, 0.5f)
{
}

void ColourHistograms::reset()
{
  std::fill(m_f.begin(), m_f.end(), 0.f);
  std::fill(m_b.begin(), m_b.end(), 0.f);
  std::fill(m_countF.begin(), m_countF.end(), 0.f);
  std::fill(m_countB.begin(), m_countB.end(), 0.f);
  std::fill(m_posterior.begin(), m_posterior.end(), 0.5f);
  m_nF = m_nB = 0;
  m_haveF = m_haveB = m_ready = false;
}

void ColourHistograms::start(const std::vector<float> &foreground, const std::vector<float> &background)
{
  reset();
  if (foreground.empty() && background.empty())
    return;
  if (foreground.size() != kSize || background.size() != kSize)
    throw core::Error("colour histograms: " + std::to_string(kSize) + " bins each are needed, got " +
                std::to_string(foreground.size()) + " and " + std::to_string(background.size()));
  m_f = foreground;
  m_b = background;
  m_haveF = m_haveB = m_ready = true;
  computePosteriors();
}

void ColourHistograms::update(double rateForeground, double rateBackground)
{
  auto blend = [](std::vector<float> &h, std::vector<float> &count, float n, bool &have, double rate) {
    if (n <= 0)
      return;
    const float r = have ? static_cast<float>(std::clamp(rate, 0.0, 1.0)) : 1.f, inv = 1.f / n;
    for (std::size_t i = 0; i < kSize; ++i) {
      h[i] = (1.f - r) * h[i] + r * count[i] * inv;
      count[i] = 0.f;
    }
    have = true;
  };
  blend(m_f, m_countF, m_nF, m_haveF, rateForeground);
  blend(m_b, m_countB, m_nB, m_haveB, rateBackground);
  m_nF = m_nB = 0;
  m_ready = m_haveF && m_haveB;
  if (m_ready)
    computePosteriors();
}

void ColourHistograms::computePosteriors()
{
  // A pseudo-count in every bin of both histograms: a colour seen only on one side is very likely
  // that side's, never certainly. (Certain posteriors make a segment's product collapse to 0 on one
  // side, and a segment across the outline then counts wholly for the other: a bias of half a segment.)
  for (std::size_t i = 0; i < kSize; ++i)
    m_posterior[i] = (m_f[i] + kPseudoCount) / (m_f[i] + m_b[i] + 2 * kPseudoCount);
}

double ColourHistograms::separation() const
{
  if (!m_ready)
    return 0.0;
  double s = 0;
  for (std::size_t i = 0; i < kSize; ++i)
    s += std::fabs(static_cast<double>(m_f[i]) - m_b[i]);
  return 0.5 * s;
}

} // namespace pm::precise
