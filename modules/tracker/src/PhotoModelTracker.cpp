#include "pm/tracker/PhotoModelTracker.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <string>

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

struct PhotoModelTracker::Clock
{
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); }
};

namespace {

//! The parameters validated, the confidence's coefficients those of the model's kind.
TrackerParams resolved(const TrackerParams &params, const core::PhotoModel &model)
{
  params.validate();
  TrackerParams p = params;
  p.judgement = params.judgement.forModel(model);
  return p;
}

//! q's scale for the model; throws unless the model fits the rig (most of it in both images at the search space's centre).
QualityScale scaleOnRig(const core::StereoFitness &fitness, const core::PhotoModel &model, const TrackerParams &params)
{
  const QualityScale scale(model, params.fitness);
  core::Phi centre;
  for (std::size_t i = 0; i < 6; ++i)
    centre[i] = 0.5 * (params.search.space.lo[i] + params.search.space.hi[i]);
  for (int cam = 0; cam < 2; ++cam) {
    const double visible = fitness.visibleFraction(centre, cam);
    if (visible < 0.5)
      throw core::Error("the photo-model does not fit the rig: at the centre of the search space " + centre.toString() +
                        " only " + std::to_string(static_cast<int>(100 * visible)) + " % of its points fall in the " +
                        (cam ? "right" : "left") + " image (a model too large for the cameras, or made at another scale?)");
  }
  return scale;
}

} // namespace

PhotoModelTracker::PhotoModelTracker(const core::StereoRig &rig, const core::PhotoModel &model, const TrackerParams &params)
    : m_params(resolved(params, model)), m_fitness(rig, model, params.fitness), m_scale(scaleOnRig(m_fitness, model, m_params)),
      m_search(m_params.search, m_fitness.scorer(), m_scale), m_lock(m_params.lock), m_steady(m_params.steady),
      m_verifier(m_params.verifier, m_params.search, m_fitness.scorer(), m_scale),
      m_refinement(m_params.refinement, rig, model, m_fitness.scorer(), m_scale),
      m_judgement(m_params.judgement, m_params.verifier.farDeg, m_fitness.scorer(), m_scale,
                  precise::ModelErrorFloor(model.passLandings, rig.left.hMc, m_params.judgement.uncertainty.modelErrorWidthDeg)),
      m_background(m_params.background, m_fitness.scorer())
{
  initialize();
}

TrackResult PhotoModelTracker::track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  const Clock clock;
  // What the frame sees (its hue planes, the background's hue) is m_fitness.frame(): made by plan (and
  // by search on an escalation, by completeHue for the judgement), and given to every part that scores.
  const core::HueFrame &hues = m_fitness.frame();
  const FramePlan frame = plan(left, right, clock);                      // 1. steady? the hue planes; the budgets
  RmGaUpdate update;
  TrackResult r = search(frame, left, right, clock);                     // 2. RM-GA (escalated if a steady frame falls)
  if (frame.verifying)
    challenge(frame, r, update);                                         // 3. the lock verifier's challenger
  const double searchedMs = clock.ms();
  const bool locked = m_scale.quality(r.fitness) >= m_params.lock.quality;
  update.inject = m_refinement.refine(hues, r, m_last, left, right, locked); // 4. the refinement chain
  const double refinedMs = clock.ms();
  r.hMo = core::toHomogeneousMatrix(r.phi);
  r.quality = m_scale.quality(r.fitness);
  completeHue(frame, r, left, right);
  const Evidence evidence = m_judgement.measure(hues, r);                // 5. the judgement's evidence, once
  const TrackState prev = m_lock.state();
  update.restart = updateState(r, evidence);                             // 6. searching, tracking or lost
  judge(r, evidence, prev);                                              // 7. confidence, trust, uncertainty
  m_lock.onJudged(r.confidence, r.trusted);
  if (r.trusted) // where the target was last seen for sure: the restarts' anchor
    update.anchor = r.phi;
  m_search.apply(update);                                                // 8. RM-GA's changes, in one place
  m_verifier.afterJudgement(r.state, r.confidence, r.phi, m_search.ga());
  m_refinement.learn(r);
  r.backgroundHueDeg = m_fitness.backgroundHue(); // what the frame was scored with
  if (const std::optional<double> hue = m_background.learn(hues, r.phi, r.trusted)) // 9. the background's hue as seen now
    useBackgroundHue(*hue);
  r.computeMs = clock.ms();
  r.stageMs = {frame.hueMs, searchedMs - frame.hueMs, refinedMs - searchedMs, r.computeMs - refinedMs};
  m_steady.remember(m_last.phi, prev == TrackState::Tracking && r.state == TrackState::Tracking);
  m_last = r;
  return r;
}

FramePlan PhotoModelTracker::plan(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Clock &clock)
{
  FramePlan frame = m_steady.plan(m_verifier.verifying(m_lock.state()));
  if (frame.windowed)
    m_fitness.setImages(left, right, m_steady.windows(m_fitness.scorer(), m_last.phi));
  else
    m_fitness.setImages(left, right);
  frame.hueMs = clock.ms();
  frame.setBudgets(m_params.search, m_params.steady, m_params.verifier);
  return frame;
}

