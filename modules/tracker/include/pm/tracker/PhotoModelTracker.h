#pragma once
/*!
  \file PhotoModelTracker.h
  The photo-model tracker: the pose-estimation feature a ViSP program uses. Give it the stereo
  rig and a photo-model; it finds the target from scratch (initialize()) or from a known pose
  (initFromPose()), then track() takes each new stereo pair and returns hMo, the pose of the
  model in the hand frame, with the fitness and a state.

  State, from the fitness normalised between "the model on background" (0) and "every S_in point
  matches" (1), q = (F - F_bg) / (F_max - F_bg):
  - searching: after initialize(), until q >= lockQuality;
  - tracking: q >= lockQuality was reached; it stays while q >= lostQuality;
  - lost: q < lostQuality for lostFrames frames in a row; the population then restarts (all
    but the best individual new, see RmGa::restart) and searches until q >= lockQuality again.
  Every restart (of a loss, of a stagnant search, of a verification) also searches near the
  last trusted pose, moved with the hand (RmGa::setAnchor): a target lost or jumped is most
  often not far from where it was last seen for sure.

  Trust: "tracking" says the model fits somewhere, not that the pose is right. A new lock is
  verified by a challenger search (TrackerParams::verifyEvaluations), and every frame gets a
  confidence from its cues (TrackConfidence.h); TrackResult::trusted (tracking, verified,
  confidence over its threshold) is what a robot should act on. The confidence's coefficients are
  those of the model's kind (flat, stereo or all-around). With the precise stage (all-around
  models), TrackResult::uncertainty gives the pose's 1-sigma along and about the hand frame's
  axes in mm and deg (PoseUncertainty.h): hold the robot when it exceeds what the task tolerates.

      pm::tracker::PhotoModelTracker tracker(rig, model);
      tracker.initialize();
      for (;;) {
        grab(IL, IR);
        const pm::tracker::TrackResult r = tracker.track(IL, IR);
        if (r.trusted && (!r.uncertainty.known || (r.uncertainty.maxMm() < 2 && r.uncertainty.maxDeg() < 2)))
          use(r.hMo);
      }
*/
#include <chrono>
#include <string>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include <memory>

#include "pm/core/StereoFitness.h"
#include "pm/precise/PoseUncertainty.h"
#include "pm/precise/PreciseStage.h"
#include "pm/rmga/LocalSimplex.h"
#include "pm/rmga/RmGa.h"
#include "pm/rmga/SmoothAscent.h"
#include "pm/rmga/StereoObjective.h"
#include "pm/tracker/TiltFilter.h"
#include "pm/tracker/TrackConfidence.h"

