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

struct FrameScore
{
  double translationMm = 0, rotationDeg = 0, ms = 0;
  bool valid = false; //!< the tracker claimed a pose
};

//! The errors of \e estimate against \e truth (both hMm).
FrameScore scoreFrame(const vpHomogeneousMatrix &estimate, const vpHomogeneousMatrix &truth);

struct Summary
{
  std::size_t frames = 0;
  double meanMs = 0, p99Ms = 0;
  double meanTranslationMm = 0, maxTranslationMm = 0, meanRotationDeg = 0, maxRotationDeg = 0;
  double success5cm5deg = 0, success1cm2deg = 0; //!< fractions of frames
  double validFraction = 0;
  //! Per loss event: frames to recover, or nothing if it never did (before the next event).
  std::vector<std::optional<int>> recovery;
  //! The worst recovery (nothing if one never recovered, or if there was no loss).
  std::optional<int> worstRecovery() const;
  bool neverRecovered() const;
};

constexpr double kRbotMm = 50, kRbotDeg = 5, kStrictMm = 10, kStrictDeg = 2;
constexpr int kRecoveredRun = 5;

//! Summary of \e frames; \e lossEnds: the first frame after each forced loss.
Summary summarize(const std::vector<FrameScore> &frames, const std::vector<int> &lossEnds = {});

//! Pools the summaries (means weighted by frames, maxima, all the recoveries).
Summary pool(const std::vector<Summary> &parts, const std::vector<std::vector<FrameScore>> &frames);

} // namespace pm::compare
