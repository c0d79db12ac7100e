#include "pm/tracker/RefinementChain.h"

namespace pm::tracker {

void RefinementParams::validate() const
{
  precise.validate();
  motion.validate();
  ascent.validate();
  tiltFilter.validate();
  tiltFilterAllAround.validate();
}

RefinementChain::RefinementChain(const RefinementParams &params, const core::StereoRig &rig, const core::PhotoModel &model,
                                 const core::StereoScorer &scorer, const QualityScale &scale)
    : m_precise(params.precise, rig, model, scorer, scale), m_ascent(params.ascent, scorer),
      m_tiltParams(model.isAllAround() ? params.tiltFilterAllAround : params.tiltFilter), m_tilt(m_tiltParams), m_motion(params.motion), m_scorer(scorer)
{
}

std::optional<RmGaUpdate::Inject> RefinementChain::refine(const core::HueFrame &frame, TrackResult &r, const TrackResult &last, const vpImage<vpRGBa> &left,
                                                          const vpImage<vpRGBa> &right, bool locked)
{
  // 1. The precise stage: a pose it keeps is final.
  if (locked && m_precise.active()) {
    r.precise = m_precise.refine(frame, r, last, m_motion.predict(last.phi), left, right);
    if (r.precise) {
      m_tilt.reset();
      return RmGaUpdate::Inject{r.phi, r.fitness};
    }
  }
  // 2. The smooth ascent.
  if (locked && m_ascent.active())
    m_ascent.refine(frame, r, last);
  // 3. The tilt filter, on frames tracked in a row.
  if (!m_tiltParams.passesThrough()) {
    if (locked && last.state == TrackState::Tracking) {
      r.phi = m_tilt.update(r.phi);
      r.fitness = m_scorer.evaluate(frame, r.phi);
    } else {
      m_tilt.reset();
    }
  }
  return std::nullopt;
}

void RefinementChain::learn(const TrackResult &r)
{
  if (r.precise && r.trusted) // the scene's colours along the outline, where the pose is trusted
    m_precise.learnColours(r.phi);
  m_motion.remember(r);
}

} // namespace pm::tracker