namespace pm::tracker {

/*!
  The tracker's state (see the file's description): Searching after initialize(), until a first
  lock; Tracking while q holds; Lost after lostFrames frames under lostQuality, until a new lock.
*/
enum class TrackState { Searching, Tracking, Lost };
//! The state's name: "searching", "tracking" or "lost".
const char *toString(TrackState s);

//! The fitness the tracker uses: the paper's, except that image pixels less saturated than 0.1
//! have no hue (a blank, grey or black frame would otherwise have hue 0, red, and match a red target).
inline core::FitnessParams trackerFitnessDefaults()
{
  core::FitnessParams f;
  f.minSaturation = 0.1f;
  return f;
}

/*!
  RM-GA as the tracker runs it, by measurement (issues 4 and 18): motion prediction, restarts
  after 30 generations without gain, no refinement of its own (the smooth ascent does it).
*/
inline rmga::RmGaParams trackerGaDefaults()
{
  rmga::RmGaParams g;
  g.predictMotion = true;
  g.refineEvaluations = 0;
  g.restartGenerations = 30;
  return g;
}

/*!
  Everything the tracker can be told. The defaults are the measured ones that every program
  uses (docs/rmga-tracker.md, "Which options"): 800 evaluations per frame, 15 % of them on steady
  frames with the hue within 24 px of the model, locks verified by 3,000 evaluations of a
  challenger; a configuration file (TrackerConfigFile.h) with no keys gives the same.
  PhotoModelTracker copies them; validate() checks them.

  \code
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main()
{
  pm::tracker::TrackerParams params;         // the measured defaults
  params.budgetEvaluations = 0;     // a wall-time budget instead of evaluations:
  params.budgetMs = 30;             // 30 ms of search a frame
  params.ga.seed = 7;               // another random sequence
  params.confidence.threshold = 0.99; // trust fewer frames
  params.validate();                // throws pm::core::Error naming the first value out of range
  pm::tracker::PhotoModelTracker tracker(pm::io::loadRig("rig.json"), pm::io::loadPhotoModel("model.json"), params);
}
  \endcode
*/
struct TrackerParams
{
  rmga::SearchSpace space;            //!< where phi is searched
  rmga::RmGaParams ga = trackerGaDefaults(); //!< RM-GA (population, operators, options, seed)
  core::FitnessParams fitness = trackerFitnessDefaults(); //!< Eqs. (8)-(11)
  long budgetEvaluations = 800; //!< per-frame budget: evaluations (deterministic; a pose rejected early counts its share) ...
  double budgetMs = 24.0;       //!< ... or wall time, used when budgetEvaluations is 0 (the paper: 24 ms)
  /*!
    Early rejection: RM-GA's children that cannot survive (under the worst parent) are scored on
    the first quarter of the model's points only (StereoFitness::evaluate with a threshold), when
    that share's estimate of q lies this much under the threshold's q; otherwise on every point.
    Negative: never (every child scored exactly).
  */
  double rejectMarginQ = 0.15;
  /*!
    Coarse search: while searching or lost, and in the verification's challenger, candidates are
    scored on the first quarter of the model's points (StereoObjective::Score::Coarse: about four
    times as many poses for the same work); the frame's best is then scored on every point.
  */
  bool coarseSearch = true;
  double lockQuality = 0.35;    //!< q at or above which the target is tracked ...
  /*!
    ... when its confidence as a first, unverified lock (TrackConfidence.h) reaches this: a plainly
    wrong pose (a look-alike of similar hue, the toy turned over) keeps the search going instead
    of locking and waiting for a challenger. 0: every pose over lockQuality locks.
  */
  double lockConfidence = 0.05;
  double lostQuality = 0.2;     //!< q below which, for lostFrames frames, it is lost
  int lostFrames = 3;           //!< frames in a row under lostQuality that make a tracked target lost (>= 1)
  double initSpread = 0.02;     //!< initFromPose: population spread, fraction of each range
  /*!
    Steady frames: once the target has been tracked for steadyAfterFrames frames in a row with q
    no more than steadyQualityDrop under its recent best (forgotten at 0.001 per frame), a frame's
    search gets only this fraction of the budget (and the smooth ascent does the fine work); any
    other frame (searching, lost, just locked, q dropping: a jump, an occlusion, a wrong lock) gets
    the whole budget. 1: every frame the same.
  */
  double steadyBudgetFraction = 0.15;
  int steadyAfterFrames = 3;    //!< tracked frames in a row near the recent best q before a frame is steady (>= 1)
  double steadyQualityDrop = 0.03; //!< how far under its recent best q may lie and still count as steady (in q)
  /*!
    A steady frame whose q ends more than steadyQualityDrop under the recent best (the target
    started to move fast, a jump, an occlusion) gets the rest of the whole budget at once, on the
    whole images, instead of waiting for the next frame (TrackResult::escalated).
  */
  bool steadyEscalation = true;
  /*!
    On a steady frame the hue planes are computed only where the model can land: around its
    footprint at the last pose and at the pose its last two frames predict (StereoFitness::
    footprint), grown by this many pixels; elsewhere a point matches nothing. The confidence's
    cues are scored on the whole images all the same (the hue under the poses they look at is
    added, StereoFitness::addHueUnder). 0: always the whole images. A target that moves out of the
    window scores lower, which ends the steadiness: the next frame has the whole images again.
  */
  int steadyHueMarginPx = 24;

