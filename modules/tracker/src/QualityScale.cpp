#include "pm/tracker/QualityScale.h"

#include "pm/core/Error.h"

namespace pm::tracker {

QualityScale::QualityScale(const core::PhotoModel &model, const core::FitnessParams &f)
{
  const double n = static_cast<double>(model.size());
  const double nIn = static_cast<double>(model.inner.size()), nOut = static_cast<double>(model.outer.size());
  m_fBackground = (f.inBackground * nIn + f.outBackground * nOut) / n;
  m_fMax = (f.inMatch * nIn + f.outBackground * nOut) / n;
  if (!(m_fMax > m_fBackground))
    throw core::Error("tracker: with these scores a perfect match does not score above the background");
}

} // namespace pm::tracker
