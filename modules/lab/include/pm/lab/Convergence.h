#pragma once
/*!
  \file Convergence.h
  When a run has converged, by one rule that every program uses (pm-track's tracker against the
  truth, pm-servo's arm against the desired pose): the first frame that starts one second of
  frames in a row within 10 mm and 2 deg (kConvergedMm, kConvergedDeg); a run within the bounds
  that reaches the end of the record counts.
*/
namespace pm::lab {

constexpr double kConvergedMm = 10.0; //!< the position bound of convergence (mm)
constexpr double kConvergedDeg = 2.0; //!< the rotation bound of convergence (deg)

/*!
  The convergence rule of Convergence.h, frame by frame: add() each frame's verdict (within the
  bounds or not), finish() at the end of the record.

  \code
    pm::lab::Convergence c(30); // 1 s at 30 fps
    for (long k = 0; k < n; ++k)
      c.add(k, static_cast<double>(k) / 30.0, errMm[k] <= pm::lab::kConvergedMm && errDeg[k] <= pm::lab::kConvergedDeg);
    c.finish();
    if (c.converged())
      std::cout << "converged after " << c.time() << " s (frame " << c.frame() << ")\n";
  \endcode
*/
class Convergence
{
public:
  //! \e windowFrames: how many frames in a row make the run (at least 1; the frame rate for 1 s).
  explicit Convergence(long windowFrames);
  /*!
    Adds frame \e frame at time \e t (s), \e within the bounds or not. Returns true when this frame
    starts a new run of frames within the bounds (before convergence), so that a caller can reset
    what it accumulates over the run.
  */
  bool add(long frame, double t, bool within);
  //! The end of the record: a run within the bounds still open counts.
  void finish();
  bool converged() const { return m_frame >= 0; } //!< whether the run has converged (so far)
  long frame() const { return m_frame; }          //!< the frame that started the converged run (-1: not converged)
  double time() const { return m_t; }             //!< its time (s; -1: not converged)
  long runLength() const { return m_run; }        //!< frames in the current run within the bounds (before convergence)

private:
  long m_window, m_run = 0, m_runFrame = -1, m_frame = -1;
  double m_runT = 0, m_t = -1;
};

} // namespace pm::lab