  /*!
    Option: after RM-GA, a local continuous search (refineLocalSimplex) of this many evaluations
    of the smooth score (StereoFitness::evaluateSmooth; each costs about 13 evaluations of F,
    pm-bench) from the frame's best, on frames whose q reaches lockQuality, on top of the frame
    budget; the pose it finds is the frame's pose when F there is not lower than at RM-GA's best
    by more than smoothRefineMaxDrop. 0: off (the default: measured, it moves the static and the
    Table 2 errors by a few tenths either way, README).
  */
  int smoothRefineEvaluations = 0;
  double smoothRefineMaxDrop = 0.01; //!< the simplex's pose is kept unless F there is this much under RM-GA's best (F's units)
  rmga::LocalSimplexParams smoothRefine; //!< its first steps (its evaluations: smoothRefineEvaluations)

  /*!
    The top of F's plateau, on every frame whose q reaches lockQuality: a climb of the smooth score
    along its gradient (climbSmooth, StereoFitness::evaluateSmoothGradient; an evaluation costs
    about what one of F does, pm-bench) from RM-GA's best or the last frame's pose, whichever scores
    higher, on top of the frame budget. Its pose is the frame's when F there is not lower than at
    RM-GA's best by more than smoothAscentMaxDrop. smoothAscent.maxEvaluations 0: off.
  */
  rmga::SmoothAscentParams smoothAscent;
  double smoothAscentMaxDrop = 0.02; //!< the climb's pose is kept unless F there is this much under RM-GA's best (F's units)
  /*!
    The precise last stage (PreciseStage.h): on every frame whose q reaches lockQuality, for a model
    that carries outlines (an all-around model of version 5), Gauss-Newton steps on the outline's
    correspondence lines in both cameras (and the interior's colours) from the frame's pose: RM-GA's
    best (after a switch made by the lock's verification), or the last frame's pose when the target
    was tracked and RM-GA's best lies within preciseRestartMm and preciseRestartDeg of it (else from
    both, the lower residual kept; and from RM-GA's best when the last frame's start gives nothing
    acceptable). A result is acceptable when it moved less than preciseMaxMoveMm and
    preciseMaxMoveDeg from its start and F there is not under RM-GA's best by more than
    preciseMaxDropQ (in q). The frame's pose is then the stage's: it seeds RM-GA's population,
    replaces the smooth ascent, and the tilt filter is not applied. Colours are learnt on trusted
    frames. false, or a model without outlines: off (the frame is RM-GA's and the smooth ascent's).
  */
  bool preciseStage = true;
  precise::PreciseParams precise;             //!< the precise stage's parameters (PreciseStage.h)
  double preciseMaxDropQ = 0.02;     //!< the precise pose is kept unless q there is this much under RM-GA's best
  double preciseMaxMoveMm = 12;      //!< ... and it moved less than this from its start (mm) ...
  double preciseMaxMoveDeg = 8;      //!< ... and turned less than this (deg)
  double preciseRestartMm = 8;       //!< RM-GA's best farther than this from the last frame's pose (mm) ...
  double preciseRestartDeg = 4;      //!< ... or turned more than this (deg): the stage starts from both
  /*!
    The tilt of the frame's pose smoothed from frame to frame (TiltFilter: alpha-beta on the
    rotation about the hand's x and y axes, which one viewpoint sees poorly), on tracked frames,
    for a model of one or a few views (flat, a stereo snapshot); alpha 1 and beta 0: off.
  */
  TiltFilterParams tiltFilter;
  /*!
    The same for an all-around model (PhotoModel::isAllAround), whose outline changes with the
    tilt as the toy's does: lighter smoothing. Measured on the main job (pm-servo --all-around,
    C12, seeds 1-5): the one-view filter (alpha 0.2, beta 0.02) lags the tilted steps by 5-6 deg
    and servoed 97 frames on a wrong pose in all; alpha 0.5, beta 0: 17 (docs/all-around-model.md).
  */
  TiltFilterParams tiltFilterAllAround{0.5, 0.0, 5.0};

