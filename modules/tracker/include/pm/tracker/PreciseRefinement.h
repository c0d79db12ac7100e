#pragma once
/*!
  \file PreciseRefinement.h
  The refinement chain's first stage: the precise stage (precise::PreciseStage: Gauss-Newton steps
  on the outline's correspondence lines in both cameras, and the interior's colours) on every frame
  whose q reaches the lock, for a model that carries outlines (an all-around model). It starts from
  the frame's pose (RM-GA's best, or the pose the lock verifier moved to), or from the pose the last
  frames predict (MotionPrediction.h: the last frame's pose moved on by its step) when the target was
  tracked and the frame's pose lies within restartMm and restartDeg of it
  (else from both, the lower residual kept; and from the frame's pose when the last frame's start
  gives nothing acceptable).

  Its acceptance rule: a result is kept when it moved less than maxMoveMm and maxMoveDeg from its
  start and F there is not under the frame's F by more than maxDropQ (in q): the outline's peak lies
  on F's plateau, a divergence (colours that do not separate, a wrong start) leaves it. A kept pose
  is final: the chain ends with it, and it joins RM-GA's population. Colours are learnt on trusted frames (a new lock's aside until it is verified).

  \code
    pm::tracker::PreciseRefinement stage(params.refinement.precise, rig, model, scorer, scale);
    const pm::tracker::PreciseRefinement::Attempt a = stage.refine(frame, searched, history, motion.predict(history), {IL, IR});
    if (a.kept) {
      pm::tracker::RmGaUpdate u;
      u.inject = pm::tracker::RmGaUpdate::Inject{a.pose.phi, a.pose.fitness}; // the frame's pose is the stage's: it joins RM-GA
      search.apply(u);
    }
  \endcode
*/
#include <memory>
#include <optional>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoScorer.h"
#include "pm/core/CameraImages.h"
#include "pm/core/CameraRig.h"
#include "pm/precise/PreciseStage.h"
#include "pm/tracker/QualityScale.h"
#include "pm/tracker/FrameSteps.h"
#include "pm/tracker/RangeCorrection.h"
#include "pm/tracker/PoseHistory.h"

namespace pm::tracker {

//! The precise stage's place in the chain: on or off, the stage's own parameters, its acceptance rule and its restarts.
struct PreciseRefinementParams
{
  bool enabled = true;             //!< false, or a model without outlines: the chain goes on to the ascent
  precise::PreciseParams stage;    //!< the precise stage's parameters (PreciseStage.h); its hidden lines follow the fitness's stereo visibility

  double maxDropQ = 0.02;          //!< the precise pose is kept unless q there is this much under the frame's ...
  double maxMoveMm = 12;           //!< ... and it moved less than this from its start (mm) ...
  double maxMoveDeg = 8;           //!< ... and turned less than this (deg)
  double restartMm = 8;            //!< the frame's pose farther than this from the last frame's (mm) ...
  double restartDeg = 4;           //!< ... or turned more than this (deg): the stage starts from both
  /*!
    The stage looks for lines and interior points hidden by something in front (precise::StereoOcclusion,
    on with the fitness's stereo visibility) only on frames where the fitness finds less than this
    share of the model's points visible at the search's pose: an occluder hides a few percent of them
    or more (the strand 11 %), a clear view at most about 1 % (at wrong poses too), where looking
    dropped lines at a wrong first lock and delayed the right one.
  */
  double lookForHiddenBelow = 0.95;
  /*!
    The reported pose less the model's own error at the pass's views (LandingCorrection.h), their
    weights this wide (deg) on the angle between the camera's direction and each view's; 0: the
    stage's pose as it landed. A model without pass landings (flat, stereo, older files) is not
    corrected.
  */
  double landingWidthDeg = 4;
  /*!
    A new lock's frame, before the verifier accepts it, teaches the colours aside (kept once it is
    accepted: RefinementChain::learn) only when its confidence reads at least this; one under it
    forgets what was aside. A lock that the confidence itself finds more likely wrong than right
    teaches nothing (the right locks' verification frames read 0.66-0.99 through Cycles and the lab).
  */
  double learnAsideMinConfidence = 0.5;

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The chain's precise stage (see the file's description). Keeps a reference to the fitness: it must outlive the stage.
class PreciseRefinement
{
public:
  //! The stage runs when \e params.enabled and \e model has outlines (core::PhotoModel::hasContours); its poses' range as \e model's pass measured it on \e rig.
  PreciseRefinement(const PreciseRefinementParams &params, const core::CameraRig &rig, const core::PhotoModel &model,
                    const core::StereoScorer &scorer, const QualityScale &scale);

