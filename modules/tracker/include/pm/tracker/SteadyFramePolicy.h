#pragma once
/*!
  \file SteadyFramePolicy.h
  Steady frames: once the target has been tracked for a few frames in a row with q near its recent
  best, a frame's search gets only a fraction of the budget (the refinement chain does the fine
  work) and its hue planes are computed only where the model can land (the windows around its
  footprint at the last pose and at the pose the last two frames predict). A steady frame whose q
  falls (the target started to move fast, a jump, an occlusion) escalates: the rest of the whole
  budget at once, on the whole images. Any other frame (searching, lost, just locked, q dropping)
  gets the whole budget.

  The policy owns what it decides from: the recent best q (forgotten at 0.001 per frame, and
  remembered through a loss, so that a relock on a wrong pose, of lower q, is not taken for
  steady) and the count of steady frames. The windows' prediction reads the last two poses from the
  tracker's past (PoseHistory.h).

  \code
    pm::tracker::SteadyFramePolicy steady(params.steady);
    const pm::tracker::FramePlan plan = steady.plan(verifying); // before the frame
    const pm::core::CameraImages images(IL, IR);                 // one image per camera
    if (plan.windowed)
      scorer.setImages(frame, images.data(), steady.windows(scorer, history).data());
    else
      scorer.setImages(frame, images.data());
    const pm::rmga::FrameResult r = search.evolve(frame, plan.main, pm::tracker::PoseSearch::Scoring::Exact);
    if (plan.steady && steady.escalates(scale.quality(r.fitness))) // after the steady search: it went wrong
      search.evolve(frame, plan.mainWhole, pm::tracker::PoseSearch::Scoring::Exact, pm::tracker::PoseSearch::Generations::SameFrame);
    steady.update(state, scale.quality(r.fitness));                // after the frame's state
  \endcode
*/
#include <array>

#include "pm/core/HuePlane.h"
#include "pm/core/Pose.h"
#include "pm/core/StereoScorer.h"
#include "pm/tracker/FramePlan.h"
#include "pm/tracker/PoseHistory.h"
#include "pm/tracker/TrackResult.h"

namespace pm::tracker {

//! The steady frames' parameters (see SteadyFramePolicy.h); validate() checks them.
struct SteadyParams
{
  double budgetFraction = 0.15; //!< a steady frame's share of the budget (1: every frame the same)
  int afterFrames = 3;          //!< tracked frames in a row near the recent best q before a frame is steady (>= 1)
  double qualityDrop = 0.03;    //!< how far under its recent best q may lie and still count as steady (in q)
  //! A steady frame whose q ends more than qualityDrop under the recent best gets the rest of the whole budget at once.
  bool escalation = true;
  /*!
    On a steady frame the hue planes are computed only where the model can land (core::StereoScorer::
    footprint at the last and the predicted pose), grown by this many pixels. The confidence's cues are
    scored on the whole images all the same (core::StereoScorer::addHueUnder). 0: always the whole images.
  */
  int hueMarginPx = 24;

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The steady-frame policy (see the file's description).
class SteadyFramePolicy
{
public:
  //! Copies \e params; no frame is steady until the target has been tracked.
  explicit SteadyFramePolicy(const SteadyParams &params) : m_p(params) {}

  //! This frame's plan (budgets not yet set): steady or not, windowed or not; \e verifying: the challenger runs (whole images).
  FramePlan plan(bool verifying) const;
  /*!
    The hue windows of a steady frame in each camera: the model's footprint at the last frame's pose
    and at the pose the last two predict (constant velocity, PoseHistory::beforeLast()), grown.
  */
  std::array<core::PixelRect, core::CameraRig::kMaxCameras> windows(const core::StereoScorer &scorer, const PoseHistory &history) const;
  //! A steady frame whose search ended at \e q must escalate (SteadyParams::escalation).
  bool escalates(double q) const { return m_p.escalation && q < m_recentBestQ - m_p.qualityDrop; }
  //! The recent best q (the confidence's drop is measured from it).
  double recentBestQ() const { return m_recentBestQ; }

  //! After the frame's state: the recent best q and the count of steady frames.
  void update(TrackState state, double q);
  //! A new start: not steady, no recent best.
  void reset();

private:
  SteadyParams m_p;
  int m_steadyFrames = 0;  //!< frames tracked in a row near the recent best q
  double m_recentBestQ = 0;
};

} // namespace pm::tracker