  /*!
    Verification of a new lock: after the tracker locks (from searching or lost), a challenger
    RM-GA, started from the lock with every other individual new (random, the lock's position
    with another orientation, its orientation elsewhere, its tilt mirrored, facing the cameras;
    see RmGa::restart) and the lock itself kept out of breeding, searches the same frames (on the
    whole images, coarse when coarseSearch) with verifyBudgetFraction of the whole budget; the main
    search has the rest of the whole budget, or its steady budget when the tracking is steady. A
    pose it finds farther than verifyFarMm or verifyFarDeg from the tracker's:
    - scoring over verifySwitchMargin (in q) above it: the tracker moves there (a wrong first
      lock), and verification starts again;
    - within verifySameObjectMm of it and scoring within verifyMargin under it (another pose of
      the same object as good, e.g. the mirrored tilt): ambiguous, verification starts again;
    - otherwise (worse, or a twin elsewhere that scores the same): no objection.
    A lock that lasts verifyEvaluations evaluations of the challenger is verified; 0: off (every
    lock counts as verified).
  */
  long verifyEvaluations = 3000;
  double verifyBudgetFraction = 0.5; //!< the challenger's share of the whole frame budget while verifying, in (0, 1)
  double verifyMargin = 0.02;        //!< in q: a same-object pose elsewhere scoring over the tracker's q minus this is as good (ambiguous)
  double verifySwitchMargin = 0.03;  //!< in q: a challenger's pose this much above the tracker's takes over
  double verifyFarMm = 20;           //!< a challenger's pose farther than this (mm) ...
  double verifyFarDeg = 5;           //!< ... or turned more than this (deg) is elsewhere; confidence competitors turned less are ignored
  double verifySameObjectMm = 60;    //!< a pose elsewhere but within this (mm) is another pose of the same object
  /*!
    A verified lock whose confidence stays under reverifyBelowConfidence this many tracked frames
    in a row is verified again (0: never): a wrong lock that the challenger missed, its confidence
    low. Not at the trust threshold: a right pose of middling confidence (a small budget, an
    occlusion) would be verified over and over, each time with half the frame's budget.
  */
  int reverifyAfterFrames = 15;
  double reverifyBelowConfidence = 0.5; //!< the confidence under which a tracked, verified frame counts toward reverifyAfterFrames
  /*!
    How the frame's confidence is computed from its cues, and its threshold (TrackResult::trusted).
    Its kind Auto (the default): the tracker weighs the cues with the coefficients shipped for its
    model's kind (flat, stereo or all-around); the threshold is this one.
  */
  ConfidenceModel confidence;
  //! From the precise stage's information to the reported 1-sigma per axis (TrackResult::uncertainty).
  precise::UncertaintyModel uncertainty;

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
  //! The whole frame budget: budgetEvaluations evaluations when positive, else budgetMs milliseconds.
  rmga::FrameBudget budget() const { return budgetEvaluations > 0 ? rmga::FrameBudget::evals(budgetEvaluations) : rmga::FrameBudget::ms(budgetMs); }
  //! The budget of a steady frame (see steadyBudgetFraction); never under one population's evaluations.
  rmga::FrameBudget steadyBudget() const;
};

//! What PhotoModelTracker::track() says about a frame (also kept: PhotoModelTracker::lastResult()).
struct TrackResult
{
  vpHomogeneousMatrix hMo;  //!< pose of the model in the hand frame (metres)
  core::Phi phi;                  //!< the same as phi (mm, quaternion vector)
  double fitness = 0;       //!< F at phi
  double quality = 0;       //!< q, the normalised fitness
  TrackState state = TrackState::Searching; //!< the state after this frame
  long evaluations = 0;     //!< the work of RM-GA and the verification, in whole evaluations (see FrameResult)
  long candidates = 0;      //!< poses they scored
  int generations = 0;      //!< RM-GA generations they ran
  double computeMs = 0;     //!< time spent in track()
  /*!
    Where it went (ms): the hue planes; the search (RM-GA, any escalation, the verification); the
    local refinements (the smooth ascent, the tilt filter, the simplex if on); the confidence's cues.
  */
  std::array<double, 4> stageMs{};
  bool steady = false;      //!< the frame had the steady budget (and no more)
  bool escalated = false;   //!< a steady frame whose q fell, given the rest of the whole budget (see TrackerParams::steadyEscalation)
  int smoothEvaluations = 0; //!< evaluations of the smooth score by the local refinement (0: none)
  int ascentEvaluations = 0; //!< evaluations of the smooth score and its gradient by the climb (0: none)
  bool precise = false;      //!< the precise stage's pose is the frame's (TrackerParams::preciseStage)
  precise::PreciseResult preciseResult; //!< what the precise stage found (its lines, residual, information), when it ran
  //! The pose's 1-sigma per axis in mm and deg (PoseUncertainty.h): known when the precise stage's pose is the frame's.
  precise::PoseUncertainty uncertainty;

