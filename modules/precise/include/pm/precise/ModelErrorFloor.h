#pragma once
/*!
  \file ModelErrorFloor.h
  The model's own error near the camera's direction, as a floor for the pose's 1-sigma: what the
  precise stage's lines cannot see, since it is the model's outline that is off, not the image.
  An all-around model holds where the stage landed on each view of its pass, the pose known
  (core::PassLanding, model::measurePassLandings): a steady offset of 0.1-0.5 deg and 0.1-0.7 mm that
  changes from one view to the next. At a pose, the floor is the root mean square of those offsets
  over the pass's views near the camera's direction (Gaussian weights of \e widthDeg on the angle
  between the directions), turned into the hand frame's axes: the error to expect at that view,
  its sign unknown between the pass's views.

  \code
    const pm::precise::ModelErrorFloor floor(model.passLandings, rig.left.hMc); // 10 deg wide
    if (!floor.empty()) {
      const std::array<double, 6> f = floor.at(phi);  // the model at phi: mm along x, y, z; deg about them (hand frame)
      std::cout << "the model's own error here: " << f[4] << " deg about y\n";
    }
  \endcode
*/
#include <array>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"

namespace pm::precise {

//! Each landing's camera direction seen from the model (unit, model frame; ModelErrorFloor and tracker::LandingCorrection weigh the views by it).
std::vector<std::array<double, 3>> landingDirections(const std::vector<core::PassLanding> &landings);
//! The direction to a camera at \e cameraMm (hand frame, mm) seen from the model at \e phi (hMm), unit, model frame; false when the camera sits at the model's origin.
bool cameraDirectionInModel(const core::Phi &phi, const std::array<double, 3> &cameraMm, double d[3]);

//! The model's error near a view (see the file's description); holds a copy of the landings. at() allocates nothing.
class ModelErrorFloor
{
public:
  /*!
    From \e landings (core::PhotoModel::passLandings; none: empty() and at() gives zeros), the left
    camera at \e hMc in the hand frame (its direction is the view's), weights \e widthDeg wide.
    Throws pm::core::Error unless \e widthDeg is positive.
  */
  ModelErrorFloor(const std::vector<core::PassLanding> &landings, const vpHomogeneousMatrix &hMc, double widthDeg = 10);

  bool empty() const { return m_landings.empty(); } //!< no landings: no floor
  //! At the model's pose \e phi (hMm): the floor per axis, mm along the hand's x, y, z then deg about them.
  std::array<double, 6> at(const core::Phi &phi) const;

private:
  std::vector<core::PassLanding> m_landings;
  std::vector<std::array<double, 3>> m_dirs; //!< each landing's camera direction (unit, model frame)
  std::array<double, 3> m_cameraMm; //!< the camera's centre in the hand frame
  double m_width; //!< rad
};

} // namespace pm::precise
