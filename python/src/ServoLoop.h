#pragma once
/*!
  \file ServoLoop.h
  The lab's servo loop for Python (teaching and tests): a toy of the catalogue, its all-around
  model made by the arm's pass, and pm::lab::ClosedLoop (the TC-robot moving the toy through
  Table 2's steps, the rig on the arm's hand, the tracker and the servo), one frame per step().
  It owns what the loop keeps by reference (the rig, the scene, the model).

      loop = visp_photomodel.lab.ServoLoop("C12", rig, seed=1)
      for k in range(300):
          frame = loop.step()             # frame.result: the tracker's; frame.error_mm: the hand's
          left, right = loop.images()     # what the rig saw (RGBA arrays)
*/
#include <memory>
#include <string>

#include "pm/core/StereoRig.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"

namespace pmpy {

//! The lab's closed loop of the Python module (see the file's description).
class ServoLoop
{
public:
  /*!
    \e target: a catalogue code (C01..C12, R1..R3); \e trajectory: a waypoints file (Table 2's);
    \e steps: its first N waypoints (0: all); \e seed: the scene's noise; \e gaSeed: RM-GA's;
    \e arm: "pa10", "viper850" or "afma6" (it makes the pass and servoes). Throws pm::core::Error.
  */
  ServoLoop(const std::string &target, const pm::core::StereoRig &rig, const std::string &trajectory, int steps, long seed,
            long gaSeed, const std::string &arm);

  //! One frame of the loop (pm::lab::ClosedLoop::step()).
  pm::lab::LoopFrame step() { return m_loop->step(); }
  //! The images of the last step(), camera k's at [k] (a stereo rig: left, right).
  const std::vector<vpImage<vpRGBa>> &images() const { return m_loop->images(); }
  //! The model the pass made, and its frame in the toy's (ground truth).
  const pm::sim::SimulatedPhotoModel &model() const { return m_model; }
  //! The time of the next step()'s frame (s).
  double time() const { return m_loop->time(); }
  //! The trajectory's duration (s): its steps held and moved.
  double duration() const { return m_durationS; }

private:
  pm::core::StereoRig m_rig;
  std::unique_ptr<pm::sim::Scene> m_scene;
  pm::sim::SimulatedPhotoModel m_model;
  double m_durationS = 0;
  std::unique_ptr<pm::lab::ClosedLoop> m_loop; //!< last: it keeps the three above by reference
};

} // namespace pmpy
