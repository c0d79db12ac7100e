#include "pm/tracker/PhotoModelTracker.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::tracker {

const char *toString(TrackState s)
{
  switch (s) {
  case TrackState::Searching: return "searching";
  case TrackState::Tracking: return "tracking";
  case TrackState::Lost: return "lost";
  }
  return "?";
}

void TrackerParams::validate() const
{
  space.validate();
  ga.validate();
  fitness.validate();
  if (budgetEvaluations < 0 || !(budgetMs > 0)) // the wall-time budget must make sense even while the evaluations rule
    throw core::Error("tracker: the frame budget must be a positive number of evaluations or milliseconds (got " +
                std::to_string(budgetEvaluations) + " evaluations, " + std::to_string(budgetMs) + " ms)");
  if (budgetEvaluations > 0 && budgetEvaluations < ga.population)
    throw core::Error("tracker: a frame budget of " + std::to_string(budgetEvaluations) +
                " evaluations cannot even evaluate the population of " + std::to_string(ga.population));
  if (!(lockQuality > lostQuality) || !(lostQuality > -1) || !(lockQuality < 1))
    throw core::Error("tracker: the qualities must satisfy -1 < lost < lock < 1");
  if (lostFrames < 1)
    throw core::Error("tracker: lost frames must be at least 1");
  if (smoothRefineEvaluations < 0 || smoothRefineEvaluations > 1000000 || !(smoothRefineMaxDrop >= 0))
    throw core::Error("tracker: the smooth refinement's evaluations must lie in [0, 1000000] and its fitness drop be non-negative");
  if (smoothRefineEvaluations > 0) {
    rmga::LocalSimplexParams sp = smoothRefine;
    sp.maxEvaluations = smoothRefineEvaluations;
    sp.validate();
  }
  if (smoothAscent.maxEvaluations != 0) // 0: off
    smoothAscent.validate();
  if (!(smoothAscentMaxDrop >= 0))
    throw core::Error("tracker: the smooth ascent's fitness drop must be non-negative");
  tiltFilter.validate();
  tiltFilterAllAround.validate();
  if (!(lockConfidence >= 0 && lockConfidence < 1))
    throw core::Error("tracker: the lock confidence must lie in [0, 1)");
  if (!(rejectMarginQ <= 1))
    throw core::Error("tracker: the early rejection margin must be at most 1 (negative: off)");
  if (!(initSpread >= 0 && initSpread <= 1))
    throw core::Error("tracker: the initial spread must lie in [0, 1]");
  if (reverifyAfterFrames < 0 || !(reverifyBelowConfidence >= 0 && reverifyBelowConfidence <= 1) || verifyEvaluations < 0 || verifyEvaluations > 100000000 || !(verifyBudgetFraction > 0 && verifyBudgetFraction < 1) || !(verifyMargin >= 0) ||
      !(verifySwitchMargin >= 0) || !(verifyFarMm > 0) || !(verifyFarDeg > 0) || !(verifySameObjectMm >= 0))
    throw core::Error("tracker: the re-verification frames must be non-negative and its confidence lie in [0, 1], the verification's evaluations lie in [0, 100000000], its budget fraction in (0, 1), its margins and "
                "same-object distance be non-negative and its far distances positive");
  confidence.validate();
  uncertainty.validate();
  precise.validate();
  if (!(preciseMaxDropQ >= 0) || !(preciseRestartMm > 0) || !(preciseRestartDeg > 0) || !(preciseMaxMoveMm > 0) || !(preciseMaxMoveDeg > 0))
    throw core::Error("tracker: the precise stage's fitness drop must be non-negative and its restart and move distances positive");
  if (!(steadyBudgetFraction > 0 && steadyBudgetFraction <= 1) || steadyAfterFrames < 1 || !(steadyQualityDrop >= 0 && steadyQualityDrop < 1) ||
      steadyHueMarginPx < 0 || steadyHueMarginPx > 10000)
    throw core::Error("tracker: the steady budget fraction must lie in (0, 1], the steady frames be at least 1, the steady "
                "quality drop lie in [0, 1) and the steady hue margin in [0, 10000] px");
}

