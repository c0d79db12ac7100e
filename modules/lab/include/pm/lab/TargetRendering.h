#pragma once
/*!
  \file TargetRendering.h
  pm-render's runner: what each camera of the rig (one or more) sees of a simulated target at a
  pose, how long the renderer takes for it, and its relief seen from three sides; then the pictures and the summary
  of one or several targets (a gallery for several).

  \code
      const pm::core::StereoRig rig = pm::io::loadRig("data/rig/pa10_stereo.json");
      const pm::sim::TargetShape shape = pm::sim::makeTarget("C12");
      const pm::sim::Scene scene(shape);
      const pm::lab::RenderedTarget t = pm::lab::renderTarget(scene, shape, rig, pm::core::Phi{0, 0, 500, 0, 0, 0}, 5);
      pm::lab::writeRenderedTargets("render", {t}, pm::core::Phi{0, 0, 500, 0, 0, 0}, pm::sim::SceneParams(), false);
  \endcode
*/
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "pm/core/Pose.h"
#include "pm/core/CameraRig.h"
#include "pm/sim/Scene.h"

namespace pm::lab {

//! One target as pm-render shows it.
struct RenderedTarget
{
  std::string code;             //!< "C12", or "user" for a target made from an image
  std::string name;             //!< its name ("crab")
  std::vector<std::string> cameras;     //!< the rig's cameras' names, in order
  std::vector<vpImage<vpRGBa>> views;   //!< each camera's view at the pose (the last of the timed renders)
  vpImage<vpRGBa> turned[3];    //!< the first camera's view with the toy turned about y by eps2 = -0.3, 0, +0.3
  double renderStereoMs = 0;    //!< mean time of one frame of every camera of the rig (ms)
  double nominalSizeMm[3] = {0, 0, 0}; //!< the catalogue's width, height and depth (mm)
  double measuredOutlineMm[2] = {0, 0}; //!< the outline's measured width and height (mm)
  std::size_t triangles = 0;    //!< triangles in the toy's mesh
};

/*!
  Renders \e scene (whose toy is \e shape) seen by \e rig with the toy at \e phi in the hand frame,
  \e repeat times (frames 0..repeat-1, timed), then the first camera's view with the toy turned.
  \e step(n) is called as work is done: repeat + 2 steps in all. Throws pm::core::Error.
*/
RenderedTarget renderTarget(const sim::Scene &scene, const sim::TargetShape &shape, const core::CameraRig &rig, const core::Phi &phi,
                            int repeat, const std::function<void(std::size_t)> &step = {});

/*!
  Writes each target's view of each camera, \<code\>_\<camera\>.png (a stereo rig: _left.png,
  _right.png), all of them side by side and labelled (\<code\>_stereo.png for a stereo rig,
  _views.png otherwise), _relief.png, with \e gallery a gallery.png of their first camera's views
  (four a row), and summary.json (the pose, the
  scene's settings \e sp, each target's sizes and render time) into \e dir. Returns the mean
  render time over the targets (ms). Throws pm::core::Error; on an error nothing is left in \e dir.
*/
double writeRenderedTargets(const std::string &dir, const std::vector<RenderedTarget> &targets, const core::Phi &phi,
                            const sim::SceneParams &sp, bool gallery);

} // namespace pm::lab
