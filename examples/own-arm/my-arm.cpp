// Your arm, driven by visp-photomodel: build your vpRobot as your ViSP programs do, and hand it
// over with the name of its kinematics. Here ViSP's simulator of the Viper850, headless; on the
// real arm: vpRobotViper850 robot; (and the same call).
#include <visp3/robot/vpSimulatorViper850.h>

#include "pm/program/ArmProgram.h"

int main(int argc, char **argv)
{
  vpSimulatorViper850 robot(false); // false: no window
  robot.init(vpViper850::TOOL_PTGREY_FLEA2_CAMERA, vpCameraParameters::perspectiveProjWithoutDistortion);
  return pm::program::runArmProgram(argc, argv, robot, "viper850");
}