  //! What the stage made of a frame.
  struct Attempt
  {
    precise::PreciseResult result; //!< what it found, kept or not
    ScoredPose pose;               //!< the kept pose (the stage's, its range corrected: RangeCorrection.h) and its F (when kept)
    bool kept = false;             //!< the acceptance rule keeps it: the frame's pose is the stage's
  };

  bool active() const { return m_stage != nullptr; } //!< the stage runs
  /*!
    Refines \e searched (a locked frame's pose) on the images (\e frame: their hues, for F), from it
    or, when the last frame (\e history.last()) was tracked by the stage, from \e predicted (the last
    pose moved on by the target's motion, or the last pose itself).
  */
  Attempt refine(const core::HueFrame &frame, const ScoredPose &searched, const PoseHistory &history, const core::Phi &predicted,
                 const core::CameraImages &images);
  /*!
    Where the stage settles from \e start on \e images (from afar: every scale; not looking for hidden
    lines), or nothing when it finds no result. For a second opinion on a pose (the lock verifier's
    ambiguities), not a frame's pose: neither the acceptance rule nor the range correction applies.
  */
  std::optional<core::Phi> settle(const core::Phi &start, const core::CameraImages &images);
  //! The scene's colours along the outline at \e phi, a trusted pose as the stage found it (precise::PreciseStage::learnColours).
  void learnColours(const core::Phi &phi) { m_stage->learnColours(phi, m_lookedForHidden); }
  /*!
    The same, kept aside until takeColoursLearntAside() (precise::PreciseStage::learnColoursAside),
    for a pose not yet known right, of confidence \e confidence: under
    PreciseRefinementParams::learnAsideMinConfidence, what was aside is forgotten instead.
  */
  void learnColoursAside(const core::Phi &phi, double confidence)
  {
    if (confidence >= m_p.learnAsideMinConfidence)
      m_stage->learnColoursAside(phi, m_lookedForHidden);
    else
      m_stage->dropColoursLearntAside();
  }
  //! The colours learnt aside become the ones in use (none: nothing changes).
  void takeColoursLearntAside()
  {
    if (m_stage)
      m_stage->takeColoursLearntAside();
  }
  //! The colours learnt aside are forgotten.
  void dropColoursLearntAside()
  {
    if (m_stage)
      m_stage->dropColoursLearntAside();
  }
  //! The background's hue the stage's hidden lines compare with (deg): the fitness's (BackgroundLearning).
  void setBackgroundHue(double deg)
  {
    if (m_stage)
      m_stage->setBackgroundHue(deg);
  }
  const precise::PreciseStage *stage() const { return m_stage.get(); } //!< the stage (its colours, its last lines); null when off

private:
  PreciseRefinementParams m_p;
  const core::StereoScorer &m_scorer;
  QualityScale m_scale;
  RangeCorrection m_range;        //!< the kept pose's range corrected as the pass measured it (never changed)
  bool m_lookedForHidden = false; //!< the last refine() looked for hidden lines (the fitness found part of the target hidden)
  std::unique_ptr<precise::PreciseStage> m_stage;
};

} // namespace pm::tracker
