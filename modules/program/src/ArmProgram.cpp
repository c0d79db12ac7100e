#include "pm/program/ArmProgram.h"

#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <visp3/core/vpException.h>

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

//! Everything the command line sets.
struct ProgramOptions
{
  std::string handEye;        //!< eMh file (empty: the flange frame)
  bool moveByVelocity = false; //!< ViSPRobotArmParams::moveByVelocity
  bool fromRest = false;      //!< move to the model's rest joints first
  CameraOptions passCameras, servoCameras;
  PassOptions pass;
  ServoOptions servo;
};

void runCommand(const std::string &program, bool pass, vpRobot &robot, const std::string &armName, const ProgramOptions &o)
{
  const CameraOptions &c = pass ? o.passCameras : o.servoCameras;
  if (c.simulate.empty() && c.left.empty())
    throw CLI::RequiredError("--left and --right (the cameras), or --simulate");
  robot::ViSPRobotArmParams params;
  params.moveByVelocity = o.moveByVelocity;
  const vpHomogeneousMatrix eMh = o.handEye.empty() ? vpHomogeneousMatrix() : io::readPoseYaml(o.handEye);
  robot::ViSPRobotArm arm(robot, robot::makeArmModel(armName), eMh, params);
  std::cout << program << ": " << arm.model().title() << " (" << arm.describe() << ")" << std::endl;
  if (o.fromRest)
    arm.moveTo(arm.model().restJoints());
  if (pass)
    runPassSession(arm, c, o.pass, std::cout);
  else
    runServoSession(arm, c, o.servo, std::cout);
}

} // namespace

int runArmProgram(int argc, char **argv, vpRobot &robot, const std::string &armName)
{
  CLI::App app("Your arm, driven by visp-photomodel: the pass of the hand around the target (a views folder for "
               "pm-make-model --views), then the servo that keeps the target in front of the hand. The arm is your "
               "vpRobot with the kinematics of " + armName + "; it stops on any error, on Ctrl-C and when the cameras end.");
  app.name(argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "arm");
  app.require_subcommand(1);
  ProgramOptions o;
  app.add_option("--hand-eye", o.handEye, "the rig's hand frame on the flange, eMh (vpPoseVector YAML; default: the flange frame)");
  app.add_flag("--move-by-velocity", o.moveByVelocity, "reach the pass's poses through joint velocities instead of the robot's "
                                                     "setPosition() (ViSP's simulators always do)");
  app.add_flag("--from-rest", o.fromRest, "first move the arm to its model's rest joints (where the lab starts; the target then "
                                        "--distance-mm ahead of the hand), in position control");
  CLI::App *pass = app.add_subcommand("pass", "the pass: the arm moves the rig around the target view by view, and writes the views folder");
  addCameraOptions(*pass, o.passCameras);
  pass->add_option("--views", o.pass.views, "the views folder to write (created; nothing appears unless all of it is written)")->required();
  pass->add_option("--pass-views", o.pass.count, "hand poses of the pass")->check(CLI::Range(6, 200))->capture_default_str();
  pass->add_option("--settle-pairs", o.pass.settlePairs, "pairs dropped at each stop (the cameras' buffer, the arm settling)")
      ->check(CLI::Range(0, 100))->capture_default_str();
  pass->add_flag("!--no-backgrounds", o.pass.backgrounds, "no second round with the target removed (a plain backdrop: pm-make-model --backdrop-hue)");
  pass->add_flag("--quiet", o.pass.quiet, "no progress");
  CLI::App *servo = app.add_subcommand("servo", "the servo: the arm keeps the target where it is first found (or at --desired)");
  addCameraOptions(*servo, o.servoCameras);
  servo->add_option("--model", o.servo.model, "the photo-model (pm-make-model's model.json)")->required();
  servo->add_option("--desired", o.servo.desired, "the pose of the target to keep in the hand frame (vpPoseVector YAML; default: where it is first found)");
  servo->add_option("--duration-s", o.servo.durationS, "stop after this long (s; 0: when the cameras end, or Ctrl-C)")->check(CLI::Range(0.0, 1e6));
  servo->add_flag("--quiet", o.servo.quiet, "no line per second");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp &e) {
    return app.exit(e);
  } catch (const CLI::ParseError &e) {
    std::cerr << app.get_name() << ": usage error: " << e.what() << " (see --help)" << std::endl;
    return 2;
  }
  try {
    runCommand(app.get_name(), pass->parsed(), robot, armName, o);
    return 0;
  } catch (const CLI::ParseError &e) {
    std::cerr << app.get_name() << ": usage error: " << e.what() << " (see --help)" << std::endl;
    return 2;
  } catch (const core::Error &e) {
    std::cerr << "error: " << e.what() << std::endl;
  } catch (const vpException &e) {
    std::cerr << "error: ViSP: " << e.getStringMessage() << std::endl;
  } catch (const std::exception &e) {
    std::cerr << "error: " << e.what() << std::endl;
  }
  return 1;
}

} // namespace pm::program
