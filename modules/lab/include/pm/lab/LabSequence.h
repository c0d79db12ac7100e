#pragma once
/*!
  \file LabSequence.h
  The simulated lab as a source of frames: the target moves along a trajectory in front of
  the fixed hand and the rig (a stereo pair, or one to four cameras) films it at a frame rate. A program reads it like a recording or
  live cameras (capture::StereoSource), and also gets each frame's truth.
*/
#include "pm/capture/StereoSource.h"
#include "pm/core/Pose.h"
#include "pm/core/CameraRig.h"
#include "pm/core/StereoRig.h"
#include "pm/sim/Scene.h"
#include "pm/sim/Trajectory.h"

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::lab {

/*!
  Frames k = 0 .. frames - 1 of \e scene's target moving along \e trajectory (poses of the target
  frame in the hand frame) at time k / fps, rendered through \e rig with noise seed k. The truth
  of frame k is the pose of the model frame (\e oMm: the model frame in the target frame, see
  sim::SimulatedPhotoModel) in the hand frame. The source keeps references to the scene and the
  trajectory: they must outlive it. next() hands out pairs (a stereo rig), nextFrame() any rig's.

  \code
    pm::sim::Scene scene(pm::sim::makeTarget("C12"));
    const pm::sim::Trajectory trajectory({{0, 0, 500, 0, 0, 0}, {40, 0, 500, 0, 0, 0}}, 1.5, 1.0);
    pm::lab::LabSequence seq(scene, rig, trajectory, vpHomogeneousMatrix(), 30.0, 105);
    pm::capture::StereoFrame f;
    while (seq.next(f))
      tracker.track(f.left, f.right), std::cout << seq.truth(f.index).x << "\n";
  \endcode
*/
class LabSequence : public capture::StereoSource
{
public:
  //! Throws pm::core::Error for fps \<= 0 or frames \< 1.
  LabSequence(const sim::Scene &scene, const core::CameraRig &rig, const sim::Trajectory &trajectory,
              const vpHomogeneousMatrix &oMm, double fps, long frames);
  //! Renders the next frame (index k, timeS k / fps); false after the last.
  bool next(capture::StereoFrame &f) override;
  //! Renders the next frame of every camera (index k, timeS k / fps); false after the last.
  bool nextFrame(capture::CameraFrame &f) override;
  //! The rig's cameras.
  std::size_t cameraCount() const override { return m_rig.size(); }
  //! "simulator, target C12 (crab)".
  std::string describe() const override;
  //! The model frame's pose in the hand frame at frame \e k (mm, quaternion vector).
  core::Phi truth(long k) const;
  //! Whether the target is moving at frame \e k (between two waypoints).
  bool moving(long k) const;
  //! The frames of the sequence.
  long length() const { return m_frames; }

private:
  const sim::Scene &m_scene;
  core::CameraRig m_rig;
  const sim::Trajectory &m_trajectory;
  vpHomogeneousMatrix m_oMm;
  double m_fps;
  long m_frames, m_next = 0;
};

} // namespace pm::lab
