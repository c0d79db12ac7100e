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

const std::array<const char *, StepTimes::kCount> &StepTimes::names()
{
  static const std::array<const char *, kCount> n = {"plan", "search", "challenge", "refine", "measure", "judge", "apply"};
  return n;
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

//! q's scale for the model; throws unless the model fits the rig (most of it in every camera's image at the search space's centre).
QualityScale scaleOnRig(const core::CameraRig &rig, const core::StereoFitness &fitness, const core::PhotoModel &model, const TrackerParams &params)
{
  const QualityScale scale(model, params.fitness);
  core::Phi centre;
  for (std::size_t i = 0; i < 6; ++i)
    centre[i] = 0.5 * (params.search.space.lo[i] + params.search.space.hi[i]);
  for (int cam = 0; cam < fitness.scorer().cameraCount(); ++cam) {
    const double visible = fitness.visibleFraction(centre, cam);
    if (visible < 0.5)
      throw core::Error("the photo-model does not fit the rig: at the centre of the search space " + centre.toString() +
                        " only " + std::to_string(static_cast<int>(100 * visible)) + " % of its points fall in the " +
                        (rig[static_cast<std::size_t>(cam)].name.empty() ? "camera " + std::to_string(cam) : rig[static_cast<std::size_t>(cam)].name) +
                        " image (a model too large for the cameras, or made at another scale?)");
  }
  return scale;
}

} // namespace

PhotoModelTracker::PhotoModelTracker(const core::CameraRig &rig, const core::PhotoModel &model, const TrackerParams &params)
    : m_params(resolved(params, model)), m_rig((rig.validate(), rig)), m_fitness(rig, model, params.fitness), m_scale(scaleOnRig(m_rig, m_fitness, model, m_params)),
      m_search(m_params.search, m_fitness.scorer(), m_scale), m_lock(m_params.lock), m_steady(m_params.steady),
      m_verifier(m_params.verifier, m_params.search, m_fitness.scorer(), m_scale),
      m_refinement(m_params.refinement, rig, model, m_fitness.scorer(), m_scale),
      m_judgement(m_params.judgement, m_params.verifier.farDeg, m_fitness.scorer(), m_scale,
                  precise::ModelErrorFloor(model.passLandings, rig[0].hMc, m_params.judgement.uncertainty.modelErrorWidthDeg)),
      m_background(m_params.background, m_fitness.scorer()),
      m_landing(m_params.refinement.precise.landingWidthDeg > 0
                    ? LandingCorrection(model.passLandings, rig[0].hMc, m_params.refinement.precise.landingWidthDeg)
                    : LandingCorrection())
{
  initialize();
}

TrackResult PhotoModelTracker::track(const core::CameraImages &images)
{
  const Clock clock;
  images.checkFor(m_rig, "tracker");
  // What the frame sees (its hue planes, the background's hue) is m_fitness.frame(): made by plan (and
  // by search on an escalation, by completeHue for the judgement), and given to every step that scores.
  const core::HueFrame &hues = m_fitness.frame();
  std::array<double, StepTimes::kCount> at{}; // the clock at the end of each step (ms)
  const FramePlan frame = plan(images, clock);                                   // 1. steady? the hue planes; the budgets
  at[0] = clock.ms();
  RmGaUpdate update;
  const SearchedPose found = search(frame, images, clock);                       // 2. RM-GA (escalated if a steady frame falls)
  at[1] = clock.ms();
  const SearchedPose searched = challenge(frame, found, images, update);        // 3. the lock verifier's challenger, if verifying
  at[2] = clock.ms();
  const bool locked = m_scale.quality(searched.pose.fitness) >= m_params.lock.quality;
  const RefinedPose refined = m_refinement.refine(hues, searched.pose, m_history, images, locked); // 4. the refinement chain
  at[3] = clock.ms();
  completeHue(frame, searched, refined.pose.phi, images);
  const Evidence evidence = m_judgement.measure(hues, refined);                // 5. the judgement's evidence, once
  at[4] = clock.ms();
  update.restart = updateState(refined.pose, evidence);                        // 6. searching, tracking or lost
  const TrackState state = m_lock.state();
  const Verdict verdict = judge(refined, evidence);                            // 7. confidence, trust, uncertainty
  at[5] = clock.ms();
  afterJudgement(refined, verdict, update);                                    // 8. what the parts learn and ask of RM-GA
  const double backgroundHueDeg = m_fitness.backgroundHue();                   // what the frame was scored with
  if (const std::optional<double> hue = m_background.learn(hues, refined.pose.phi, verdict.trusted)) // 9. the background's hue as seen now
    useBackgroundHue(*hue);
  at[6] = clock.ms();
  TrackResult r = assembled(searched, refined, state, verdict, backgroundHueDeg, at);
  m_history.remember(r); // the stage's pose: what the steps read of the last frames
  m_landingTaken = r.precise ? m_landing.inModel(r.phi) : std::array<double, 6>{};
  takeLandingOff(r);
  return r;
}

