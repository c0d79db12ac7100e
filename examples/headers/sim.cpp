// The usage examples of pm::sim's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/sim/Clutter.h"
#include "pm/sim/Gripper.h"
#include "pm/sim/ImageVariation.h"
#include "pm/sim/Mesh.h"
#include "pm/sim/MeshOutlineCut.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/RobotPA10.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"

#include <iostream>
#include "pm/sim/SimulatedPhotoModel.h"
namespace pm_examples {

// Clutter.h
void exampleClutter()
{
  const pm::sim::TargetShape crab = pm::sim::makeTarget("C12");
  for (const pm::sim::ClutterToy &t : pm::sim::clutterAround(crab))
    std::cout << t.code << " at x " << t.poseMm[0] << " y " << t.poseMm[1] << (t.similarHue ? " (similar hue)" : "") << "\n";
}

// Gripper.h
void exampleGripper()
{
  pm::sim::SceneParams sp;
  sp.gripper = true; // the scene draws makeGripperMesh(sp.gripperShape) at the hand in every image
}

// ImageVariation.h
void exampleImageVariation()
{
  pm::sim::SceneParams sp;
  sp.variation = pm::sim::imageVariation("defocus,jpeg"); // a soft lens and a compressed stream
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"), sp);
}

// Mesh.h
void exampleMesh()
{
  auto olive = pm::sim::speckledTexture(8, 64, 5, 0.8, 0.4, [](int, int) { return std::array<double, 3>{60, 120, 40}; });
}

// MeshOutlineCut.h
void exampleMeshOutlineCut()
{
  const pm::sim::Mesh toy = pm::sim::buildTargetMesh(pm::sim::makeTarget("C12"));
  const pm::sim::Mesh cut = pm::sim::cutAlongOutline(toy); // cut.useMask is false
}

// Rasterizer.h
void exampleRasterizer(const pm::sim::Mesh &backdrop, const pm::sim::Mesh &toy, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam)
{
  pm::sim::Rasterizer r;
  r.reset(640, 480, 2);                            // 640 x 480 pixels, 2 x 2 samples each
  r.clear(0.04f, 0.06f, 0.09f);
  r.draw(backdrop, cMo, cam, pm::sim::Lighting(), 1); // backdrop, toy: pm::sim::Mesh; cMo (m)
  r.draw(toy, cMo, cam, pm::sim::Lighting(), 2);
  vpImage<vpRGBa> I;
  r.resolve(I, 1.0, 2.0, 42);                      // exposure 1, noise sigma 2 grey levels, seed 42
  const double onToy = r.coverage(320, 240, 2);    // fraction of the centre pixel on the toy
}

// Rasterizer.h
void exampleRasterizer2(const pm::sim::Mesh &backdrop, const pm::sim::Mesh &toy, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam,
                         std::uint64_t seed)
{
  pm::sim::Rasterizer r;
  r.reset(640, 480, 2);
  const float sky[3] = {0.04f, 0.06f, 0.09f};
  pm::sim::Rasterizer::DrawCall calls[2];
  calls[0].mesh = &backdrop; calls[0].cMo = cMo; calls[0].id = 1;
  calls[1].mesh = &toy;      calls[1].cMo = cMo; calls[1].id = 2;
  vpImage<vpRGBa> I;
  r.render(sky, calls, 2, cam, I, 1.0, 2.0, seed);
}

// RobotPA10.h
void exampleRobotPA10()
{
  pm::sim::RobotPA10 robot;                          // q = 0: the arm straight up
  vpColVector q0(pm::sim::RobotPA10::kDof, 0.0);
  q0[1] = vpMath::rad(30);
  q0[3] = vpMath::rad(90);
  q0[5] = vpMath::rad(60);
  robot.setPosition(vpRobot::JOINT_STATE, q0);
  robot.setRobotState(vpRobot::STATE_VELOCITY_CONTROL);
  vpColVector v(6, 0.0);                             // twist in the flange frame (m/s, rad/s)
  v[2] = 0.05;                                       // 5 cm/s along the flange's z axis
  robot.setVelocity(vpRobot::END_EFFECTOR_FRAME, v);
  for (int k = 0; k < 500; ++k)
    robot.step(0.002);                               // 1 s in steps of 2 ms
  const vpHomogeneousMatrix fMe = robot.fMe();       // the flange's pose in the base frame
  vpColVector q;
  if (pm::sim::RobotPA10::inverse(fMe, q0, q))       // back to it from q0
    robot.setPosition(vpRobot::JOINT_STATE, q);
}

// Scene.h
void exampleScene()
{
  pm::sim::SceneParams sp;
  sp.exposure = 0.8;                                     // a darker lab
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"), sp); // the crab
  const vpCameraParameters cam(800, 800, 320, 240);
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 640, 480, 0.12, pm::core::StereoRig::toeInFor(0.12, 0.5));
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(pm::core::Phi{0, 0, 500, 0, 0, 0}); // 500 mm ahead
  for (std::uint64_t frame = 0; frame < 30; ++frame) {
    const pm::sim::StereoImages im = scene.renderStereo(rig, hMo, frame);
    // im.left, im.right: what the two cameras see
  }
}

// TargetCatalog.h
void exampleTargetCatalog()
{
  for (const pm::sim::TargetInfo &t : pm::sim::labTargetCatalog())
    std::cout << t.code << " " << t.name << ": " << t.widthMm << " x " << t.heightMm << " x " << t.depthMm << " mm\n";
  pm::sim::TargetShape crab = pm::sim::makeTarget("c12");       // case-insensitive
  crab.scaleRelief(0.5);                                        // half as thick
  const pm::sim::Mesh mesh = pm::sim::buildTargetMesh(crab);    // what the renderer draws
  const bool shadows = pm::sim::isReliefTarget(crab.info.code); // false: a sea creature
}

// Trajectory.h
void exampleTrajectory()
{
  const std::vector<pm::core::Phi> steps = {{0, 0, 500, 0, 0, 0}, {80, 0, 500, 0, 0, 0}, {80, 60, 520, 0, 0, 0.05}};
  const pm::sim::Trajectory traj(steps, 1.5, 1.0);  // each held 1.5 s, moves of 1 s: 6.5 s in all
  for (double t = 0; t <= traj.duration(); t += 1.0 / 30) {
    const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(traj.at(t)); // metres
    if (traj.moving(t))
      std::cout << "t = " << t << " s: moving to step " << traj.stepAt(t) + 1 << "\n";
  }
}

// SimulatedPhotoModel.h
void exampleSimulatedPhotoModel(const pm::sim::Scene &scene, const pm::core::StereoRig &rig, const vpHomogeneousMatrix &hMo)
{
  const auto sm = pm::sim::makeSimulatedStereoPhotoModel(scene, rig);
  const pm::core::Phi truth = sm.truth(hMo);   // the model's true pose for a toy at hMo
}

} // namespace pm_examples
