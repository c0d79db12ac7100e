#pragma once
/*!
  \file ArmProgram.h
  A whole program for your own arm: you build your vpRobot as your ViSP programs do, and hand it
  over with the name of its kinematic model; the program makes the pass of the hand around the
  target (the views folder pm-make-model --views reads) and servos on the model made from it.

      my-arm pass  --rig rig.json --left 0 --right 1 --distance-mm 500 --views views
      pm-make-model --views views --rig rig.json --out model
      my-arm servo --rig rig.json --left 0 --right 1 --model model/model.json

  --simulate TARGET puts the lab's renderer in place of the cameras (the target TARGET ahead of the
  hand): the whole flow can be tried on ViSP's simulated arms before a real one. docs/tutorial-any-robot.md.
*/
#include <string>

#include <visp3/robot/vpRobot.h>

namespace pm::program {

/*!
  The program's main (see ArmProgram.h): parses \e argv (subcommands pass and servo, --help),
  drives \e robot through pm::robot::ViSPRobotArm with the kinematics of \e arm (a name of
  pm::robot::armNames(): "viper850", "afma6", "pa10"), and returns the exit status: 0, 1 after
  "error: ..." on stderr (nothing half written; the arm stopped), 2 for a usage error.
  \code
    #include <visp3/robot/vpRobotViper850.h>
    #include "pm/program/ArmProgram.h"
    int main(int argc, char **argv)
    {
      vpRobotViper850 robot;
      return pm::program::runArmProgram(argc, argv, robot, "viper850");
    }
  \endcode
*/
int runArmProgram(int argc, char **argv, vpRobot &robot, const std::string &arm);

} // namespace pm::program
