#include "pm/robot/ViSPSimulatedArm.h"

#include <algorithm>

#include <visp3/robot/vpSimulatorAfma6.h>
#include <visp3/robot/vpSimulatorViper850.h>

#include "pm/core/Error.h"
#include "pm/io/QuietStdout.h"
#include "pm/robot/ArmCatalog.h"

namespace pm::robot {

namespace {

std::unique_ptr<vpRobot> makeSimulator(const std::string &name, const ArmModel &model)
{
  std::unique_ptr<vpRobot> robot;
  io::QuietStdout quiet; // ViSP's simulators tell their camera and their files on std::cout
  if (name == "viper850") {
    auto sim = std::make_unique<vpSimulatorViper850>(false);
    sim->init(vpViper850::TOOL_PTGREY_FLEA2_CAMERA, vpCameraParameters::perspectiveProjWithoutDistortion);
    robot = std::move(sim);
  } else if (name == "afma6") {
    auto sim = std::make_unique<vpSimulatorAfma6>(false);
    sim->init(vpAfma6::TOOL_CCMOP, vpCameraParameters::perspectiveProjWithoutDistortion);
    robot = std::move(sim);
  } else {
    throw core::Error("robot '" + name + "' has no ViSP simulator running in real time (viper850 or afma6; the PA-10's runs are stepped)");
  }
  robot->setVerbose(false);
  // ViSP scales a joint velocity command as a whole to these (0.7 rad/s and 0.2 m/s by default): the model's limits instead.
  const vpColVector v = model.speedLimits();
  double rot = 0, trans = 0;
  for (unsigned i = 0; i < v.size(); ++i)
    (model.prismatic(i) ? trans : rot) = std::max(model.prismatic(i) ? trans : rot, v[i]);
  robot->setMaxRotationVelocity(rot > 0 ? rot : 1.0);
  robot->setMaxTranslationVelocity(trans > 0 ? trans : 1.0);
  return robot;
}

//! The simulator for \e name with its model (the model is made twice: once to set the simulator up, once for the Arm).
detail::SimulatorHolder holder(const std::string &name)
{
  return detail::SimulatorHolder{makeSimulator(name, *makeArmModel(name))};
}

} // namespace

ViSPSimulatedArm::ViSPSimulatedArm(const std::string &name, const vpHomogeneousMatrix &eMh)
    : detail::SimulatorHolder(holder(name)), ViSPRobotArm(*simulator, makeArmModel(name), eMh)
{
  moveTo(model().restJoints());
}

ViSPSimulatedArm::~ViSPSimulatedArm()
{
  try {
    stop();
  } catch (...) {
  }
}

std::string ViSPSimulatedArm::describe() const
{
  return "ViSP's threaded simulator of the " + model().title() + ", in real time (not repeatable frame for frame)";
}

} // namespace pm::robot
