#pragma once
/*!
  \file TiltFilter.h
  A constant-velocity (alpha-beta) filter of the tilt of the tracker's pose, frame after frame.
  One viewpoint sees the tilt of a toy poorly: turning a flat photo-model by two degrees about an
  axis across the view moves its points by a fraction of a pixel, so the fitness changes by a few
  points of a thousand, and each frame's best tilt lands anywhere within a degree or two of the
  truth. The filter smooths the rotation about the hand's x and y axes (the tilt) with gains
  \e alpha (pose) and \e beta (angular velocity); the position and the turn about the hand's z
  axis (the optical axes' direction), which the images pin down, pass as measured. A measurement
  whose tilt lies farther than \e gateDeg from the prediction (a jump, a switch to another pose)
  restarts it.

  \code
      pm::tracker::TiltFilter filter;              // alpha 0.2, beta 0.02
      for (;;) {
        const pm::core::Phi raw = estimate();   // this frame's best pose
        use(filter.update(raw));          // its tilt smoothed
        filter.transform(hNowMhPrev);     // the hand moved (eye-in-hand)
      }
  \endcode
*/
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"

namespace pm::tracker {

//! TiltFilter's gains and gate (alpha 1 and beta 0: off); validate() checks them.
struct TiltFilterParams
{
  double alpha = 0.2;  //!< share of the tilt residual taken each frame (1: no smoothing)
  double beta = 0.02;  //!< share taken into the angular velocity (per frame)
  double gateDeg = 5;  //!< a measurement whose tilt lies farther from the prediction (deg) restarts the filter

  //! alpha 1 and beta 0: the filter passes every pose unchanged.
  bool passesThrough() const { return alpha >= 1 && beta <= 0; }
  void validate() const; //!< throws pm::core::Error unless 0 < alpha <= 1, 0 <= beta < 1 and gateDeg > 0
};

/*!
  The alpha-beta filter of the tilt (see the file's description): a state of one pose and a tilt
  velocity (rad per frame) about the hand's x and y axes.
*/
class TiltFilter
{
public:
  //! Copies and checks \e params (throws pm::core::Error if invalid); no state until the first update().
  explicit TiltFilter(const TiltFilterParams &params = TiltFilterParams());
  //! This frame's pose \e measured (valid); returns it with its tilt filtered.
  core::Phi update(const core::Phi &measured);
  //! Forgets the past: the next update passes its pose and starts from it.
  void reset() { m_has = false; }
  //! The hand moved by \e hNowMhPrev (the previous hand frame seen from the current one).
  void transform(const vpHomogeneousMatrix &hNowMhPrev);
  //! True once update() has a pose to predict from (never when the filter passes through).
  bool hasState() const { return m_has; }

private:
  TiltFilterParams m_p;
  bool m_has = false;
  core::Phi m_pose;          //!< the last output
  double m_w[2] = {0, 0}; //!< tilt velocity (rad per frame) about the hand's x and y axes
};

} // namespace pm::tracker