namespace {

//! The part \e fraction of \e b; never under one population's evaluations.
rmga::FrameBudget part(const rmga::FrameBudget &b, double fraction, int population)
{
  if (b.evaluations > 0)
    return rmga::FrameBudget::evals(std::max<long>(population, std::lround(fraction * static_cast<double>(b.evaluations))));
  return rmga::FrameBudget::ms(fraction * b.milliseconds);
}

//! The challenger's RM-GA: the tracker's, with another seed, no motion prediction and no refinement.
rmga::RmGaParams challengerParams(rmga::RmGaParams p)
{
  p.seed = p.seed * 0x9E3779B97F4A7C15ULL + 0x632BE59BD9B4E019ULL;
  p.predictMotion = false;
  p.refineEvaluations = 0;
  return p;
}

} // namespace

rmga::FrameBudget TrackerParams::steadyBudget() const
{
  return part(budget(), steadyBudgetFraction, ga.population);
}

PhotoModelTracker::PhotoModelTracker(const core::StereoRig &rig, const core::PhotoModel &model, const TrackerParams &params)
    : m_params((params.validate(), params)), m_fitness(rig, model, params.fitness), m_ga(params.space, params.ga),
      m_challenger(params.space, challengerParams(params.ga)), m_tilt(model.isAllAround() ? params.tiltFilterAllAround : params.tiltFilter),
      m_allAround(model.isAllAround())
{
  const core::FitnessParams &f = params.fitness;
  const double n = static_cast<double>(model.size());
  const double nIn = static_cast<double>(model.inner.size()), nOut = static_cast<double>(model.outer.size());
  m_fBackground = (f.inBackground * nIn + f.outBackground * nOut) / n;
  m_fMax = (f.inMatch * nIn + f.outBackground * nOut) / n;
  if (!(m_fMax > m_fBackground))
    throw core::Error("tracker: with these scores a perfect match does not score above the background");
  // The model must fit the rig: at the centre of the search space most of it is in both images.
  core::Phi centre;
  for (std::size_t i = 0; i < 6; ++i)
    centre[i] = 0.5 * (params.space.lo[i] + params.space.hi[i]);
  for (int cam = 0; cam < 2; ++cam) {
    const double visible = m_fitness.visibleFraction(centre, cam);
    if (visible < 0.5)
      throw core::Error("the photo-model does not fit the rig: at the centre of the search space " + centre.toString() +
                  " only " + std::to_string(static_cast<int>(100 * visible)) + " % of its points fall in the " +
                  (cam ? "right" : "left") + " image (a model too large for the cameras, or made at another scale?)");
  }
  if (params.preciseStage && model.hasContours())
    m_precise = std::make_unique<precise::PreciseStage>(rig, model, params.precise);
  if (params.confidence.kind == ConfidenceKind::Auto) { // the coefficients of the model's kind, the threshold as given
    const ConfidenceKind kind = model.isAllAround() ? ConfidenceKind::AllAround : model.hasDepth() ? ConfidenceKind::Stereo : ConfidenceKind::Flat;
    const double threshold = m_params.confidence.threshold;
    m_params.confidence = ConfidenceModel::shipped(kind);
    m_params.confidence.threshold = threshold;
  }
  initialize();
}

std::array<core::Phi, 8> PhotoModelTracker::competitors(const core::Phi &b)
{
  const vpHomogeneousMatrix hMb = core::toHomogeneousMatrix(b);
  std::array<core::Phi, 8> alt;
  for (std::size_t k = 0; k < 7; ++k) {
    const double a = (static_cast<double>(k) - 3.0) * M_PI / 4.0 + (k >= 3 ? M_PI / 4.0 : 0.0); // -135..-45, 45..180 deg
    alt[k] = core::fromHomogeneousMatrix(hMb * vpHomogeneousMatrix(0, 0, 0, 0, 0, a));
  }
  alt[7] = core::Phi{b.x, b.y, b.z, -b.e1, -b.e2, b.e3};
  return alt;
}

