#pragma once
/*!
  \file TrackingReport.h
  The figures of a tracking run against its truth, as pm-track reports them (the paper's Table 2):
  when it converged (Convergence.h), each pose variable's errors after convergence (rms, largest,
  largest while moving and at rest) against a goal, the frame time's mean and p99
  (pm::core::percentile), the mean work per frame and the frames in each tracker state.
*/
#include <array>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "pm/capture/StereoSource.h"
#include "pm/core/Pose.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::lab {

//! One tracked frame: its time, its truth when known, and what the tracker made of it.
struct TrackedFrame
{
  double t = 0;            //!< time of the frame from the first (s)
  bool haveTruth = false;  //!< whether \e truth holds the frame's true pose
  bool moving = false;     //!< the target was moving (simulator; false when unknown)
  core::Phi truth{};             //!< the model frame's true pose in the hand frame (mm, quaternion vector)
  tracker::TrackResult result;      //!< the tracker's output for the frame (its estimate: result.phi)
};

//! The errors of one pose variable (x, y, z in mm; eps1..3 unitless) over the frames after convergence.
struct AxisErrors
{
  std::size_t frames = 0;  //!< frames with a truth counted
  double rms = 0;          //!< root mean square of estimate - truth
  double max = 0;          //!< largest |estimate - truth|
  double maxMoving = 0;    //!< ... while the target moved
  double maxAtRest = 0;    //!< ... while it was at rest
  double goal = 0;         //!< the largest error allowed (Table 2's goals by default)
};

//! The figures of a tracking run (see TrackingReport.h).
struct TrackingReport
{
  long convergedFrame = -1;   //!< the frame from which the run converged (-1: never; the errors then cover every frame)
  double convergedS = -1;     //!< its time (s)
  std::array<AxisErrors, 6> errors{}; //!< x, y, z, eps1, eps2, eps3 (only when some frame has a truth)
  bool haveTruth = false;     //!< some frame had a truth
  bool goalsMet = false;      //!< converged, some frame had a truth, and every variable's max within its goal
  double meanMs = 0;          //!< mean TrackResult::computeMs (ms)
  double p99Ms = 0;           //!< its 99th percentile (ms, pm::core::percentile)
  double meanEvaluations = 0; //!< mean TrackResult::evaluations per frame
  std::map<std::string, int> states; //!< frames per tracker state ("searching", "tracking", "lost")
  long preciseFrames = 0;     //!< frames whose pose the precise stage gave (TrackResult::precise)
  /*! \var TrackingReport::positionRmsMm
      \brief rms distance of the estimate's position to the truth over the frames after convergence (mm)
      \var TrackingReport::positionMaxMm
      \brief its largest value (mm)
      \var TrackingReport::rotationRmsDeg
      \brief rms angle between the estimate's rotation and the truth's (deg) */
  double positionRmsMm = 0, positionMaxMm = 0, rotationRmsDeg = 0, rotationMaxDeg = 0; //!< its largest value (deg)
  long trustedFrames = 0;     //!< frames trusted (TrackResult::trusted)
  std::map<std::string, long> heldBy; //!< the frames not trusted, by why (TrackResult::heldBy)
  long rightFrames = 0;       //!< frames whose estimate is within 5 mm and 2 deg of the truth
  long rightTrusted = 0;      //!< ... of them trusted
  long wrongFrames = 0;       //!< frames whose estimate is over 20 mm or 5 deg off
  long wrongTrusted = 0;      //!< ... of them trusted (a robot would have acted on them)
  /*!
    The trusted frames' largest position error against the truth (mm; 0 with none trusted): how close a
    frame the arm would have acted on came to a wrong one (20 mm or 5 deg).
  */
  double trustedMaxMm = 0;
  double trustedMaxDeg = 0; //!< ... and their largest rotation error (deg), each its own maximum
  /*!
    The share of the true errors within the reported 1-sigma, per axis (along the hand's x, y, z, about
    them), over the tracked frames after convergence with a known uncertainty; sigmaFrames of them.
  */
  std::array<double, 6> withinSigma{};
  long sigmaFrames = 0;       //!< frames the shares are over
  //! The names of the pose variables, in the order of \e errors.
  static const std::array<const char *, 6> &names();
};

