#pragma once
/*!
  \file TrustCalibration.h
  What the pass taught the tracker about trust through the user's own camera (pm::trust),
  as a photo-model carries it (model.json's "trust_calibration"): how its confidence's cues read at
  right poses there, and how its uncertainty's sigmas compare with the true errors there. Plain data:
  pm::trust measures it when the model is made, the tracker reads it (JudgementParams::forModel()).

  The rule it holds: a cue of the image is read relative to what right poses read through this camera.
  Where the pass's held-out views read a cue worse than the worst of the lab's toys do at right poses
  (a soft shadow along the outline raises the precise stage's residual, a soft lens lowers the
  separation), the reading is moved by that difference before it is weighed (cueShifts); a cue the
  pass reads within the lab's range is not moved. The shifts are shrunk together (guard < 1) until no
  wrong pose tried on the pass's images comes near the threshold. Where the shipped confidence itself
  trusts a plainly wrong try there (over 40 mm or 10 deg: a camera through which wrong poses read
  right, as one camera on the head), every confidence is lowered (confidenceOffset on its logit)
  until the highest sits at the guard's ceiling: fewer right frames trusted, no plainly wrong one. The sigmas are widened per axis
  where fewer than 68 % of the held-out views' true errors fall within them (sigmaGain, never under 1).
  Where the held-out views' right poses read the target consistently too far or too near from the
  cameras (the model's colours and outline placed a tenth of a pixel off give a millimetre of depth
  through one camera), the precise stage's pose is moved along the line from the cameras by that share
  of its range (rangeScale), on a rig of as many cameras as the pass was tried on (one: a pair's bias
  is measured, rangeErrorPct, and left to its triangulation).
*/
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace pm::core {

//! The calibration of trust from the pass (see TrustCalibration.h); measured false: none (the shipped confidence and sigmas).
struct TrustCalibration
{
  bool measured = false; //!< made from the pass (false: a model made before it, or without it)
  //! Added to each named feature of the confidence (ConfidenceCues::featureNames()) before it is weighed.
  std::vector<std::pair<std::string, double>> cueShifts;
  //! What the pass's right poses read, per named feature (their median): the reference "why the arm waits" compares a frame with.
  std::vector<std::pair<std::string, double>> rightReadings;
  std::array<double, 6> sigmaGain{1, 1, 1, 1, 1, 1}; //!< the reported 1-sigma per axis (x, y, z, about x, y, z) times this
  double guard = 1;         //!< the share of the measured shifts kept (1: all; less where wrong poses came near the threshold)
  double confidenceOffset = 0; //!< added to the confidence's logit (<= 0; 0 unless the shipped confidence trusted a plainly wrong try)
  //! The precise stage's pose's distance from the cameras' centre times this (1: none; 1 / (1 + the held-out views' range error))
  double rangeScale = 1;
  int rangeCameras = 0;     //!< the cameras of the rig rangeScale was measured through (a rig of another count: not applied; 0: none)
  double rangeErrorPct = 0; //!< the held-out views' range error before it (% of the range; > 0: too far)
  int rangeViews = 0;       //!< the held-out views it was measured on
  int heldOutViews = 0;     //!< the pass's views held out of the models they were tried on
  int rightExamples = 0;    //!< tries that landed right (within 5 mm and 2 deg)
  int wrongExamples = 0;    //!< tries that landed wrong (over 20 mm or 5 deg)
  double auroc = 0;         //!< how well the calibrated confidence tells the two apart (1: perfectly)
  double rightTrusted = 0;  //!< the share of the right tries it would trust (steady, verified)
  double rightTrustedShipped = 0; //!< the same with the shipped confidence
  int wrongTrusted = 0;     //!< wrong tries it would trust (the guard keeps this 0)
  double wrongMaxConfidence = 0; //!< the highest calibrated confidence of a wrong try
  std::array<double, 6> withinSigma{}; //!< the share of the right tries' errors within 1 calibrated sigma, per axis
  double seconds = 0;       //!< what the calibration took (s)
};

} // namespace pm::core
