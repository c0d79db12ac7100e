#pragma once
/*!
  \file TrackConfidence.h
  How much a frame's estimate can be trusted: a logistic model over what the tracker knows of the
  frame (its cues), fitted on a labelled set of frames (pm-confidence) where a frame is wrong when
  its estimate is more than 2 cm or 5 degrees from the truth.

  The cues (ConfidenceCues), each from the tracker's own state, none from the truth:
  - the normalised fitness q of the best pose, and the lower of the two cameras' own q (a pose
    that fits one view only is suspect);
  - in the worse camera, the share of S_in points on the model's hue and the share of S_out
    points on the background (a look-alike toy of another shape fills one but not the other);
  - the tilt of the model from the hand's optical axis (the flat model is biased by the relief
    when tilted: its error grows with the tilt);
  - how far the best stands above competing poses of the same object: the pose turned about the
    model's own z axis by 45, 90, 135 and 180 degrees either way and with its tilt mirrored (a
    toy of nearly symmetric outline, such as the octopus, scores nearly as well turned);
  - how far q lies under its recent best (an occlusion, a drift onto the background);
  - how far the pose jumped since the last frame (the hand's own motion taken out), in mm and deg;
  - how long the target has been tracked, and whether the lock was verified (a challenger search
    after the lock found no better pose elsewhere, see VerifierParams::evaluations);
  - whether the tracker says it is tracking at all;
  - from the precise stage, when its pose is the frame's (all-around models): the rms distance
    between the outline found along its lines and the model's, how well its lines pin the pose
    (the largest 1-sigma of their own covariance, in mm and deg, PoseUncertainty.h), how sharply
    the colours split into target and background along them, and how much the two cameras'
    residuals differ (a pose that fits one camera's outline only).

  Each kind of photo-model has its own coefficients (ConfidenceKind, ConfidenceModel::shipped),
  fitted on labelled runs of that kind: the flat model weighs the tilt (its error grows with the
  tilt, the relief it does not know), the stereo and all-around models do not (they see the
  relief); only the all-around model has the precise stage's cues.

  \code
    pm::tracker::ConfidenceModel m;                 // the shipped coefficients
    const double c = m.confidence(cues);   // in (0, 1)
    if (c >= m.threshold) use(pose);
  \endcode
*/
#include <array>
#include <string>

#include "pm/core/TrustCalibration.h"

namespace pm::tracker {

//! The cues of one frame (see the file's description); the tracker fills them in TrackResult::cues.
struct ConfidenceCues
{
  double quality = 0;        //!< q of the best pose
  double qualityMin = 0;     //!< min(q_left, q_right), each camera's own normalised score
  double inMatchMin = 0;     //!< min over the cameras of the share of S_in points on the model's hue
  double outBackgroundMin = 0; //!< min over the cameras of the share of S_out points on the background
  double tiltDeg = 0;        //!< angle between the model's z axis and the hand's (deg)
  double competitorMargin = 0; //!< q minus the best q of the competing poses (turned about z, tilt mirrored)
  double qualityDrop = 0;    //!< max(0, recent best q - q)
  double jumpMm = 0;         //!< |translation change| since the last frame (mm)
  double jumpDeg = 0;        //!< rotation change since the last frame (deg)
  int framesTracked = 0;     //!< frames in a row in the tracking state, this one included
  bool verified = false;     //!< the lock survived its challenger search
  bool tracking = false;     //!< the state is tracking
  bool precise = false;      //!< the precise stage's pose is the frame's (the cues below are measured)
  /*!
    PreciseResult::residualPx as seen from kPixelCueDistanceMm (times the pose's z / 500): the model's
    outline error is in mm on the target, and its pixels grow as the hand closes in (1.7 times at 300 mm).
  */
  double preciseResidualPx = 0;
  double preciseSigmaMm = 0;    //!< the largest of the lines' own 1-sigma along x, y, z (mm, lineSigmas())
  double preciseSigmaDeg = 0;   //!< the largest of the lines' own 1-sigma about x, y, z (deg)
  double separation = 0;        //!< PreciseResult::separation, in [0, 1]
  double cameraDisagreementPx = 0; //!< |left camera's residual - right camera's| (px, as seen from kPixelCueDistanceMm too)
  //! The distance the pixel cues are stated at (mm): the lab's, where the coefficients were fitted.
  static constexpr double kPixelCueDistanceMm = 500;

