// The usage example of modules/program/include/pm/program/ArmProgram.h, a whole program (compiled where ViSP has
// the Viper850's driver, never linked).
#include <visp3/core/vpConfig.h>
#ifdef VISP_HAVE_VIPER850
#include <visp3/robot/vpRobotViper850.h>
#include "pm/program/ArmProgram.h"
int main(int argc, char **argv)
{
  vpRobotViper850 robot;
  return pm::program::runArmProgram(argc, argv, robot, "viper850");
}
#endif