  ConfidenceCues cues;       //!< what the confidence is computed from
  double confidence = 0;     //!< in (0, 1): how likely the estimate is within 2 cm and 5 deg (see TrackConfidence.h)
  bool verified = false;     //!< the lock survived its challenger search (TrackerParams::verifyEvaluations)
  bool switched = false;     //!< the challenger found a better pose elsewhere this frame and the tracker moved there
  //! Tracking, verified and confidence at or above the threshold: a pose a robot may act on.
  bool trusted = false;
};

/*!
  The photo-model tracker (see the file's description): a stereo pair in, the pose hMo of the
  model in the hand frame out, with its fitness, state and confidence. It copies the parameters
  and what it needs of the rig and the model (none of them need outlive it); the images given to
  track() are only read during the call. Not thread-safe: call it from one thread.

  \code
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");
  pm::tracker::PhotoModelTracker tracker(rig, model); // the default TrackerParams
  tracker.initialize();                      // search from scratch
  for (int k = 0; k < 100; ++k) {
    const vpImage<vpRGBa> IL = pm::io::readColorImage("left_" + std::to_string(k) + ".png");
    const vpImage<vpRGBa> IR = pm::io::readColorImage("right_" + std::to_string(k) + ".png");
    // eye-in-hand: tracker.applyHandMotion(hNowMhPrev) here, when the hand moved since the last frame
    const pm::tracker::TrackResult r = tracker.track(IL, IR);
    std::cout << pm::tracker::toString(r.state) << " q " << r.quality << " confidence " << r.confidence << "\n";
    if (r.trusted) // tracking, verified, confident: a pose to act on
      std::cout << "hMo (m):\n" << r.hMo << "\n";
  }
}
  \endcode
*/
class PhotoModelTracker
{
public:
  /*!
    Throws pm::core::Error if the rig, the model or the parameters are invalid, or if the model does
    not fit the rig (under half of its points in an image at the centre of the search space).
  */
  PhotoModelTracker(const core::StereoRig &rig, const core::PhotoModel &model, const TrackerParams &params = TrackerParams());

  //! Searches from scratch: a random population over the search space (state: searching).
  void initialize();
  //! Starts from a known pose (state: tracking).
  void initFromPose(const vpHomogeneousMatrix &hMo);
  /*!
    One frame: hue planes of the pair, RM-GA within the frame budget, the state. Throws
    pm::core::Error if an image's size differs from its camera's.
  */
  TrackResult track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right);

  /*!
    The hand moved by \e hNowMhPrev (the previous hand frame seen from the current one, from the
    robot's odometry) since the last frame: the population follows, so that a target that did not
    move is still where the search looks (eye-in-hand ego-motion compensation).
  */
  void applyHandMotion(const vpHomogeneousMatrix &hNowMhPrev);

