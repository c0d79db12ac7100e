#pragma once
/*!
  \file RunLog.h
  What a closed-loop run leaves behind, in memory that does not grow with the run: the figures
  of the run computed online (convergence, errors at rest and while moving, per tenth of the run,
  joint checks, tracker time) and a decimated record for the plots (at most \e maxSamples
  samples; each keeps the largest errors of the frames it stands for, so no peak is lost).

  (A usage example at the class RunLog.)
*/
#include <array>
#include <map>
#include <string>
#include <cstddef>
#include <vector>

#include <visp3/core/vpColVector.h>

#include "pm/core/Pose.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/lab/Convergence.h"
#include "pm/robot/ArmModel.h"

namespace pm::lab {

//! Error statistics of a set of frames.
struct ErrorStats
{
  std::size_t frames = 0;        //!< frames added
  //! \var sumSquaredMm
  //! Sum of the squared translation errors (mm^2).
  //! \var maxMm
  //! Largest translation error (mm).
  //! \var sumSquaredDeg
  //! Sum of the squared rotation errors (deg^2).
  double sumSquaredMm = 0, maxMm = 0, sumSquaredDeg = 0, maxDeg = 0; //!< largest rotation error (deg)
  void add(double mm, double deg); //!< adds one frame's translation (mm) and rotation (deg) errors
  void add(const ErrorStats &o);   //!< adds the frames of \e o
  double rmsMm() const;            //!< root mean square of the translation errors (mm; 0 without frames)
  double rmsDeg() const;           //!< root mean square of the rotation errors (deg; 0 without frames)
};

//! One plot sample: the first frame of a bucket of frames, with the bucket's largest errors.
struct RunSample
{
  double t = 0;                                        //!< time of the bucket's first frame (s)
  //! Largest translation error over the bucket (LoopFrame::translationErrorMm, mm).
  double translationErrorMm = 0, rotationErrorDeg = 0; //!< largest rotation error over the bucket (LoopFrame::rotationErrorDeg, deg)
  //! The true relative pose (LoopFrame::hMmTrue as a Phi: mm, quaternion vector) at the bucket's first frame.
  core::Phi truth{}, used{};                                 //!< the pose the servo used (LoopFrame::hMmUsed) at the bucket's first frame
  std::array<double, 7> q{};                           //!< the joints at the bucket's first frame (rad)
};

/*!
  The figures and the plot record of a closed-loop run, computed online (see RunLog.h).

  \code
    pm::lab::ClosedLoop loop(rig, scene, sm, tp, sp, lp, makeTc);
    const long n = static_cast<long>(60 * lp.fps) + 1; // one minute
    pm::lab::RunLog log(n, lp.fps, loop.arm().model());
    for (long k = 0; k < n; ++k)
      log.add(loop.step());
    log.finish();
    if (log.converged())
      std::cout << "converged after " << log.convergedAfterS() << " s, then " << log.atRest().rmsMm() << " mm rms at rest" << std::endl;
  \endcode
*/
class RunLog
{
public:
  /*!
    \e expectedFrames: the run's length (sets the decimation and the tenths). More frames are
    accepted: they count in the last tenth, and the samples are merged by pairs when they reach
    twice \e maxSamples, so memory stays bounded. \e arm gives the joint and speed limits.
    Convergence: the true relative pose within \e convergedMm and \e convergedDeg for 1 s.
  */
  RunLog(long expectedFrames, double fps, const robot::ArmModel &arm, std::size_t maxSamples = 4000,
         double convergedMm = kConvergedMm, double convergedDeg = kConvergedDeg);

  //! Takes the run's next frame (in order: the convergence and the tenths count them).
  void add(const LoopFrame &f);
  //! Closes the last bucket and the convergence (a run within the bounds at its very end counts).
  void finish();

