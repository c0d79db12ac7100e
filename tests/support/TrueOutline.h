#pragma once
// The toy's true outline from a model's viewpoints (the renderer's coverage, supersampled): what a
// perfect model would store. Lets the precise stage's tests tell the stage's own error from the model's.
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/PhotoModel.h"
#include "pm/sim/Scene.h"

namespace pm::test {

/*!
  Replaces the outline points of \e model's viewpoints within \e withinDeg of its front view (its model
  frame at \e oMm in the toy's frame, metres) by the toy's, seen through \e cam at 640 x 480 from the
  viewpoint's camera centre: about 200 points per view where the coverage crosses one half, with the
  outline's normal and the toy's depth just inside. The other viewpoints keep the built outlines (a
  test's poses stay well inside \e withinDeg; rendering all 240 would cost the suite a minute).
*/
void useTrueOutlines(core::PhotoModel &model, const sim::Scene &scene, const vpHomogeneousMatrix &oMm, const vpCameraParameters &cam,
                     double withinDeg = 55);

} // namespace pm::test