  static constexpr std::size_t kFeatures = 18; //!< the number of features
  /*!
    The features the logistic model weighs (the jumps as log1p, the frames capped at 30, then / 30,
    the tilt / 10; the precise stage's: its flag, then the residual, log1p of the sigmas, the
    separation and the disagreement, each 0 when the flag is 0).
  */
  std::array<double, kFeatures> features() const;
  //! The precise stage's features begin here (the flag "precise", then its cues).
  static constexpr std::size_t kFirstPreciseFeature = 13;
  //! Whether feature \e i was measured on this frame: the precise stage's cues only when its pose is the frame's.
  bool measured(std::size_t i) const;
  //! The features' names, in the order of features() ("quality", "quality_min", ..., "tracking").
  static const std::array<const char *, kFeatures> &featureNames();
};

//! The kind of photo-model a confidence model is fitted on; Auto: the tracker's model's own kind.
enum class ConfidenceKind
{
  Auto,      //!< the kind of the tracker's model (PhotoModelTracker's constructor chooses)
  Flat,      //!< the paper's flat model (two photos face-on)
  Stereo,    //!< the stereo snapshot model (relief from the rig's two cameras)
  AllAround, //!< the all-around model (a pass of the hand around the target)
  Custom     //!< the weights as given (a configuration file's)
};

//! "auto", "flat", "stereo", "all-around" or "custom".
const char *toString(ConfidenceKind k);
//! The kind named \e s (as toString()); throws pm::core::Error for another name.
ConfidenceKind confidenceKindFromString(const std::string &s);

/*!
  The logistic model that turns a frame's cues into its confidence, with the threshold of trust.
  The default-constructed model is the shipped one (threshold 0.95); the tracker's is
  JudgementParams::confidence.

  \code
#include <iostream>
#include <pm/tracker/TrackConfidence.h>

int main()
{
  pm::tracker::ConfidenceCues cues; // in a program: TrackResult::cues of the frame
  cues.quality = 0.6;
  cues.qualityMin = 0.55;
  cues.inMatchMin = 0.8;
  cues.outBackgroundMin = 0.9;
  cues.competitorMargin = 0.2;
  cues.framesTracked = 30;
  cues.verified = true;
  cues.tracking = true;
  const pm::tracker::ConfidenceModel m; // the shipped coefficients
  const double c = m.confidence(cues);
  std::cout << "confidence " << c << (c >= m.threshold ? ": trusted" : ": not trusted") << "\n";
}
  \endcode
*/
struct ConfidenceModel
{
  //! Weights of the features, then the bias: confidence = 1 / (1 + exp(-(w . x + b))).
  std::array<double, ConfidenceCues::kFeatures> weights{};
  double bias = 0;        //!< the bias b
  double threshold = 0.5; //!< the confidence from which an estimate is trusted (the constructor sets 0.95)
  /*!
    Whose coefficients these are. Auto (the default): PhotoModelTracker replaces the weights and
    the bias with those shipped for its model's kind (the threshold stays); Custom: as given.
  */
  ConfidenceKind kind = ConfidenceKind::Auto;
  /*!
    Added to each feature before it is weighed: zeros for the shipped reading; a model calibrated from
    its pass moves the cues its camera reads worse at right poses than the lab's (calibrated()).
  */
  std::array<double, ConfidenceCues::kFeatures> shift{};
  /*!
    What a right pose reads, feature by feature, after the shift: the lab's right poses for the
    shipped coefficients (their median), the reference heldBy() measures a frame against.
  */
  std::array<double, ConfidenceCues::kFeatures> reference{};

  //! The flat model's shipped coefficients, kind Auto, threshold 0.95.
  ConfidenceModel();
  /*!
    The coefficients shipped for the model \e kind (Flat, Stereo or AllAround; fitted by
    `pm-confidence --fit`, docs/trust.md), each kind's bias placed so that its operating point is
    the threshold 0.95. The result's kind is \e kind. Throws pm::core::Error for Auto or Custom.
  */
  static ConfidenceModel shipped(ConfidenceKind kind);
  //! The features a model of \e kind weighs (the others' weights are 0): Flat the first 12, Stereo those but the tilt, AllAround also the precise stage's.
  static std::array<bool, ConfidenceCues::kFeatures> featuresUsed(ConfidenceKind kind);
  //! 1 / (1 + exp(-(w . (x + shift) + b))) with x = c.features(), a feature not measured on the frame not shifted: in (0, 1).
  double confidence(const ConfidenceCues &c) const;
  /*!
    The feature that lowers \e c's confidence most below a right pose's: the index j of the most
    negative w_j (x_j + shift_j - reference_j) over the features measured on the frame
    (ConfidenceCues::featureNames() names it; kFeatures when none lowers it).
  */
  std::size_t weakestCue(const ConfidenceCues &c) const;
  //! The name of weakestCue() (ConfidenceCues::featureNames()), or "confidence" when no measured cue reads below a right pose's.
  const char *weakestCueName(const ConfidenceCues &c) const;
  /*!
    These coefficients read through the camera of a model's pass (core::TrustCalibration): its
    cueShifts added to the shift, its confidenceOffset to the bias. Throws pm::core::Error naming a
    cue that is not a feature.
  */
  ConfidenceModel calibrated(const core::TrustCalibration &t) const;
  //! Throws pm::core::Error if a coefficient, shift or reference is not finite or the threshold is outside (0, 1).
  void validate() const;

private:
  struct Blank
  {
  };
  explicit ConfidenceModel(Blank) {} // every weight 0 (shipped() fills them)
};

} // namespace pm::tracker
