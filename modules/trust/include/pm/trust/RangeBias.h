#pragma once
/*!
  \file RangeBias.h
  How far the held-out views' right poses sit from the cameras against the truth (the pass's
  calibration, PassCalibration.h): depth read from the model's size in the images is off by a steady
  share of the range wherever the model's colours and outline are placed a tenth of a pixel off (the
  lab's crab through one camera: 0.27 %, the estimate too far; with the pair 0.08 %). Each right try
  the precise stage made gives its relative range error, (|estimate - c| - |truth - c|) / |truth - c|
  about the rig's cameras' centre c; each view gives the median of its tries, and the bias is the
  median of the views'. It is measured only where at least three views have right tries, all but
  one of them err on the same side as the median, and the median reaches minPct (0.1 %, 0.5 mm at
  500 mm): a bias the views do not agree on is no bias to correct, and under 0.1 % the views and the
  tracked poses disagree in the lab (the head through the pair: +0.05 % on its held-out views, -0.06 %
  at the main job's rest). Where it is corrected (a rig of one camera:
  CalibrationParams::rangeMaxCameras), the tracker scales the precise stage's range by 1 / (1 + bias)
  (tracker::RangeCorrection), and the tries' errors are corrected the same way before the confidence
  and the sigmas are calibrated on them, so that both see the poses the tracker will report.

  \code
      const std::array<double, 3> centre = pm::tracker::cameraCentreMm(rig); // the rig's cameras' centre (mm)
      const pm::trust::RangeBias b = pm::trust::measureRangeBias(tries, centre);
      if (b.measured()) for (pm::trust::PassTry &t : tries) t = pm::trust::rangeCorrected(t, b.scale, centre);
  \endcode
*/
#include <array>
#include <vector>

#include "pm/trust/PassTries.h"

namespace pm::trust {

//! The held-out views' range bias (see RangeBias.h).
struct RangeBias
{
  double errorPct = 0; //!< the median of the views' median relative range errors (%; > 0: the estimates too far)
  int views = 0;       //!< the views with right tries the precise stage made
  int agreeing = 0;    //!< of them, those whose median errs on the side of errorPct
  double scale = 1;    //!< 1 / (1 + errorPct / 100) when measured, else 1
  //! The views agree on a bias (see RangeBias.h): the scale is to be applied.
  bool measured() const { return scale != 1; }
};

//! \e t's relative range error about \e centreMm (hand frame, mm): > 0 when its estimate lies farther from there than the truth.
double relativeRangeError(const PassTry &t, const std::array<double, 3> &centreMm);

/*!
  The bias of \e tries' right ones that the precise stage made (see RangeBias.h), about \e centreMm
  (the rig's cameras' centre, hand frame, mm); at most \e maxPct (%) either way. \e minViews: the
  fewest views with such tries for a bias to be measured; \e minPct (%): the least bias corrected.
*/
RangeBias measureRangeBias(const std::vector<PassTry> &tries, const std::array<double, 3> &centreMm, int minViews = 3, double minPct = 0.1,
                           double maxPct = 2);

//! \e t with its estimate's range about \e centreMm times \e scale: its error, errorMm (the rotation unchanged).
PassTry rangeCorrected(const PassTry &t, double scale, const std::array<double, 3> &centreMm);

} // namespace pm::trust