void PhotoModelTracker::takeLandingOff(TrackResult &r) const
{
  if (r.precise && m_landing.active()) { // the model's own error at the pass's views taken off (moved with the hand since)
    r.phi = LandingCorrection::takenOff(r.phi, m_landingTaken);
    core::toHomogeneousMatrix(r.phi, r.hMo);
  }
}

FramePlan PhotoModelTracker::plan(const core::CameraImages &images, const Clock &clock)
{
  FramePlan frame = m_steady.plan(m_verifier.verifying(m_lock.state()));
  if (frame.windowed)
    m_fitness.setImages(images.data(), m_steady.windows(m_fitness.scorer(), m_history).data());
  else
    m_fitness.setImages(images.data());
  frame.hueMs = clock.ms();
  frame.setBudgets(m_params.search, m_params.steady, m_params.verifier);
  return frame;
}

SearchedPose PhotoModelTracker::search(const FramePlan &frame, const core::CameraImages &images, const Clock &clock)
{
  const PoseSearch::Scoring scoring = m_lock.state() == TrackState::Tracking ? PoseSearch::Scoring::Exact : PoseSearch::Scoring::Coarse;
  const rmga::FrameResult fr = m_search.evolve(m_fitness.frame(), frame.main, scoring); // coarse until tracked
  SearchedPose s;
  s.pose = ScoredPose{fr.best, fr.fitness};
  s.work = SearchWork().plus(fr);
  if (frame.steady && m_steady.escalates(m_scale.quality(fr.fitness))) {
    // The steady frame went wrong: the rest of the whole budget at once, on the whole images.
    s.escalated = true;
    if (frame.windowed)
      m_fitness.setImages(images.data());
    rmga::FrameBudget rest = frame.mainWhole;
    if (rest.evaluations > 0)
      rest.evaluations = std::max<long>(m_params.search.ga.population, rest.evaluations - fr.evaluations);
    else
      rest.milliseconds = std::max(0.05, rest.milliseconds - (clock.ms() - frame.hueMs));
    const rmga::FrameResult more = m_search.evolve(m_fitness.frame(), rest, PoseSearch::Scoring::Exact, PoseSearch::Generations::SameFrame);
    s.pose = ScoredPose{more.best, more.fitness};
    s.work = s.work.plus(more);
  }
  s.steady = frame.steady && !s.escalated;
  return s;
}

SearchedPose PhotoModelTracker::challenge(const FramePlan &frame, const SearchedPose &searched, const core::CameraImages &images,
                                          RmGaUpdate &update)
{
  if (!frame.verifying)
    return searched;
  // The second opinion on an ambiguity: where the precise stage settles (two pointers: no allocation).
  const LockVerifier::Settle settle = [this, &images](const core::Phi &phi) { return m_refinement.settle(phi, images); };
  const LockVerifier::Challenge c = m_verifier.challenge(m_fitness.frame(), frame.challenger, searched.pose, m_search.ga(), settle);
  SearchedPose s = searched;
  s.work = s.work.plus(c.run);
  if (!c.better) {
    if (m_verifier.verified()) // accepted now: this frame's refinement measures with its verification's colours
      m_refinement.lockAccepted();
    return s;
  }
  // A clearly better pose elsewhere (a wrong first lock): the tracker moves there.
  s.pose = *c.better;
  s.switched = true;
  update.reseed = RmGaUpdate::Reseed{c.better->phi, m_params.search.initSpread};
  m_refinement.reset();     // the pose jumped: the tilt filter starts again, the colours learnt aside are forgotten ...
  m_history.forgetMotion(); // ... and so does the motion
  return s;
}

void PhotoModelTracker::completeHue(const FramePlan &frame, const SearchedPose &searched, const core::Phi &phi, const core::CameraImages &images)
{
  if (!frame.windowed || searched.escalated)
    return;
  // The judgement scores on the whole images: the hue under the poses it looks at, where the windows left it out.
  std::array<core::Phi, 9> seen;
  seen[0] = phi;
  const std::size_t n = 1 + m_judgement.competitors(phi, seen.data() + 1);
  m_fitness.addHueUnder(images.data(), seen.data(), n);
}

