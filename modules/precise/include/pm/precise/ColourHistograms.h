#pragma once
/*!
  \file ColourHistograms.h
  The colour statistics of the precise stage (PreciseStage.h): a histogram of the target's colours
  and one of the background's, over RGB in PhotoModel::kColourBins bins per channel, and from them
  the posterior that a pixel of a given colour belongs to the target, P(f | c) = p(c | f) / (p(c | f)
  + p(c | b)), the two classes taken as equally likely (the region-based trackers' pixel-wise
  posteriors, as in DLR's M3T). They start from the model's photos (PhotoModel::foregroundHistogram)
  or from a first frame, and follow the scene while tracking: each frame's colours along the
  correspondence lines are blended in at a learning rate.

  \code
      pm::precise::ColourHistograms h;
      h.start(model.foregroundHistogram, model.backgroundHistogram);   // the model's photos
      h.addForeground(vpRGBa(200, 40, 30)); h.addBackground(vpRGBa(30, 60, 200));
      h.update(0.2, 0.2);                                               // a frame's colours blended in
      const float pf = h.posterior(vpRGBa(190, 50, 30));               // near 1: the target's colour
  \endcode
*/
#include <array>
#include <cstdint>
#include <vector>

#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"

namespace pm::precise {

/*!
  Foreground and background colour histograms and the posterior table they give (see
  ColourHistograms.h). Lookups allocate nothing. Copyable.
  \code
  pm::precise::ColourHistograms h;
  for (const vpRGBa &c : targetPixels) h.addForeground(c);
  for (const vpRGBa &c : backgroundPixels) h.addBackground(c);
  h.update(1.0, 1.0);            // the first frame: taken whole
  if (h.ready()) std::cout << h.posterior(vpRGBa(255, 0, 0)) << "\n";
  \endcode
*/
class ColourHistograms
{
public:
  static constexpr int kBins = core::PhotoModel::kColourBins;           //!< bins per channel
  static constexpr int kShift = 4;                                //!< 256 / kBins = 2^kShift
  static constexpr std::size_t kSize = static_cast<std::size_t>(kBins) * kBins * kBins; //!< bins in all
  static constexpr float kPseudoCount = 2e-4f; //!< added to every bin of both histograms for the posteriors (about one sample of a few thousand)

  ColourHistograms();

  //! The bin of colour \e c (red slowest, then green, then blue).
  static std::size_t bin(const vpRGBa &c)
  {
    return (static_cast<std::size_t>(c.R >> kShift) * kBins + static_cast<std::size_t>(c.G >> kShift)) * kBins +
           static_cast<std::size_t>(c.B >> kShift);
  }
  /*!
    Starts from given histograms (kSize bins each, each summing to 1, e.g. the model's): ready at
    once. An empty pair: not ready until the first update(). Throws pm::core::Error for another size.
  */
  void start(const std::vector<float> &foreground, const std::vector<float> &background);
  //! Forgets everything: not ready.
  void reset();
  //! Counts a target pixel of colour \e c for the next update().
  void addForeground(const vpRGBa &c) { m_countF[bin(c)] += 1.f, m_nF += 1.f; }
  //! Counts a background pixel of colour \e c for the next update().
  void addBackground(const vpRGBa &c) { m_countB[bin(c)] += 1.f, m_nB += 1.f; }
  /*!
    Blends the counted colours into the histograms (h = (1 - rate) h + rate * counts / n; the whole
    counts when not ready yet) and clears the counts; a class with no pixel counted keeps its
    histogram. Then recomputes the posteriors. Rates in [0, 1].
  */
  void update(double rateForeground, double rateBackground);
  //! Foreground and background histograms both known.
  bool ready() const { return m_ready; }
  //! P(foreground | colour of bin \e b), in (0, 1) (0.5 where neither histogram has the colour; see kPseudoCount).
  float posteriorOfBin(std::size_t b) const { return m_posterior[b]; }
  //! P(foreground | \e c).
  float posterior(const vpRGBa &c) const { return m_posterior[bin(c)]; }
  /*!
    How well the two histograms tell the classes apart: sum over colours of |p_f - p_b| / 2, in
    [0, 1] (1: no colour shared, 0: the same statistics).
  */
  double separation() const;
  const std::vector<float> &foreground() const { return m_f; } //!< the target's histogram (sums to 1 once ready)
  const std::vector<float> &background() const { return m_b; } //!< the background's histogram

private:
  void computePosteriors();
  std::vector<float> m_f, m_b, m_countF, m_countB, m_posterior;
  float m_nF = 0, m_nB = 0;
  bool m_haveF = false, m_haveB = false, m_ready = false;
};

} // namespace pm::precise
