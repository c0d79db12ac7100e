#pragma once
/*!
  \file LockVerifier.h
  The verification of a lock. "Tracking" says that the model fits somewhere, not that the pose is
  right: after the tracker locks (from searching or lost), a challenger RM-GA, started from the lock
  with every other individual new (random, the lock's position with another orientation, its
  orientation elsewhere, its tilt mirrored, facing the cameras; see rmga::RmGa::restart) and the lock
  itself kept out of breeding, searches the same frames (on the whole images, coarse when
  SearchParams::coarse) with a share of the whole budget. A pose it finds farther than farMm or
  farDeg from the tracker's:
  - scoring over switchMargin (in q) above it: the tracker moves there (a wrong first lock), and
    verification starts again;
  - within sameObjectMm of it and scoring within margin under it (another pose of the same object
    as good, e.g. the mirrored tilt): ambiguous, verification starts again, and lookingAgain() says
    so until the next lock (the frames it holds are "verification_ambiguous", not "verification"),
    unless a second opinion (\e settle: the precise stage's lines, which the hue fitness does not
    see) takes both poses to one peak, within farMm / 2 and farDeg / 2 of each other (through soft
    light the fitness has peaks 5-10 deg apart that score alike: docs/trust.md);
  - otherwise (worse, or a twin elsewhere that scores the same): no objection.
  A lock that lasts \e evaluations evaluations of the challenger is verified. A verified lock whose
  confidence stays under reverifyBelowConfidence for reverifyAfterFrames tracked frames in a row is
  verified again (a wrong lock that the challenger missed, its confidence low).

  The verifier owns the challenger's population, the evaluations still to run, whether the lock is
  verified, whether it is looking again after an ambiguity and the count of doubtful frames.

  \code
    pm::tracker::LockVerifier verifier(params.verifier, params.search, scorer, scale);
    const pm::tracker::LockVerifier::Settle settle = [&](const pm::core::Phi &phi) { return chain.settle(phi, images); }; // a second opinion
    if (verifier.verifying(lastState)) {
      const pm::tracker::LockVerifier::Challenge c = verifier.challenge(frame, plan.challenger, searched.pose, search.ga(), settle);
      work = work.plus(c.run);
      if (c.better)
        moveTo(*c.better); // a wrong first lock
    }
    verifier.onState(prev, state, pose.phi, search.ga());                      // a new lock is verified on the next frames
    verifier.afterJudgement(state, verdict.confidence, pose.phi, search.ga()); // a doubtful lock again
  \endcode
*/
#include <functional>
#include <optional>

#include "pm/core/StereoScorer.h"
#include "pm/rmga/RmGa.h"
#include "pm/rmga/StereoObjective.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/PoseSearch.h"
#include "pm/tracker/QualityScale.h"
#include "pm/tracker/TrackResult.h"

namespace pm::tracker {

//! The lock verifier's parameters (see LockVerifier.h); validate() checks them.
struct VerifierParams
{
  long evaluations = 3000;        //!< evaluations of the challenger a lock must last to be verified (0: every lock verified)
  double budgetFraction = 0.5;    //!< the challenger's share of the whole frame budget while verifying, in (0, 1)
  double margin = 0.02;           //!< in q: a same-object pose elsewhere scoring over the tracker's q minus this is as good (ambiguous)
  double switchMargin = 0.03;     //!< in q: a challenger's pose this much above the tracker's takes over
  double farMm = 20;              //!< a challenger's pose farther than this (mm) ...
  double farDeg = 5;              //!< ... or turned more than this (deg) is elsewhere; confidence competitors turned less are ignored
  double sameObjectMm = 60;       //!< a pose elsewhere but within this (mm) is another pose of the same object
  /*!
    A verified lock whose confidence stays under reverifyBelowConfidence this many tracked frames in
    a row is verified again (0: never). Not at the trust threshold: a right pose of middling
    confidence (a small budget, an occlusion) would be verified over and over.
  */
  int reverifyAfterFrames = 15;
  double reverifyBelowConfidence = 0.5; //!< the confidence under which a tracked, verified frame counts toward reverifyAfterFrames

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The lock verifier (see the file's description). Keeps a reference to the scorer: it must outlive the verifier.
class LockVerifier
{
public:
  //! The challenger: \e search's RM-GA with another seed and no motion prediction, scored by \e scorer.
  LockVerifier(const VerifierParams &params, const SearchParams &search, const core::StereoScorer &scorer, const QualityScale &scale);

  //! The challenger runs this frame: evaluations are left and the last state was tracking.
  bool verifying(TrackState lastState) const { return m_left > 0 && lastState == TrackState::Tracking; }
  //! What a challenger's search made.
  struct Challenge
  {
    rmga::FrameResult run;           //!< its search (its work; its best scored on every point)
    std::optional<ScoredPose> better; //!< a better pose elsewhere, with its F, when the challenger takes over
    bool onePeak = false;            //!< an ambiguity that the second opinion took to the lock's peak (no objection)
  };
  //! A second opinion on a pose: where another cue settles from it (RefinementChain::settle, the precise stage), or nothing.
  using Settle = std::function<std::optional<core::Phi>(const core::Phi &)>;
  /*!
    The challenger's search on \e frame within \e budget, against the tracker's pose \e pose. When it
    takes over, verification starts again from its pose, near \e ga's anchor. \e settle (may be
    empty: no second opinion) is asked only on an ambiguity.
  */
  Challenge challenge(const core::HueFrame &frame, const rmga::FrameBudget &budget, const ScoredPose &pose, const rmga::RmGa &ga,
                      const Settle &settle = nullptr);
  //! After the frame's state: a new lock (\e prev not tracking) is verified on the next frames; a target not tracked is no longer verified.
  void onState(TrackState prev, TrackState state, const core::Phi &pose, const rmga::RmGa &ga);
  //! After the judgement: a verified, tracked lock of low \e confidence for long is verified again.
  void afterJudgement(TrackState state, double confidence, const core::Phi &pose, const rmga::RmGa &ga);

  bool verified() const { return m_verified; } //!< the lock survived its challenger
  /*!
    The verification running now was started again because the challenger found another pose of the
    same object scoring as well as the lock's (ambiguous); false from the next lock, the next start
    for low confidence, or a reset.
  */
  bool lookingAgain() const { return m_lookingAgain; }
  //! The hand moved: a running challenger follows.
  void transform(const std::function<core::Phi(const core::Phi &)> &moved);
  //! A new start: nothing verified, nothing to verify (\e verified: a pose given, taken as verified).
  void reset(bool verified = false);

private:
  //! \e settle takes \e challenger and \e lock to one peak (within farMm / 2 and farDeg / 2); false without \e settle.
  bool onePeak(const core::Phi &challenger, const core::Phi &lock, const Settle &settle) const;
  //! Verification from \e lock: the challenger around it, near \e ga's anchor (\e again: after an ambiguity).
  void start(const core::Phi &lock, const rmga::RmGa &ga, bool again = false);

  VerifierParams m_p;
  bool m_coarse;           //!< the challenger scores its candidates on a quarter of the points (SearchParams::coarse)
  double m_rejectMargin;   //!< else children that cannot survive by this much (F's units) are rejected early (negative: never)
  const core::StereoScorer &m_scorer;
  QualityScale m_scale;
  rmga::RmGa m_challenger;
  long m_left = 0;          //!< evaluations of verification still to run
  bool m_verified = false;
  bool m_lookingAgain = false; //!< the running verification follows an ambiguity (lookingAgain())
  int m_doubtfulFrames = 0; //!< tracked, verified frames in a row under reverifyBelowConfidence
};

} // namespace pm::tracker
