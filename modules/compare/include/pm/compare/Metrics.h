#pragma once
/*!
  \file Metrics.h
  How pm-compare scores a tracker on a sequence: per frame, the translation error (mm, between
  the estimated and true model origins) and the rotation error (deg, the angle of
  R_est^T R_true), and the time track() took. Success as in the RBOT benchmark (under 5 cm and
  5 degrees) and a strict one (1 cm and 2 degrees). Recovery after a forced loss: frames from
  the loss's end to the first of 5 frames in a row within the RBOT success.
*/
#include <optional>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::compare {

//! One frame's score of a tracker: scoreFrame() gives the errors, the caller sets ms and valid.
struct FrameScore
{
  //! \var translationMm
  //! Distance between the estimated and true model origins (mm).
  //! \var rotationDeg
  //! Angle of R_est^T R_true (deg).
  double translationMm = 0, rotationDeg = 0, ms = 0; //!< time the tracker's track() took (ms)
  bool valid = false; //!< the tracker claimed a pose
};

//! The errors of \e estimate against \e truth (both hMm); both errors are 1e9 when either is not finite.
FrameScore scoreFrame(const vpHomogeneousMatrix &estimate, const vpHomogeneousMatrix &truth);

/*!
  A tracker's scores on a sequence (summarize()) or on several (pool()); see Metrics.h.

  \code
    std::vector<pm::compare::FrameScore> scores;
    for (std::size_t k = 0; k < s.frames.size(); ++k) {
      const pm::sim::StereoImages im = pm::compare::renderScenarioFrame(scene, rig, s, k);
      const vpHomogeneousMatrix truth = s.frames[k].hMo * oMm; // hMm: the model in the hand frame
      if (k == 0)
        tracker->start({im.left, im.right}, truth);
      const pm::compare::Estimate e = tracker->track({im.left, im.right});
      pm::compare::FrameScore f = pm::compare::scoreFrame(e.hMm, truth);
      f.valid = e.valid;
      scores.push_back(f);
    }
    const pm::compare::Summary sum = pm::compare::summarize(scores, s.lossEnds);
    std::cout << 100 * sum.success5cm5deg << " % within 5 cm and 5 deg" << std::endl;
  \endcode
*/
struct Summary
{
  std::size_t frames = 0;        //!< frames scored
  //! Mean time of track() (ms).
  double meanMs = 0, p99Ms = 0;  //!< 99th percentile of the time of track() (ms)
  //! \var meanTranslationMm
  //! Mean translation error (mm).
  //! \var maxTranslationMm
  //! Largest translation error (mm).
  //! \var meanRotationDeg
  //! Mean rotation error (deg).
  double meanTranslationMm = 0, maxTranslationMm = 0, meanRotationDeg = 0, maxRotationDeg = 0; //!< largest rotation error (deg)
  //! Fraction of frames under kRbotMm and kRbotDeg (RBOT's success: 5 cm and 5 degrees).
  double success5cm5deg = 0, success1cm2deg = 0; //!< fraction of frames under kStrictMm and kStrictDeg (1 cm and 2 degrees)
  double validFraction = 0;      //!< fraction of frames for which the tracker claimed a pose
  //! Per loss event: frames to recover, or nothing if it never did (before the next event).
  std::vector<std::optional<int>> recovery;
  //! The worst recovery (nothing if one never recovered, or if there was no loss).
  std::optional<int> worstRecovery() const;
  //! Some loss event was never recovered from.
  bool neverRecovered() const;
};

//! \var kRbotMm
//! RBOT's success: translation error under this (mm) ...
//! \var kRbotDeg
//! ... and rotation error under this (deg).
//! \var kStrictMm
//! The strict success: translation error under this (mm) ...
constexpr double kRbotMm = 50, kRbotDeg = 5, kStrictMm = 10, kStrictDeg = 2; //!< ... and rotation error under this (deg)
constexpr int kRecoveredRun = 5; //!< recovered: this many frames in a row within RBOT's success

//! Summary of \e frames; \e lossEnds: the first frame after each forced loss.
Summary summarize(const std::vector<FrameScore> &frames, const std::vector<int> &lossEnds = {});

//! Pools the summaries (means weighted by frames, maxima, all the recoveries).
Summary pool(const std::vector<Summary> &parts, const std::vector<std::vector<FrameScore>> &frames);

} // namespace pm::compare