std::array<core::PixelRect, 2> PhotoModelTracker::steadyWindows() const
{
  std::array<core::PixelRect, 2> w;
  const core::Phi &last = m_last.phi;
  core::Phi next = last; // constant velocity from the two last frames (else the last pose again)
  if (m_haveBeforeLast)
    for (std::size_t i = 0; i < 6; ++i)
      next[i] = 2 * last[i] - m_beforeLast[i];
  if (!next.isValid())
    next = last;
  for (int cam = 0; cam < 2; ++cam) {
    w[static_cast<std::size_t>(cam)] = m_fitness.footprint(last, cam).united(m_fitness.footprint(next, cam));
    const core::StereoFitness::Camera &c = m_fitness.camera(cam);
    w[static_cast<std::size_t>(cam)] = w[static_cast<std::size_t>(cam)].grown(m_params.steadyHueMarginPx, c.width, c.height);
  }
  return w;
}

ConfidenceCues PhotoModelTracker::cuesAt(const core::Phi &phi, double q, const core::Phi *last) const
{
  ConfidenceCues c;
  const core::FitnessDetail d = m_fitness.evaluateDetail(phi);
  c.quality = q;
  c.qualityMin = std::min(quality(d.left), quality(d.right));
  auto shares = [](const core::FitnessCounts &n, double &in, double &out) {
    const int nIn = n.inMatch + n.inBackground + n.inOther + n.inOff, nOut = n.outBackground + n.outOther + n.outOff;
    in = nIn > 0 ? static_cast<double>(n.inMatch) / nIn : 0.0;
    out = nOut > 0 ? static_cast<double>(n.outBackground) / nOut : 0.0;
  };
  double inL, outL, inR, outR;
  shares(d.countsLeft, inL, outL);
  shares(d.countsRight, inR, outR);
  c.inMatchMin = std::min(inL, inR);
  c.outBackgroundMin = std::min(outL, outR);
  const double r22 = 1.0 - 2.0 * (phi.e1 * phi.e1 + phi.e2 * phi.e2); // the model's z axis . the hand's
  c.tiltDeg = std::acos(std::clamp(r22, -1.0, 1.0)) * 180.0 / M_PI;
  // Competing poses of the same object: turned about the model's z axis, or the tilt mirrored.
  std::array<core::Phi, 8> rivals;
  std::array<double, 8> rivalF{};
  std::size_t nRivals = 0;
  for (const core::Phi &p : competitors(phi))
    if (p.isValid() && core::rotationDistanceDeg(p, phi) > m_params.verifyFarDeg) // a mirrored small tilt is the same pose
      rivals[nRivals++] = p;
  m_fitness.evaluate(rivals.data(), nRivals, rivalF.data()); // one batch, on two cores
  double qAlt = -1e9;
  for (std::size_t k = 0; k < nRivals; ++k)
    qAlt = std::max(qAlt, quality(rivalF[k]));
  c.competitorMargin = q - qAlt;
  c.qualityDrop = std::max(0.0, m_recentBestQ - q);
  c.jumpMm = last ? core::translationDistanceMm(phi, *last) : 0.0;
  c.jumpDeg = last ? core::rotationDistanceDeg(phi, *last) : 0.0;
  return c;
}

void PhotoModelTracker::resetCounters()
{
  m_lowFrames = 0;
  m_steadyFrames = 0;
  m_recentBestQ = 0;
  m_verifyLeft = 0;
  m_verified = false;
  m_framesTracked = 0;
  m_untrustedFrames = 0;
  m_haveBeforeLast = false;
  m_tilt.reset();
}

void PhotoModelTracker::startVerification(const core::Phi &lock)
{
  m_verified = m_params.verifyEvaluations == 0;
  m_verifyLeft = m_params.verifyEvaluations;
  if (m_verifyLeft == 0)
    return;
  // Every individual the lock, then all but it replaced by the restart's blocks; the lock does
  // not breed for the whole verification, so the others search on their own.
  // The challenger searches near the last trusted pose too (the tracker's anchor; no frame is
  // trusted while it verifies, so the anchor stays the same until it ends).
  if (m_ga.hasAnchor())
    m_challenger.setAnchor(m_ga.anchor());
  else
    m_challenger.clearAnchor();
  m_challenger.seedAround(lock, 0.0);
  m_challenger.restart(1, 1000000);
}

