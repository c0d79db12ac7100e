#include "pm/program/ArmProgram.h"

#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <visp3/core/vpException.h>
#include <visp3/robot/vpRobotWireFrameSimulator.h>

#include "pm/core/Error.h"
#include "pm/io/PoseFile.h"
#include "pm/program/ArmSessions.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/ViSPRobotArm.h"

namespace pm::program {

namespace {

void addCameraOptions(CLI::App &cmd, CameraOptions &o)
{
  cmd.add_option("--rig", o.rig, "the stereo rig file (pm-make-rig, pm-calibrate-rig)")->required();
  auto *left = cmd.add_option("--left", o.left, "the left camera (OpenCV VideoCapture: device index, V4L2 path, video file or GStreamer pipeline)");
  auto *right = cmd.add_option("--right", o.right, "the right camera (the same)");
  auto *sim = cmd.add_option("--simulate", o.simulate, "no cameras: the lab's renderer on the arm's hand, this target (C01..C12, R1..R3) "
                                                      "--distance-mm ahead of the hand at the start");
  left->needs(right);
  right->needs(left);
  sim->excludes(left)->excludes(right);
  cmd.add_option("--fps", o.fps, "the cameras' rate (pairs per second)")->check(CLI::Range(1.0, 1000.0))->capture_default_str();
  cmd.add_option("--distance-mm", o.distanceMm, "the target's distance ahead of the hand, along its z axis, at the start (mm)")
      ->check(CLI::Range(100.0, 5000.0))->capture_default_str();
}

int body(const CLI::App &app, const CLI::App &pass, const CLI::App &servo, vpRobot &robot, const std::string &armName,
         const std::string &handEye, bool moveByVelocity, bool fromRest, const CameraOptions &cameras, const PassOptions &po,
         const ServoOptions &so)
{
  const CameraOptions &c = cameras;
  if (c.simulate.empty() && c.left.empty())
    throw CLI::RequiredError("--left and --right (the cameras), or --simulate");
  robot::ViSPRobotArmParams params;
  // ViSP's simulators' setPosition races their thread: our velocity loop instead (ViSPRobotArmParams::moveByVelocity).
  params.moveByVelocity = moveByVelocity || dynamic_cast<vpRobotWireFrameSimulator *>(&robot) != nullptr;
  const vpHomogeneousMatrix eMh = handEye.empty() ? vpHomogeneousMatrix() : io::readPoseYaml(handEye);
  robot::ViSPRobotArm arm(robot, robot::makeArmModel(armName), eMh, params);
  std::cout << app.get_name() << ": " << arm.model().title() << " (" << arm.describe() << ")" << std::endl;
  if (fromRest)
    arm.moveTo(arm.model().restJoints());
  if (pass.parsed())
    runPassSession(arm, c, po, std::cout);
  else if (servo.parsed())
    runServoSession(arm, c, so, std::cout);
  return 0;
}

} // namespace

int runArmProgram(int argc, char **argv, vpRobot &robot, const std::string &armName)
{
  CLI::App app("Your arm, driven by visp-photomodel: the pass of the hand around the target (a views folder for "
               "pm-make-model --views), then the servo that keeps the target in front of the hand. The arm is your "
               "vpRobot with the kinematics of " + armName + "; it stops on any error, on Ctrl-C and when the cameras end.");
  app.name(argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "arm");
  app.require_subcommand(1);
  std::string handEye;
  bool moveByVelocity = false, fromRest = false;
  app.add_option("--hand-eye", handEye, "the rig's hand frame on the flange, eMh (vpPoseVector YAML; default: the flange frame)");
  app.add_flag("--move-by-velocity", moveByVelocity, "reach the pass's poses through joint velocities instead of the robot's "
                                                     "setPosition() (ViSP's simulators always do)");
  app.add_flag("--from-rest", fromRest, "first move the arm to its model's rest joints (where the lab starts; the target then "
                                        "--distance-mm ahead of the hand), in position control");
  CameraOptions cameras, servoCameras;
  PassOptions po;
  ServoOptions so;
  CLI::App *pass = app.add_subcommand("pass", "the pass: the arm moves the rig around the target view by view, and writes the views folder");
  addCameraOptions(*pass, cameras);
  pass->add_option("--views", po.views, "the views folder to write (created; nothing appears unless all of it is written)")->required();
  pass->add_option("--pass-views", po.count, "hand poses of the pass")->check(CLI::Range(6, 200))->capture_default_str();
  pass->add_option("--settle-pairs", po.settlePairs, "pairs dropped at each stop (the cameras' buffer, the arm settling)")
      ->check(CLI::Range(0, 100))->capture_default_str();
  pass->add_flag("!--no-backgrounds", po.backgrounds, "no second round with the target removed (a plain backdrop: pm-make-model --backdrop-hue)");
  pass->add_flag("--quiet", po.quiet, "no progress");
  CLI::App *servo = app.add_subcommand("servo", "the servo: the arm keeps the target where it is first found (or at --desired)");
  addCameraOptions(*servo, servoCameras);
  servo->add_option("--model", so.model, "the photo-model (pm-make-model's model.json)")->required();
  servo->add_option("--desired", so.desired, "the pose of the target to keep in the hand frame (vpPoseVector YAML; default: where it is first found)");
  servo->add_option("--duration-s", so.durationS, "stop after this long (s; 0: when the cameras end, or Ctrl-C)")->check(CLI::Range(0.0, 1e6));
  servo->add_flag("--quiet", so.quiet, "no line per second");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp &e) {
    return app.exit(e);
  } catch (const CLI::ParseError &e) {
    std::cerr << app.get_name() << ": usage error: " << e.what() << " (see --help)" << std::endl;
    return 2;
  }
  try {
    return body(app, *pass, *servo, robot, armName, handEye, moveByVelocity, fromRest, pass->parsed() ? cameras : servoCameras, po, so);
  } catch (const CLI::ParseError &e) {
    std::cerr << app.get_name() << ": usage error: " << e.what() << " (see --help)" << std::endl;
    return 2;
  } catch (const Error &e) {
    std::cerr << "error: " << e.what() << std::endl;
  } catch (const vpException &e) {
    std::cerr << "error: ViSP: " << e.getStringMessage() << std::endl;
  } catch (const std::exception &e) {
    std::cerr << "error: " << e.what() << std::endl;
  }
  return 1;
}

} // namespace pm::program
