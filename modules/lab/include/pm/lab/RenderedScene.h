#pragma once
/*!
  \file RenderedScene.h
  A scene pm-export-scene wrote and another renderer rendered (scripts/cycles/render.py), read back
  as a user's recording: a views folder (the pass), a sequence of stereo pairs, and the truth that a
  user would not have, the toy frame in the hand frame at every frame. The model the pass makes has
  its own frame (AllAroundBuild::fMm, in the pass's world frame), so the truth is given in it by
  truthInModelFrame(). The same scene through our own rasterizer is its peer (lab_views/,
  lab_sequence/): the same poses, our renderer's images.

  \code
    const pm::lab::RenderedScene s = pm::lab::openRenderedScene("scenes/r2_sea");
    const pm::core::StereoRig rig = pm::io::loadRig(s.rigPath);
    const auto pass = pm::io::loadViewsFolder(s.viewsDir, rig, 6);
    const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass);
    const std::vector<pm::core::Phi> truth = s.truthInModelFrame(b.fMm); // frame k's hMm
  \endcode
*/
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"

namespace pm::lab {

//! A rendered scene's files and truth (see RenderedScene.h).
struct RenderedScene
{
  std::string dir;          //!< the scene's folder
  std::string description;  //!< "scene r2_sea (R2 head), another renderer" for reports
  std::string target;       //!< the toy's catalogue code (sim::makeTarget())
  std::string rigPath;      //!< its rig file
  std::string viewsDir;     //!< its pass, a views folder
  std::string leftPattern;  //!< its sequence's left images (a printf pattern from frame 0)
  std::string rightPattern; //!< its right images
  vpHomogeneousMatrix fMo;  //!< the toy frame in the pass's world frame during the pass (metres)
  std::vector<vpHomogeneousMatrix> hMo; //!< the toy frame in the hand frame at each frame of the sequence (metres)

  /*!
    The truth of every frame in the frame of a model built from the pass with its frame at \e fMm
    (AllAroundBuild::fMm): hMm = hMo * fMo^-1 * fMm.
  */
  std::vector<core::Phi> truthInModelFrame(const vpHomogeneousMatrix &fMm) const;
};

/*!
  The scene in folder \e dir: its scene.json, its views/ and sequence/ (the other renderer's), or
  with \e peer the same scene through our own renderer (lab_views/, lab_sequence/). Throws
  pm::core::Error naming what is missing: no scene.json (not a pm-export-scene folder), a scene
  not yet rendered (no views/ or sequence/: run scripts/cycles/render.py), a scene.json that does
  not parse.
*/
RenderedScene openRenderedScene(const std::string &dir, bool peer = false);

/*!
  Where the second renderer's set is kept (scripts/render-cycles.sh): $PM_CYCLES_DIR when set, else
  $HOME/.cache/visp-photomodel/cycles. The folder may not exist (the set not rendered on this machine).
*/
std::string renderedScenesDir();

} // namespace pm::lab