void PhotoModelTracker::verify(rmga::StereoObjective &objective, const rmga::FrameBudget &budget, TrackResult &r)
{
  rmga::FrameResult c = m_challenger.evolve(objective, budget);
  if (m_params.coarseSearch) { // its best on every point, to compare with the tracker's F
    c.fitness = m_fitness.evaluate(c.best);
    ++c.evaluations;
    ++c.candidates;
  }
  r.evaluations += c.evaluations;
  r.candidates += c.candidates;
  r.generations += c.generations;
  const double apartMm = core::translationDistanceMm(c.best, r.phi);
  const bool far = apartMm > m_params.verifyFarMm || core::rotationDistanceDeg(c.best, r.phi) > m_params.verifyFarDeg;
  if (far && quality(c.fitness) > quality(r.fitness) + m_params.verifySwitchMargin) {
    // A clearly better pose elsewhere: the tracker moves there, and that lock is verified in turn.
    m_ga.seedAround(c.best, m_params.initSpread);
    r.phi = c.best;
    r.fitness = c.fitness;
    r.switched = true;
    m_tilt.reset();
    startVerification(c.best);
  } else if (far && apartMm < m_params.verifySameObjectMm && quality(c.fitness) > quality(r.fitness) - m_params.verifyMargin) {
    startVerification(r.phi); // another pose of the same object scores as well: ambiguous, look again
  } else if ((m_verifyLeft -= std::min(m_verifyLeft, c.evaluations)) == 0) {
    m_verified = true;
  }
}

void PhotoModelTracker::initialize()
{
  m_ga.randomize();
  m_ga.clearAnchor();
  m_last = TrackResult();
  m_last.state = TrackState::Searching;
  resetCounters();
}

void PhotoModelTracker::initFromPose(const vpHomogeneousMatrix &hMo)
{
  const core::Phi p = core::fromHomogeneousMatrix(hMo);
  m_ga.seedAround(p, m_params.initSpread);
  m_last = TrackResult();
  m_last.hMo = hMo;
  m_last.phi = p;
  m_last.state = TrackState::Tracking;
  resetCounters();
  m_verified = true; // a pose given is taken as verified
  m_ga.setAnchor(p);
  m_last.verified = true;
}

void PhotoModelTracker::applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (!hNowMhPrev.isAnHomogeneousMatrix())
    throw core::Error("tracker: the hand motion is not a rigid transformation");
  const auto moved = [&](const core::Phi &p) {
    const core::Phi q = core::fromHomogeneousMatrix(hNowMhPrev * core::toHomogeneousMatrix(p));
    return q.isValid() ? q : p;
  };
  m_ga.transform(moved);
  if (m_verifyLeft > 0) // an idle challenger is started afresh from the next lock
    m_challenger.transform(moved);
  m_last.hMo = hNowMhPrev * m_last.hMo;
  m_last.phi = core::fromHomogeneousMatrix(m_last.hMo);
  m_tilt.transform(hNowMhPrev);
  if (m_haveBeforeLast)
    m_beforeLast = moved(m_beforeLast);
}

rmga::FrameResult PhotoModelTracker::search(const Frame &f, rmga::StereoObjective &objective, rmga::StereoObjective &coarseObjective)
{
  const bool coarse = m_params.coarseSearch && m_last.state != TrackState::Tracking;
  rmga::FrameResult fr = m_ga.evolve(coarse ? coarseObjective : objective, f.budget);
  if (coarse) { // the estimate of the best, then F itself
    fr.fitness = m_fitness.evaluate(fr.best);
    ++fr.evaluations;
    ++fr.candidates;
  }
  if (f.steady && m_params.steadyEscalation && quality(fr.fitness) < m_recentBestQ - m_params.steadyQualityDrop) {
    // The steady frame went wrong: the rest of the whole budget at once, on the whole images.
    f.escalated = true;
    if (f.windowed) {
      m_fitness.setImages(*f.left, *f.right);
      f.windowed = false;
    }
    rmga::FrameBudget rest = f.mainWhole;
    if (rest.evaluations > 0)
      rest.evaluations = std::max<long>(m_params.ga.population, rest.evaluations - fr.evaluations);
    else
      rest.milliseconds = std::max(0.05, rest.milliseconds - (f.msSinceStart() - f.hueMs));
    const rmga::FrameResult more = m_ga.evolve(objective, rest, true);
    fr.best = more.best;
    fr.fitness = more.fitness;
    fr.evaluations += more.evaluations;
    fr.candidates += more.candidates;
    fr.generations += more.generations;
    fr.restarted = fr.restarted || more.restarted;
  }
  return fr;
}

