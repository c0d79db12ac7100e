#pragma once
/*!
  \file SilhouetteTruth.h
  The pass's silhouettes (AllAroundBuild::silhouettes) against the toy's true outline, which our own
  rasterizer draws at each view's pose: how far each silhouette's edge lies from the toy's (signed,
  positive outside the toy: a cast shadow or its penumbra taken for the target), and the shares of
  the toy's area added and missed. It measures the background subtraction on images our renderer did
  not make (another renderer's soft shadows, RenderedScene.h), where the truth is the same toy at the
  same poses.

  \code
      const pm::lab::SilhouetteTruth t = pm::lab::checkSilhouettes(toyScene, pass, fMo, build, rig);
      std::cout << t.text;
  \endcode
*/
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/StereoRig.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassView.h"
#include "pm/sim/Scene.h"

namespace pm::lab {

//! What checkSilhouettes() found, over every view's two cameras.
struct SilhouetteTruth
{
  double meanPx = 0;        //!< mean signed distance of the silhouettes' edge pixels from the toy's outline (px; positive: outside)
  double rmsPx = 0;         //!< its rms (px)
  double p95OutsidePx = 0;  //!< the 95th percentile of the edge's distance outside the toy (px; 0 when none lies outside)
  double addedShare = 0;    //!< pixels of the silhouettes off the toy, over the toy's pixels
  double missedShare = 0;   //!< pixels of the toy the silhouettes missed, over the toy's pixels
  long edgePx = 0;          //!< edge pixels measured
  std::string text;         //!< one line for the terminal
};

/*!
  The silhouettes of \e build (made from \e pass; each view's left then right) against \e scene's toy
  at \e fMo (the toy in the pass's world frame, metres), seen through \e rig's cameras (pinhole images:
  a lens's silhouettes are in the ideal images, as the builder keeps them). Throws pm::core::Error when
  the build holds no silhouettes for the pass.
*/
SilhouetteTruth checkSilhouettes(const sim::Scene &scene, const std::vector<model::PassView> &pass, const vpHomogeneousMatrix &fMo,
                                 const model::AllAroundBuild &build, const core::StereoRig &rig);

} // namespace pm::lab
