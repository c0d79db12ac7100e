#pragma once
/*!
  \file Scenario.h
  The sequences pm-compare runs every tracker on: per frame, where the target is (the toy's
  frame in the hand frame, the PA-10 held still) and what happens to the images.
  - table2: the 20 steps of the paper's Table 2 (hold 1.5 s, move 1 s), as pm-track;
  - sinusoid: x, y and a turn about the optical axis, sines of 0.5 and 0.25 Hz;
  - fast: moves of 80 mm in 0.25 s (peak 600 mm/s, about 30 px per frame);
  - occlusion: a strand of seaweed in front of the toy for 4 s while it moves slowly;
  - lighting: the exposure falls to 0.4 and rises to 1.5 while the light swings from the
    upper left to the right;
  - loss: the frames go blank for 0.5 s while the target moves 60 mm, then later the target
    jumps 50 mm and 8 degrees from one frame to the next.
  On request only (allScenarioNames()):
  - random6dof: a random smooth 6-DoF motion, rotations up to 45 deg;
  - still-backdrop: the target sways and turns in front of a backdrop that stands still 50 mm
    farther back, so that the background slides behind its outline;
  - clutter: the slow sway with three other toys around the target, one of similar hue (the scene
    must be made with sim::SceneParams::clutter on: Comparison does so);
  - grasp: the target comes from 500 to 300 mm in front of the hand (a grasp approach seen from the
    hand) with the gripper's fingers in view.
*/
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>

#include "pm/core/Pose.h"
#include "pm/core/StereoRig.h"
#include "pm/rmga/SearchSpace.h"
#include "pm/sim/Scene.h"

namespace pm::compare {

//! One frame of a Scenario: where the target is and what happens to the images.
struct ScenarioFrame
{
  vpHomogeneousMatrix hMo;   //!< the toy's frame in the hand frame (metres)
  bool moving = false;       //!< the target is moving (every frame of the timed scenarios; the blank frames of loss)
  bool blank = false;        //!< the camera delivers black frames
  bool occluded = false;     //!< the seaweed is in front of the toy
  double exposure = 1.0;     //!< the scene's exposure, a global brightness gain (sim::SceneParams::exposure)
  double lightX = -0.35;     //!< x of the direction toward the light (hand frame; y -0.6, z -1)
  bool stillBackdrop = false; //!< the backdrop stands still where it stood at the first frame, farther back
  bool clutter = false;      //!< other toys stand around the target (sim::SceneParams::clutter)
  bool gripper = false;      //!< the gripper's fingers on the hand are in view (sim::SceneParams::gripper)
};

/*!
  A sequence pm-compare runs every tracker on (see Scenario.h for the list), made by
  makeScenario() or makeScenarios().

  \code
    const std::vector<pm::compare::Scenario> seqs =
        pm::compare::makeScenarios(pm::compare::scenarioNames(), "data/trajectories/table2.csv");
    for (const pm::compare::Scenario &s : seqs)
      for (std::size_t k = 0; k < s.frames.size(); ++k) {
        const pm::sim::StereoImages im = pm::compare::renderScenarioFrame(scene, rig, s, k);
        const vpHomogeneousMatrix hMmTrue = s.frames[k].hMo * oMm; // oMm: the model frame in the toy's frame
        // track im.left, im.right at t = k / s.fps and score against hMmTrue
      }
  \endcode
*/
struct Scenario
{
  //! The scenario's name (one of allScenarioNames()).
  std::string name, description; //!< what happens in it, in one line
  double fps = 30;           //!< frame rate (frames per second)
  std::vector<ScenarioFrame> frames; //!< the frames, one every 1 / fps seconds
  std::vector<int> lossEnds; //!< first frame after each forced loss (blank frames end, the jump)
};

//! The scenarios' names, in the order pm-compare runs them by default.
const std::vector<std::string> &scenarioNames();
//! Those and the ones run on request only: random6dof, still-backdrop, clutter, grasp (see Scenario.h).
const std::vector<std::string> &allScenarioNames();

/*!
  The scenario \e name (one of allScenarioNames()); \e table2 are the waypoints of Table 2;
  \e steps > 0 keeps only the first steps of table2. Throws pm::core::Error for an unknown name.
*/
Scenario makeScenario(const std::string &name, const std::vector<core::Phi> &table2, int steps = 0);
//! The scenarios \e names, Table 2's waypoints read from \e table2Path (step,x,y,z,e1,e2,e3). Throws pm::core::Error.
std::vector<Scenario> makeScenarios(const std::vector<std::string> &names, const std::string &table2Path, int steps = 0);

/*!
  What the scenarios \e names need of the scene and of the trackers' search: the clutter's toys
  built (clutter: \e scene.clutter on; each frame then says whether they are drawn) and a search
  that reaches 250 mm (grasp: \e space's lower z bound).
*/
void prepareForScenarios(const std::vector<std::string> &names, sim::SceneParams &scene, rmga::SearchSpace &space);

/*!
  The images of frame \e k of \e s: the scene set as the frame says (exposure, light, occluder, still
  backdrop, clutter, gripper), rendered (frame \e k's noise), or black for a blank frame. The scene's
  parameters stay as set. Throws pm::core::Error for a frame with clutter in a scene made without it.
*/
sim::StereoImages renderScenarioFrame(sim::Scene &scene, const core::StereoRig &rig, const Scenario &s, std::size_t k);
//! The same through a rig of any number of cameras: camera k's image at [k].
std::vector<vpImage<vpRGBa>> renderScenarioViews(sim::Scene &scene, const core::CameraRig &rig, const Scenario &s, std::size_t k);


} // namespace pm::compare