constexpr double kRightMm = 5;   //!< a right estimate lies within this of the truth (mm) ...
constexpr double kRightDeg = 2;  //!< ... and within this (deg)
constexpr double kWrongMm = 20;  //!< a wrong one lies beyond this (mm) ...
constexpr double kWrongDeg = 5;  //!< ... or beyond this (deg)

//! Estimate less truth along the hand's x, y, z (mm) and about them (deg, the rotation Re Rt^T's theta-u).
std::array<double, 6> handFrameErrors(const core::Phi &estimate, const core::Phi &truth);

//! Table 2's goals: 5, 5, 8 mm on x, y, z; 0.02 on each eps.
std::array<double, 6> table2Goals();

/*!
  The report of \e frames filmed at \e fps (the convergence window is 1 s of frames). A frame is
  within the bounds of convergence when its estimate is within kConvergedMm and kConvergedDeg of
  its truth, or, without a truth, when the tracker is tracking. Throws pm::core::Error for no frames.

  \code
    std::vector<pm::lab::TrackedFrame> frames; // filled while tracking
    const pm::lab::TrackingReport r = pm::lab::reportTracking(frames, 30.0, pm::lab::table2Goals());
    std::cout << "converged after " << r.convergedS << " s, z rms " << r.errors[2].rms << " mm\n";
  \endcode
*/
TrackingReport reportTracking(const std::vector<TrackedFrame> &frames, double fps, const std::array<double, 6> &goals);

/*!
  Writes \e frames as pm-track's frames.csv: a header, then per frame t, the truth (NaN when
  unknown), the estimate, their difference, fitness, quality, state, evaluations, generations,
  compute_ms, moving (0/1), confidence, trusted (0/1), the reported uncertainty
  (writeUncertaintyCells()), the confidence's cues and the steps' times (writeStepCells()), at 8
  significant digits. Throws pm::core::Error when the stream fails.
*/
void writeFramesCsv(std::ostream &out, const std::vector<TrackedFrame> &frames);

//! ",cue_quality,...": the confidence's features (ConfidenceCues::features(), as it weighs them) for a CSV header.
std::string cuesCsvHeader();
//! \e c's features as CSV cells, each preceded by a comma.
void writeCueCells(std::ostream &out, const tracker::ConfidenceCues &c);
//! The uncertainty's columns of a frames.csv: ",sigma_x_mm,sigma_y_mm,sigma_z_mm,sigma_rx_deg,sigma_ry_deg,sigma_rz_deg".
const char *uncertaintyCsvHeader();
//! Its six cells of one frame, each after a comma; empty when the uncertainty is unknown (TrackResult::uncertainty).
void writeUncertaintyCells(std::ostream &out, const precise::PoseUncertainty &u);
//! The frame's steps' times of a frames.csv: ",step_plan_ms,step_search_ms,...,step_apply_ms" (tracker::StepTimes).
std::string stepsCsvHeader();
//! Their seven cells of one frame (ms), each after a comma.
void writeStepCells(std::ostream &out, const tracker::StepTimes &s);

//! What a TrackingReport does not know of the run (for its summary).
struct TrackingRunInfo
{
  std::string source;               //!< where the pairs came from, in words
  std::size_t frames = 0;           //!< frames tracked
  double fps = 30;                  //!< the frame rate (frames per second)
  capture::SourceStats stats;       //!< the source's counts (unreadable pairs, pairing of live cameras)
  bool live = false;                //!< the pairs came from live cameras (summary.json gets their pairing)
  std::string trackerJson;          //!< the tracker's settings (pm::tracker::trackerConfigToJson)
  std::string budget;               //!< the budget per frame, in words (e.g. "800 evaluations")
};

/*!
  pm-track's summary.json of \e report (indented JSON text): source, frames, unreadable pairs,
  convergence, each variable's errors against its goal, frame time, work per frame, states, the
  tracker's settings and, live, the cameras' pairing.
*/
std::string trackingSummaryJson(const TrackingReport &report, const TrackingRunInfo &info);
//! The same figures as text, one line each (what pm-track prints).
std::string trackingSummaryText(const TrackingReport &report, const TrackingRunInfo &info);

} // namespace pm::lab