bool PhotoModelTracker::refinePrecise(TrackResult &r, const Frame &f)
{
  m_precise->setImages(*f.left, *f.right);
  // A result is kept when it stays near its start and F there is not much under RM-GA's best: the
  // outline's peak lies on F's plateau, a divergence (colours that do not separate, a wrong start)
  // leaves it.
  const double minF = r.fitness - m_params.preciseMaxDropQ * (m_fMax - m_fBackground);
  auto acceptable = [&](const precise::PreciseResult &p, const core::Phi &start, double &F) {
    if (!p.ok || core::translationDistanceMm(p.phi, start) > m_params.preciseMaxMoveMm || core::rotationDistanceDeg(p.phi, start) > m_params.preciseMaxMoveDeg)
      return false;
    F = m_fitness.evaluate(p.phi);
    return F >= minF;
  };
  const bool haveLast = m_last.state == TrackState::Tracking && m_last.precise && m_last.phi.isValid();
  const bool near = haveLast && core::translationDistanceMm(r.phi, m_last.phi) <= m_params.preciseRestartMm &&
                    core::rotationDistanceDeg(r.phi, m_last.phi) <= m_params.preciseRestartDeg;
  precise::PreciseResult best;
  double bestF = 0;
  bool found = false;
  if (haveLast) {
    const precise::PreciseResult fromLast = m_precise->refine(m_last.phi, true); // the target moves little between frames
    r.preciseResult = fromLast;
    found = acceptable(fromLast, m_last.phi, bestF);
    if (found)
      best = fromLast;
  }
  if (!near || !found) {
    const precise::PreciseResult fromSearch = m_precise->refine(r.phi);
    double F = 0;
    if (acceptable(fromSearch, r.phi, F) && (!found || fromSearch.residualPx < best.residualPx)) {
      best = fromSearch;
      bestF = F;
      found = true;
    }
    if (!found)
      r.preciseResult = fromSearch;
  }
  if (!found)
    return false;
  r.preciseResult = best;
  r.phi = best.phi;
  r.fitness = bestF;
  m_ga.inject(best.phi, bestF);
  return true;
}

void PhotoModelTracker::refine(TrackResult &r, rmga::StereoObjective &objective, const Frame &f)
{
  if (m_params.smoothRefineEvaluations > 0 && quality(r.fitness) >= m_params.lockQuality) {
    // The top of F's plateau: a continuous search of the smooth score from RM-GA's best.
    rmga::StereoObjective smooth(m_fitness, rmga::StereoObjective::Score::Smooth);
    rmga::LocalSimplexParams sp = m_params.smoothRefine;
    sp.maxEvaluations = m_params.smoothRefineEvaluations;
    const rmga::LocalSimplexResult lr = rmga::refineLocalSimplex(smooth, r.phi, sp);
    r.smoothEvaluations = lr.evaluations;
    const double F = m_fitness.evaluate(lr.best);
    if (F >= r.fitness - m_params.smoothRefineMaxDrop) {
      r.phi = lr.best;
      r.fitness = F;
    }
  }
  const bool locked = quality(r.fitness) >= m_params.lockQuality;
  if (m_precise && locked) {
    r.precise = refinePrecise(r, f);
    if (r.precise) {
      m_tilt.reset();
      return;
    }
  }
  if (m_params.smoothAscent.maxEvaluations > 0 && locked) {
    // The top of the smooth score near RM-GA's best, or near the last frame's pose if that scores higher
    // (the GA's best wanders over F's plateau from frame to frame).
    const core::Phi starts[2] = {r.phi, m_last.phi};
    const std::size_t n = m_last.state == TrackState::Tracking && m_last.phi.isValid() && m_params.smoothAscent.maxEvaluations > 1 ? 2 : 1;
    const rmga::SmoothAscentResult a = rmga::climbSmooth(objective, starts, n, m_params.smoothAscent);
    r.ascentEvaluations = a.evaluations;
    const double F = m_fitness.evaluate(a.best);
    if (F >= r.fitness - m_params.smoothAscentMaxDrop) {
      r.phi = a.best;
      r.fitness = F;
    }
  }
  if (!tiltFilter().passesThrough()) {
    if (locked && m_last.state == TrackState::Tracking) {
      r.phi = m_tilt.update(r.phi);
      r.fitness = m_fitness.evaluate(r.phi);
    } else {
      m_tilt.reset();
    }
  }
}