  //! hMo of the last frame, or the one given to initFromPose() (metres); moved by applyHandMotion().
  vpHomogeneousMatrix getPose() const { return m_last.hMo; }
  //! The last frame's F (0 before the first frame).
  double getFitness() const { return m_last.fitness; }
  //! The state after the last frame (Searching after initialize(), Tracking after initFromPose()).
  TrackState getState() const { return m_last.state; }
  //! Everything the last track() returned (reset by initialize() and initFromPose()).
  const TrackResult &lastResult() const { return m_last; }
  //! q of a fitness value for this model.
  double quality(double fitness) const { return (fitness - m_fBackground) / (m_fMax - m_fBackground); }
  //! The model's points at the last pose in camera \e camera's image (0 left, 1 right), each with its score class (for drawing).
  std::vector<core::PointScore> pointScores(int camera) const { return m_fitness.pointScores(m_last.phi, camera); }
  //! The stereo fitness the tracker scores with (its hue planes: those of the last frame).
  const core::StereoFitness &fitness() const { return m_fitness; }
  //! The parameters (the tracker's copy, validated).
  const TrackerParams &params() const { return m_params; }
  //! The tilt filter this model gets: TrackerParams::tiltFilterAllAround for an all-around model, tiltFilter otherwise.
  const TiltFilterParams &tiltFilter() const { return m_allAround ? m_params.tiltFilterAllAround : m_params.tiltFilter; }
  //! True when the precise stage runs (TrackerParams::preciseStage and a model with outlines).
  bool hasPreciseStage() const { return m_precise != nullptr; }
  //! The precise stage (its colour statistics, its last lines); null when off.
  const precise::PreciseStage *preciseStage() const { return m_precise.get(); }

private:
  //! What track() decided about the frame it works on.
  struct Frame
  {
    const vpImage<vpRGBa> *left = nullptr, *right = nullptr;
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    bool steady = false;             //!< the steady budget for the main search
    mutable bool windowed = false;   //!< the hue planes hold only the steady windows
    mutable bool escalated = false;  //!< see TrackResult::escalated
    double hueMs = 0;                //!< the time the hue planes took
    rmga::FrameBudget budget;              //!< the main search's
    rmga::FrameBudget mainWhole;           //!< the main search's when not steady (the whole budget but the challenger's share)
    double msSinceStart() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); }
  };
  //! RM-GA on the frame (coarse while searching), and the escalation of a steady frame that went wrong.
  rmga::FrameResult search(const Frame &f, rmga::StereoObjective &objective, rmga::StereoObjective &coarseObjective);
  //! The local refinements of the frame's pose: the simplex (option), the smooth ascent or the precise stage, the tilt filter.
  void refine(TrackResult &r, rmga::StereoObjective &objective, const Frame &f);
  //! The precise stage on the frame: from r's pose or the last frame's (see TrackerParams::preciseStage); true when its pose is kept.
  bool refinePrecise(TrackResult &r, const Frame &f);
  //! The state machine (with the lock gate), the verification's start, the steadiness.
  void updateState(TrackResult &r);
  //! The cues, the confidence, the trust, the anchor and the re-verification of a doubtful lock.
  void scoreConfidence(TrackResult &r, const Frame &f);
  void resetCounters(); //!< the state machine's and the steadiness's, for a new start
  //! Other poses of the same object the confidence compares \e b with (turned about its z axis, its tilt mirrored).
  static std::array<core::Phi, 8> competitors(const core::Phi &b);
  //! The cues of pose \e phi of quality \e q on this frame's images (\e last: the last frame's pose, when it was tracked); the state's own cues are left to the caller.
  ConfidenceCues cuesAt(const core::Phi &phi, double q, const core::Phi *last) const;
  //! The precise stage's cues of \e r (when its pose is the frame's; \e s: its lines' sigmas, lineSigmas()) into \e c.
  static void addPreciseCues(ConfidenceCues &c, const TrackResult &r, const std::array<double, 6> &s);
  //! A steady frame's hue windows (see TrackerParams::steadyHueMarginPx).
  std::array<core::PixelRect, 2> steadyWindows() const;
  void startVerification(const core::Phi &lock);
  //! Runs the challenger on this frame (objective set on its images); may move \e r to a better pose.
  void verify(rmga::StereoObjective &objective, const rmga::FrameBudget &budget, TrackResult &r);

  TrackerParams m_params;
  core::StereoFitness m_fitness;
  rmga::RmGa m_ga;
  TrackResult m_last;
  core::Phi m_beforeLast;        //!< the pose of the frame before the last (for the steady windows' prediction)
  bool m_haveBeforeLast = false;
  double m_fBackground = 0, m_fMax = 1;
  int m_lowFrames = 0;
  int m_steadyFrames = 0;  //!< frames tracked in a row near the recent best q
  double m_recentBestQ = 0;
  rmga::RmGa m_challenger;       //!< the verification's search (see TrackerParams::verifyEvaluations)
  long m_verifyLeft = 0;   //!< evaluations of verification still to run
  bool m_verified = false;
  int m_framesTracked = 0;
  int m_untrustedFrames = 0; //!< tracked, verified frames in a row under reverifyBelowConfidence
  TiltFilter m_tilt;
  bool m_allAround = false;    //!< the model is an all-around one (PhotoModel::isAllAround)
  std::unique_ptr<precise::PreciseStage> m_precise; //!< null: off
};

} // namespace pm::tracker
