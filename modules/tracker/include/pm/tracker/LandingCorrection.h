#pragma once
/*!
  \file LandingCorrection.h
  The precise stage's pose brought back by the model's own error at the pass's views near the
  camera's direction. An all-around model holds where the stage landed on each view of its pass, the
  pose known (core::PassLanding): a steady offset of 0.1-0.7 deg and 0.1-0.6 mm that changes from one
  view to the next, and that the stage makes again whenever it sees the target from that view (the
  main job at rest, whose relative pose is the pass's first view: over ten noise seeds of the crab's
  pass, the rest error's size follows the first view's landing with a correlation of 0.90). The
  correction is the landings' offsets weighted by a Gaussian of \e widthDeg on the angle between the
  camera's direction and each view's, not normalised below one: whole at a view of the pass, fading
  to nothing between views (where the offsets' signs are not known), taken off the pose in the hand
  frame. A value: made once from the model, never changed; at() and corrected() allocate nothing.

  \code
      const pm::tracker::LandingCorrection landing(model.passLandings, rig[0].hMc); // 4 deg wide
      const pm::core::Phi phi = landing.corrected(stage.refine(start).phi);        // what the tracker reports
  \endcode
*/
#include <array>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"

namespace pm::tracker {

/*!
  Takes the model's own error at the pass's views off a pose (see LandingCorrection.h).
  \code
  const pm::tracker::LandingCorrection none;                              // poses unchanged
  const pm::tracker::LandingCorrection landing(model.passLandings, hMc);  // the left camera's place on the hand
  const std::array<double, 6> e = landing.at(phi); // mm along the hand's x, y, z; deg about them
  \endcode
*/
class LandingCorrection
{
public:
  //! No correction.
  LandingCorrection() = default;
  /*!
    From \e landings (none: no correction), the camera they were measured through at \e hMc on the
    hand, weights \e widthDeg wide. Throws pm::core::Error unless \e widthDeg is positive.
  */
  LandingCorrection(const std::vector<core::PassLanding> &landings, const vpHomogeneousMatrix &hMc, double widthDeg = 4);
  //! The model's error expected at \e phi (hMm): mm along the hand's x, y, z, then deg about them (zeros: none).
  std::array<double, 6> at(const core::Phi &phi) const;
  //! The same in the model frame's axes (mm, deg): what at() turns into the hand frame.
  std::array<double, 6> inModel(const core::Phi &phi) const;
  //! \e phi less at(phi): the origin moved back, the rotation turned back, both in the hand frame.
  core::Phi corrected(const core::Phi &phi) const { return takenOff(phi, inModel(phi)); }
  /*!
    \e phi less the model-frame error \e mModel (inModel()'s, of this or an earlier pose): hMm times a
    fixed motion of the model, so that a pose moved with the hand (hN hMm) is corrected into hN times
    the corrected pose, exactly.
  */
  static core::Phi takenOff(const core::Phi &phi, const std::array<double, 6> &mModel);
  bool active() const { return !m_landings.empty(); } //!< landings to correct by

private:
  std::vector<core::PassLanding> m_landings;
  std::vector<std::array<double, 3>> m_dirs; //!< each landing's camera direction (unit, model frame)
  std::array<double, 3> m_cameraMm{0, 0, 0}; //!< the camera's centre in the hand frame
  double m_width = 1;                        //!< rad
};

} // namespace pm::tracker