void PhotoModelTracker::updateState(TrackResult &r)
{
  const TrackState prev = m_last.state;
  bool lockDoubted = false;
  if (r.quality >= m_params.lockQuality && prev != TrackState::Tracking && m_params.lockConfidence > 0) {
    // A new lock: only if it would not be plainly wrong (its confidence as a first, unverified lock).
    ConfidenceCues lock = cuesAt(r.phi, r.quality, nullptr);
    if (r.precise)
      addPreciseCues(lock, r, precise::lineSigmas(r.preciseResult.information));
    lock.framesTracked = 1;
    lock.verified = m_params.verifyEvaluations == 0;
    lock.tracking = true;
    lockDoubted = m_params.confidence.confidence(lock) < m_params.lockConfidence;
    if (lockDoubted) // the search converged on a plainly wrong pose: search everywhere again, that pose kept apart
      m_ga.scatter(1, m_params.ga.restartGenerations);
  }
  if (r.quality >= m_params.lockQuality && !lockDoubted) {
    r.state = TrackState::Tracking;
    m_lowFrames = 0;
  } else if (prev == TrackState::Tracking) {
    m_lowFrames = r.quality < m_params.lostQuality ? m_lowFrames + 1 : 0;
    r.state = m_lowFrames >= m_params.lostFrames ? TrackState::Lost : TrackState::Tracking;
  } else {
    r.state = prev; // searching or lost, until locked
  }
  if (r.state == TrackState::Lost && prev != TrackState::Lost)
    m_ga.restart(1, m_params.ga.restartGenerations); // search again, keeping the best guess apart (and near the last trusted pose)
  // A new lock is verified on the next frames; a lost target is no longer.
  if (r.state == TrackState::Tracking && prev != TrackState::Tracking)
    startVerification(r.phi);
  else if (r.state != TrackState::Tracking)
    m_verified = false, m_verifyLeft = 0;
  m_framesTracked = r.state == TrackState::Tracking ? m_framesTracked + 1 : 0;
  // Steadiness for the next frame's budget. The recent best is remembered through a loss, so that
  // a relock on a wrong pose (lower q) is not taken for steady and keeps the whole budget to find
  // the true one.
  m_recentBestQ = std::max(r.state == TrackState::Tracking ? r.quality : 0.0, m_recentBestQ - 0.001);
  m_steadyFrames = r.state == TrackState::Tracking && r.quality >= m_recentBestQ - m_params.steadyQualityDrop ? m_steadyFrames + 1 : 0;
}

void PhotoModelTracker::addPreciseCues(ConfidenceCues &c, const TrackResult &r, const std::array<double, 6> &s)
{
  if (!r.precise)
    return;
  // How well the precise stage's lines pin the pose (s: their sigmas), and how well they fit.
  const precise::PreciseResult &p = r.preciseResult;
  c.precise = true;
  c.preciseResidualPx = p.residualPx;
  c.preciseSigmaMm = std::min(1e3, std::max({s[0], s[1], s[2]}));
  c.preciseSigmaDeg = std::min(1e3, std::max({s[3], s[4], s[5]}));
  c.separation = p.separation;
  c.cameraDisagreementPx = std::fabs(p.residualPxPerCamera[0] - p.residualPxPerCamera[1]);
}

