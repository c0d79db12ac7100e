#pragma once
/*!
  \file QualityScale.h
  The normalised fitness q of a model: 0 for "the model on background", 1 for "every S_in point
  matches", q = (F - F_bg) / (F_max - F_bg). Every part of the tracker compares poses in q.

  \code
    const pm::tracker::QualityScale scale(model, pm::tracker::trackerFitnessDefaults());
    const double q = scale.quality(fitness.evaluate(phi));
    const double minF = F - scale.fitnessSpan(0.02); // F lower by 0.02 in q
  \endcode
*/
#include "pm/core/PhotoModel.h"
#include "pm/core/StereoFitness.h"

namespace pm::tracker {

//! q of a fitness value for one model and one set of scores (see the file's description).
class QualityScale
{
public:
  QualityScale() = default;
  //! F_bg and F_max of \e model under \e params; throws core::Error when a perfect match does not score above the background.
  QualityScale(const core::PhotoModel &model, const core::FitnessParams &params);
  //! q of \e fitness.
  double quality(double fitness) const { return (fitness - m_fBackground) / (m_fMax - m_fBackground); }
  //! A difference of \e dq in q, in F's units.
  double fitnessSpan(double dq) const { return dq * (m_fMax - m_fBackground); }

private:
  double m_fBackground = 0, m_fMax = 1;
};

} // namespace pm::tracker