TrackResult PhotoModelTracker::search(const FramePlan &frame, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Clock &clock)
{
  const PoseSearch::Scoring scoring = m_lock.state() == TrackState::Tracking ? PoseSearch::Scoring::Exact : PoseSearch::Scoring::Coarse;
  rmga::FrameResult fr = m_search.evolve(m_fitness.frame(), frame.main, scoring); // coarse until tracked
  TrackResult r;
  if (frame.steady && m_steady.escalates(m_scale.quality(fr.fitness))) {
    // The steady frame went wrong: the rest of the whole budget at once, on the whole images.
    r.escalated = true;
    if (frame.windowed)
      m_fitness.setImages(left, right);
    rmga::FrameBudget rest = frame.mainWhole;
    if (rest.evaluations > 0)
      rest.evaluations = std::max<long>(m_params.search.ga.population, rest.evaluations - fr.evaluations);
    else
      rest.milliseconds = std::max(0.05, rest.milliseconds - (clock.ms() - frame.hueMs));
    const rmga::FrameResult more = m_search.evolve(m_fitness.frame(), rest, PoseSearch::Scoring::Exact, PoseSearch::Generations::SameFrame);
    fr.best = more.best;
    fr.fitness = more.fitness;
    fr.evaluations += more.evaluations;
    fr.candidates += more.candidates;
    fr.generations += more.generations;
  }
  r.phi = fr.best;
  r.fitness = fr.fitness;
  r.evaluations = fr.evaluations;
  r.candidates = fr.candidates;
  r.generations = fr.generations;
  r.steady = frame.steady && !r.escalated;
  return r;
}

void PhotoModelTracker::challenge(const FramePlan &frame, TrackResult &r, RmGaUpdate &update)
{
  const auto better = m_verifier.challenge(m_fitness.frame(), frame.challenger, r.phi, r.fitness, m_search.ga(), r);
  if (!better)
    return;
  // A clearly better pose elsewhere (a wrong first lock): the tracker moves there.
  r.phi = better->first;
  r.fitness = better->second;
  r.switched = true;
  update.reseed = RmGaUpdate::Reseed{better->first, m_params.search.initSpread};
  m_refinement.reset(); // the pose jumped: the tilt filter and the motion start again
}

void PhotoModelTracker::completeHue(const FramePlan &frame, const TrackResult &r, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  if (!frame.windowed || r.escalated)
    return;
  // The judgement scores on the whole images: the hue under the poses it looks at, where the windows left it out.
  std::array<core::Phi, 9> seen;
  seen[0] = r.phi;
  const std::size_t n = 1 + m_judgement.competitors(r.phi, seen.data() + 1);
  m_fitness.addHueUnder(left, right, seen.data(), n);
}

RmGaUpdate::Restart PhotoModelTracker::updateState(TrackResult &r, const Evidence &evidence)
{
  // A new lock only if it would not be plainly wrong (its confidence as a first, unverified lock).
  const bool refused = m_params.lock.confidence > 0 && m_lock.wouldLock(r.quality) &&
                       m_judgement.firstLockConfidence(evidence, m_steady.recentBestQ(), m_params.verifier.evaluations == 0) <
                           m_params.lock.confidence;
  const TrackState prev = m_lock.state();
  const RmGaUpdate::Restart restart = m_lock.update(r.quality, refused);
  r.state = m_lock.state();
  m_verifier.onState(prev, r.state, r.phi, m_search.ga()); // a new lock is verified on the next frames
  m_steady.update(r.state, r.quality);
  return restart;
}

void PhotoModelTracker::judge(TrackResult &r, const Evidence &evidence, TrackState prev) const
{
  JudgedState s;
  s.last = prev == TrackState::Tracking ? &m_last.phi : nullptr;
  s.recentBestQ = m_steady.recentBestQ();
  s.framesTracked = m_lock.framesTracked();
  s.verified = m_verifier.verified();
  m_judgement.judge(r, evidence, s);
}

void PhotoModelTracker::reset(TrackState state, Start start)
{
  const bool verified = start == Start::Verified;
  m_last = TrackResult();
  m_last.state = state;
  m_last.verified = verified;
  m_lock.reset(state);
  m_steady.reset();
  m_verifier.reset(verified);
  m_refinement.reset();
  useBackgroundHue(m_background.reset());
}

void PhotoModelTracker::useBackgroundHue(double deg)
{
  m_fitness.setBackgroundHue(deg);
  m_refinement.setBackgroundHue(deg);
}

void PhotoModelTracker::initialize()
{
  m_search.initialize();
  reset(TrackState::Searching, Start::Unverified);
}

void PhotoModelTracker::initFromPose(const vpHomogeneousMatrix &hMo)
{
  const core::Phi p = core::fromHomogeneousMatrix(hMo);
  m_search.initFromPose(p);
  reset(TrackState::Tracking, Start::Verified); // a pose given is taken as verified
  m_last.hMo = hMo;
  m_last.phi = p;
}

void PhotoModelTracker::applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (!hNowMhPrev.isAnHomogeneousMatrix())
    throw core::Error("tracker: the hand motion is not a rigid transformation");
  const auto moved = [&](const core::Phi &p) {
    const core::Phi q = core::fromHomogeneousMatrix(hNowMhPrev * core::toHomogeneousMatrix(p));
    return q.isValid() ? q : p;
  };
  m_search.transform(moved);
  m_verifier.transform(moved);
  m_steady.transform(moved);
  m_refinement.transform(hNowMhPrev);
  m_last.hMo = hNowMhPrev * m_last.hMo;
  m_last.phi = core::fromHomogeneousMatrix(m_last.hMo);
}

} // namespace pm::tracker