RmGaUpdate::Restart PhotoModelTracker::updateState(const ScoredPose &pose, const Evidence &evidence)
{
  // A new lock only if it would not be plainly wrong (its confidence as a first, unverified lock).
  const double quality = m_scale.quality(pose.fitness);
  const bool verifiedAtOnce = m_params.verifier.evaluations == 0; // no challenger: a lock is verified as it is taken
  const bool refused = m_params.lock.confidence > 0 && m_lock.wouldLock(quality) &&
                       m_judgement.firstLockConfidence(evidence, m_steady.recentBestQ(), verifiedAtOnce) < m_params.lock.confidence;
  const TrackState prev = m_lock.state();
  const RmGaUpdate::Restart restart = m_lock.update(quality, refused);
  const TrackState state = m_lock.state();
  m_verifier.onState(prev, state, pose.phi, m_search.ga()); // a new lock is verified on the next frames
  m_steady.update(state, quality);
  return restart;
}

Verdict PhotoModelTracker::judge(const RefinedPose &refined, const Evidence &evidence) const
{
  const TrackResult &last = m_history.last();
  JudgedState s;
  s.state = m_lock.state();
  s.last = last.state == TrackState::Tracking ? &last.phi : nullptr;
  s.recentBestQ = m_steady.recentBestQ();
  s.framesTracked = m_lock.framesTracked();
  s.verified = m_verifier.verified();
  s.lookingAgain = m_verifier.lookingAgain();
  return m_judgement.judge(refined, evidence, s);
}

void PhotoModelTracker::afterJudgement(const RefinedPose &refined, const Verdict &verdict, RmGaUpdate &update)
{
  m_lock.onJudged(verdict.confidence, verdict.trusted);
  if (refined.precise) // the precise stage's pose joins RM-GA's population
    update.inject = RmGaUpdate::Inject{refined.pose.phi, refined.pose.fitness};
  if (verdict.trusted) // where the target was last seen for sure: the restarts' anchor
    update.anchor = refined.pose.phi;
  m_search.apply(update); // RM-GA's changes, in one place; the verifier below starts from the population they leave
  m_verifier.afterJudgement(m_lock.state(), verdict.confidence, refined.pose.phi, m_search.ga());
  m_refinement.learn(refined, verdict, {m_lock.state() == TrackState::Tracking, m_verifier.verified(), m_verifier.lookingAgain()});
}

TrackResult PhotoModelTracker::assembled(const SearchedPose &searched, const RefinedPose &refined, TrackState state, const Verdict &verdict,
                                         double backgroundHueDeg, const std::array<double, StepTimes::kCount> &at) const
{
  TrackResult r;
  r.phi = refined.pose.phi;
  r.hMo = core::toHomogeneousMatrix(r.phi);
  r.fitness = refined.pose.fitness;
  r.quality = m_scale.quality(r.fitness);
  r.state = state;
  r.evaluations = searched.work.evaluations;
  r.candidates = searched.work.candidates;
  r.generations = searched.work.generations;
  double *const step[StepTimes::kCount] = {&r.steps.plan, &r.steps.search, &r.steps.challenge, &r.steps.refine,
                                           &r.steps.measure, &r.steps.judge, &r.steps.apply};
  for (std::size_t k = 0; k < StepTimes::kCount; ++k)
    *step[k] = at[k] - (k ? at[k - 1] : 0.0);
  r.computeMs = at.back();
  r.steady = searched.steady;
  r.escalated = searched.escalated;
  r.switched = searched.switched;
  r.ascentEvaluations = refined.ascentEvaluations;
  r.precise = refined.precise;
  r.preciseResult = refined.preciseResult;
  r.uncertainty = verdict.uncertainty;
  r.cues = verdict.cues;
  r.visibleShare = verdict.visibleShare;
  r.backgroundHueDeg = backgroundHueDeg;
  r.confidence = verdict.confidence;
  r.verified = verdict.verified;
  r.trusted = verdict.trusted;
  r.heldBy = verdict.heldBy;
  return r;
}

void PhotoModelTracker::reset(const TrackResult &first)
{
  m_history.reset(first);
  m_landingTaken = {};
  m_lock.reset(first.state);
  m_steady.reset();
  m_verifier.reset(first.verified);
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
  reset(TrackResult()); // searching, nothing verified
}

void PhotoModelTracker::initFromPose(const vpHomogeneousMatrix &hMo)
{
  const core::Phi p = core::fromHomogeneousMatrix(hMo);
  m_search.initFromPose(p);
  TrackResult given;
  given.state = TrackState::Tracking;
  given.verified = true; // a pose given is taken as verified
  given.hMo = hMo;
  given.phi = p;
  reset(given);
}

void PhotoModelTracker::applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev)
{
  if (!hNowMhPrev.isAnHomogeneousMatrix())
    throw core::Error("tracker: the hand motion is not a rigid transformation");
  const auto moved = [&](const core::Phi &p) { return movedWithHand(hNowMhPrev, p); };
  m_search.transform(moved);
  m_verifier.transform(moved);
  m_refinement.transform(hNowMhPrev);
  m_history.transform(hNowMhPrev);
}

} // namespace pm::tracker
