#pragma once
/*!
  \file ArmCameraSource.h
  The lab's cameras on any arm: a stereo source that renders the scene from where the arm's hand
  is when a pair is asked for, the target fixed in the arm's base frame (or removed, for the
  backgrounds of a pass). A program that drives an arm from its cameras (pm::hand::recordPass,
  pm::hand::HandLoop) runs on it unchanged: what the lab puts in place of the rig's cameras.
*/
#include <functional>

#include "pm/capture/StereoSource.h"
#include "pm/core/StereoRig.h"
#include "pm/robot/Arm.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/Scene.h"

#include <visp3/core/vpHomogeneousMatrix.h>

namespace pm::lab {

/*!
  Pairs of \e scene seen through \e rig on the hand of \e arm, the target at \e fMo in the arm's base
  frame (or at fMoAt(t) at the pair's time t = k / fps); at most \e maxPairs of them (0: no end), numbered from 0 at \e fps. The scene, the rig and
  the arm must outlive it.
  \code
    pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));
    const vpHomogeneousMatrix fMo = arm.fMh() * vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0); // 500 mm ahead
    pm::lab::ArmCameraSource cameras(scene, rig, arm, fMo, 30, 0);
    pm::capture::StereoFrame f;
    cameras.next(f);            // what the rig sees from the arm's hand, now
  \endcode
*/
class ArmCameraSource : public capture::StereoSource
{
public:
  //! Throws pm::core::Error for fps \<= 0 or a negative \e maxPairs.
  ArmCameraSource(const sim::Scene &scene, const core::StereoRig &rig, robot::Arm &arm, const vpHomogeneousMatrix &fMo,
                  double fps, long maxPairs);
  //! The target moving: at fMoAt(t) in the arm's base frame at time t (s).
  ArmCameraSource(const sim::Scene &scene, const core::StereoRig &rig, robot::Arm &arm,
                  std::function<vpHomogeneousMatrix(double t)> fMoAt, double fps, long maxPairs);
  //! Renders the pair seen from the hand's pose now (noise seed: the pair's number).
  bool next(capture::StereoFrame &f) override;
  //! "simulator on the Viper850's hand, target C12 (crab)".
  std::string describe() const override;
  //! Puts the target in view (true, the start) or removes it (false).
  void setTargetPresent(bool present) { m_present = present; }
  //! The target's pose in the hand frame now (at the time of the next pair).
  vpHomogeneousMatrix hMo() { return m_arm.fMh().inverse() * m_fMoAt(static_cast<double>(m_next) / m_fps); }

private:
  const sim::Scene &m_scene;
  const core::StereoRig &m_rig;
  robot::Arm &m_arm;
  std::function<vpHomogeneousMatrix(double)> m_fMoAt;
  double m_fps;
  long m_maxPairs, m_next = 0;
  bool m_present = true;
  sim::Rasterizer m_raster;
};

} // namespace pm::lab
