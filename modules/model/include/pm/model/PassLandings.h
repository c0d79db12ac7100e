#pragma once
/*!
  \file PassLandings.h
  The model's own error, view by view, measured on the pass that made it: the hand's pose at each
  view is known (the arm's), so the model's true pose in that view's hand frame is too
  (fMh^-1 fMm); the precise stage (precise::PreciseStage), started there on the view's own pair,
  lands where the model's outline and colours fit the images best. How far it lands from the
  truth is what the model's outline being a little off costs at that view (core::PassLanding):
  0.1-0.5 deg and 0.1-0.7 mm on the lab's toys, and the same, within about 0.1 deg, on other
  renders at the same pose (docs/model-outline.md). The tracker's uncertainty takes it as its floor
  near that view (precise::ModelErrorFloor).

  \code
    const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass); // measures them (AllAroundParams::passLandings)
    for (const pm::core::PassLanding &l : b.model.passLandings)
      std::cout << l.offsetDeg[0] << " " << l.offsetDeg[1] << " " << l.offsetDeg[2] << " deg\n";
  \endcode
*/
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoRig.h"
#include "pm/model/PassView.h"

namespace pm::model {

/*!
  The precise stage's landing on each view of \e pass marked in \e used, for \e model (an all-around
  model with outlines) whose frame is \e fMm in the pass's world frame; a view where the stage finds
  no pose (too few lines) or lands over 20 mm or 10 deg off on an axis (elsewhere: not the model's
  error) gives none. Throws pm::core::Error if the model has no outlines or \e used
  and \e pass differ in size.
*/
std::vector<core::PassLanding> measurePassLandings(const core::StereoRig &rig, const core::PhotoModel &model,
                                                   const std::vector<PassView> &pass, const std::vector<bool> &used,
                                                   const vpHomogeneousMatrix &fMm);

} // namespace pm::model