  //! The frames added.
  long frames() const { return m_frames; }
  //! The time from which the run stayed within the bounds for 1 s; negative if never.
  double convergedAfterS() const { return m_conv.time(); }
  //! The run converged (convergedAfterS() >= 0).
  bool converged() const { return m_conv.converged(); }
  //! The frames with the target at rest, from convergence on (the whole run if it never converged).
  const ErrorStats &atRest() const { return converged() ? m_rest : m_allRest; }
  //! The frames with the target moving, from convergence on (the whole run if it never converged).
  const ErrorStats &moving() const { return converged() ? m_moving : m_allMoving; }
  //! All frames of each tenth of the expected run (to see a drift).
  const std::array<ErrorStats, 10> &tenths() const { return m_tenths; }
  //! Joints found outside their limits after a frame, counted once per joint and frame.
  int jointLimitViolations() const { return m_violations; }
  //! The largest commanded joint speed over its limit, |qdot_i| / vmax_i, over the run.
  double maxJointSpeedFraction() const { return m_maxSpeedFraction; }
  //! Frames the servo acted on a wrong pose (the pose it used, LoopFrame::wrongUsed()).
  long framesServoedOnWrongPose() const { return m_servoedOnWrong; }
  //! Frames the servo acted while the tracker's raw estimate was wrong (LoopFrame::wrongEstimate()).
  long framesServoedOnWrongRawEstimate() const { return m_servoedOnWrongRaw; }
  //! Frames the arm was held (stopped or stopping: the estimate not usable).
  long framesHeld() const { return m_held; }
  //! The frames held, by why (LoopFrame::heldBy: the tracker's cue, its state, the uncertainty's axis...).
  const std::map<std::string, long> &heldBy() const { return m_heldBy; }
  //! Frames the servo acted on (LoopFrame::servoing).
  long framesServoed() const { return m_servoed; }
  //! The tracker's own estimate against the truth over the tracked frames from convergence on (ErrorStats: rms and max).
  const ErrorStats &estimate() const { return m_estimate; }
  //! Frames whose pose the precise stage gave (TrackResult::precise).
  long framesPrecise() const { return m_precise; }
  //! Frames whose estimate had some of the model hidden (TrackResult::visibleShare under 0.99).
  long framesPartlyHidden() const { return m_partlyHidden; }
  //! The lowest TrackResult::visibleShare of the run (1 without frames).
  double minVisibleShare() const { return m_minVisible; }
  //! The nearest the target came ahead of the hand (the true pose's z, mm; a grasp approach's end).
  double nearestMm() const { return m_nearestMm; }
  /*!
    The tracker's own estimate against the truth over the tracked frames whose target stood within
    \e spanMm of nearestMm() (kept online in 10 mm bands of distance: the bands that start within
    the span), e.g. how well the hand saw the target at the end of a grasp approach.
  */
  ErrorStats estimateNearest(double spanMm = 10) const;
  //! The tracker's mean time per frame (TrackResult::computeMs, ms; 0 without frames).
  double meanComputeMs() const { return m_frames ? m_sumMs / static_cast<double>(m_frames) : 0; }
  //! The decimated record for the plots (the last, partial bucket only after finish()).
  const std::vector<RunSample> &samples() const { return m_samples; }
  //! Frames per sample (it doubles each time the samples are merged by pairs).
  long framesPerSample() const { return m_bucket; }

private:
  void halveSamples();

  long m_expected, m_bucket;
  double m_mm, m_deg;
  vpColVector m_qmin, m_qmax, m_vmax;
  std::size_t m_maxSamples;
  long m_frames = 0;
  // Convergence, online (Convergence.h): the current run of frames within the bounds, and its statistics.
  Convergence m_conv;
  ErrorStats m_runRest, m_runMoving;
  ErrorStats m_rest, m_moving, m_allRest, m_allMoving;
  std::array<ErrorStats, 10> m_tenths{};
  int m_violations = 0;
  double m_maxSpeedFraction = 0, m_sumMs = 0, m_minVisible = 1;
  long m_partlyHidden = 0;
  double m_nearestMm = 1e9;
  std::array<ErrorStats, 200> m_byDistance{}; //!< the tracked frames' estimate errors in 10 mm bands of distance (0 to 2 m)
  long m_servoedOnWrong = 0, m_servoedOnWrongRaw = 0, m_held = 0, m_servoed = 0, m_precise = 0;
  std::map<std::string, long> m_heldBy; //!< the frames held, by why
  ErrorStats m_estimate;
  std::vector<RunSample> m_samples;
  RunSample m_open;
  long m_inBucket = 0;
};

} // namespace pm::lab