void PhotoModelTracker::scoreConfidence(TrackResult &r, const Frame &f)
{
  // The cues are scored on the whole images: the hue under the poses they look at is added where
  // a steady frame's windows left it out.
  if (f.windowed) {
    std::array<core::Phi, 9> seen;
    std::size_t n = 0;
    seen[n++] = r.phi;
    for (const core::Phi &p : competitors(r.phi))
      if (p.isValid())
        seen[n++] = p;
    m_fitness.addHueUnder(*f.left, *f.right, seen.data(), n);
  }
  ConfidenceCues &c = r.cues;
  c = cuesAt(r.phi, r.quality, m_last.state == TrackState::Tracking ? &m_last.phi : nullptr);
  c.framesTracked = m_framesTracked;
  c.verified = m_verified;
  c.tracking = r.state == TrackState::Tracking;
  if (r.precise) { // the lines' sigmas once: for the cues and for the uncertainty
    const std::array<double, 6> s = precise::lineSigmas(r.preciseResult.information);
    addPreciseCues(c, r, s);
    r.uncertainty = m_params.uncertainty.uncertainty(s, r.preciseResult.residualPx);
  }
  r.verified = m_verified;
  r.confidence = m_params.confidence.confidence(c);
  r.trusted = c.tracking && r.verified && r.confidence >= m_params.confidence.threshold;
  if (r.trusted) // where the target was last seen for sure: the restarts' anchor
    m_ga.setAnchor(r.phi);
  // A verified lock whose confidence stays low is doubted: the challenger searches again.
  m_untrustedFrames = c.tracking && r.verified && r.confidence < m_params.reverifyBelowConfidence ? m_untrustedFrames + 1 : 0;
  if (m_params.reverifyAfterFrames > 0 && m_untrustedFrames >= m_params.reverifyAfterFrames) {
    m_untrustedFrames = 0;
    startVerification(r.phi);
  }
}

TrackResult PhotoModelTracker::track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  Frame f;
  f.left = &left;
  f.right = &right;
  // Verifying a lock: the challenger gets its share of the whole budget, on the whole images; the
  // main search keeps the steady budget when the tracking is steady, else the rest of the whole one.
  const bool verifying = m_verifyLeft > 0 && m_last.state == TrackState::Tracking;
  f.steady = m_steadyFrames >= m_params.steadyAfterFrames;
  f.windowed = f.steady && !verifying && m_params.steadyHueMarginPx > 0;
  if (f.windowed)
    m_fitness.setImages(left, right, steadyWindows());
  else
    m_fitness.setImages(left, right);
  f.hueMs = f.msSinceStart();
  rmga::StereoObjective objective(m_fitness, rmga::StereoObjective::Score::Fitness,
                            m_params.rejectMarginQ < 0 ? -1.0 : m_params.rejectMarginQ * (m_fMax - m_fBackground));
  rmga::StereoObjective coarseObjective(m_fitness, rmga::StereoObjective::Score::Coarse);
  rmga::FrameBudget whole = m_params.budget();
  if (whole.milliseconds > 0) // the hue planes are part of the frame's time
    whole.milliseconds = std::max(0.05, whole.milliseconds - f.hueMs);
  f.mainWhole = verifying ? part(whole, 1.0 - m_params.verifyBudgetFraction, m_params.ga.population) : whole;
  f.budget = f.steady ? m_params.steadyBudget() : f.mainWhole;

  const rmga::FrameResult fr = search(f, objective, coarseObjective);
  TrackResult r;
  r.phi = fr.best;
  r.fitness = fr.fitness;
  r.evaluations = fr.evaluations;
  r.candidates = fr.candidates;
  r.generations = fr.generations;
  if (verifying)
    verify(m_params.coarseSearch ? coarseObjective : objective, part(whole, m_params.verifyBudgetFraction, m_params.ga.population), r);
  const double searchMs = f.msSinceStart() - f.hueMs;
  refine(r, objective, f);
  const double refinedMs = f.msSinceStart();
  r.hMo = core::toHomogeneousMatrix(r.phi);
  r.quality = quality(r.fitness);
  const TrackState prev = m_last.state;
  updateState(r);
  r.steady = f.steady && !f.escalated;
  r.escalated = f.escalated;
  scoreConfidence(r, f);
  if (r.precise && r.trusted) // the scene's colours along the outline, where the pose is trusted
    m_precise->learnColours(r.phi);
  r.computeMs = f.msSinceStart();
  r.stageMs = {f.hueMs, searchMs, refinedMs - f.hueMs - searchMs, r.computeMs - refinedMs};
  m_beforeLast = m_last.phi;
  m_haveBeforeLast = prev == TrackState::Tracking && r.state == TrackState::Tracking;
  m_last = r;
  return r;
}

} // namespace pm::tracker
