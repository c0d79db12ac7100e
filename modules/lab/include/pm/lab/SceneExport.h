#pragma once
/*!
  \file SceneExport.h
  A lab scene written out for another renderer (Blender's Cycles: scripts/cycles/render.py), so
  that the tracker can be checked on images our rasterizer cannot make: an area light and its soft
  cast shadows, light bounced between surfaces, highlights, depth of field.

  The folder holds the scene's geometry in one world frame f (the arm's base frame of the lab's
  pass, metres): the toy's mesh cut along its outline (toy.obj, its texture), the backdrop panel
  (backdrop.obj), the rig (rig.json and its intrinsics), the pass (the hand poses fMh of every view,
  the toy at fMo), the sequence (per frame the hand's, the toy's and the backdrop's poses in f, and
  the truth: the toy frame in the hand frame) and the light, all in scene.json; and the same pass
  and sequence rendered by our own rasterizer (lab_views/, lab_sequence/), so that a figure on the
  other renderer's images has its lab peer on the same poses.

  \code
    pm::lab::SceneExportParams p;
    p.target = "R2";
    p.stillBackdrop = true;   // the backdrop stands 100 mm behind the toy while the toy moves
    pm::lab::exportScene(p, pm::io::loadRig("data/rig/pa10_stereo.json"), "scenes/r2_still");
  \endcode
*/
#include <string>
#include <vector>

#include "pm/core/Pose.h"
#include "pm/core/StereoRig.h"
#include "pm/model/PassPlanner.h"

namespace pm::lab {

//! What scene exportScene() writes: the toy, its backdrop, the pass and the sequence.
struct SceneExportParams
{
  std::string target = "C12"; //!< the toy (a catalogue code: C01..C12, R1..R3)
  /*!
    The backdrop another renderer draws: "sea-bottom" (the lab's panel and texture, exported) or
    "cloth" (a green cloth the other renderer makes itself; our renderer's peer images keep the sea
    bottom).
  */
  std::string backdrop = "sea-bottom";
  //! The backdrop stands still stillGapMm behind the toy's base while the toy moves; off: the toy rests on it and it moves with the toy.
  bool stillBackdrop = false;
  double stillGapMm = 100; //!< the still backdrop's distance behind the toy's base (mm)
  model::PassPlan plan;    //!< the pass (the lab's: 16 views on rings at 20 and 40 deg)
  std::string arm = "pa10"; //!< the arm that makes the pass (pm::robot::makeArmModel())
  /*!
    The toy's poses in the hand frame the sequence passes through (the hand still at its rest), each
    held holdS, moves of moveS between them: moves of up to 60 mm and 10 deg, 121 frames (4 s).
  */
  std::vector<core::Phi> waypoints{{0, 0, 500, 0, 0, 0},          {30, -15, 505, 0, 0, 0.07},     {15, 20, 540, 0.06, -0.05, 0},
                                   {-30, 10, 480, -0.05, 0.07, -0.06}, {-10, -20, 520, 0.03, 0.04, 0.05}, {25, 5, 470, -0.04, -0.03, 0.04},
                                   {-20, -10, 530, 0.05, 0.05, -0.05}, {0, 0, 500, 0, 0, 0}};
  double holdS = 0.15;  //!< each waypoint held (s)
  double moveS = 0.4; //!< each move (s)
  double fps = 30;     //!< the sequence's frame rate
  //! The area light's centre in the toy's frame at the pass (mm): upper left, in front, 40 deg off the view axis, 900 mm away.
  double lightCentreMm[3] = {-411, -411, -693};
  double lightSizeMm = 300; //!< the side of the square area light (mm): the larger, the softer the shadows

  //! Throws pm::core::Error naming the first value out of range (an unknown target or backdrop, no waypoint, ...).
  void validate() const;
};

/*!
  Writes the scene of \e p seen through \e rig into the folder \e dir (see the file's description),
  all files at once or none. Throws pm::core::Error (an invalid parameter, a pass the arm cannot
  make, a file that cannot be written).
*/
void exportScene(const SceneExportParams &p, const core::StereoRig &rig, const std::string &dir);

} // namespace pm::lab
