#pragma once
/*!
  \file ArmCatalog.h
  The arms the lab knows by name (the programs' --robot): "pa10" (the paper's arm, our own
  model), "viper850" and "afma6" (ViSP's own models, vpViper850 and vpAfma6).
*/
#include <memory>
#include <string>
#include <vector>

#include "pm/robot/ArmModel.h"

namespace pm::robot {

//! The names makeArmModel() knows, the lab's default first.
std::vector<std::string> armNames();
/*!
  The model of the arm called \e name. Throws pm::core::Error naming the known ones for another name.
  \code
    const std::unique_ptr<pm::robot::ArmModel> arm = pm::robot::makeArmModel("afma6");
  \endcode
*/
std::unique_ptr<ArmModel> makeArmModel(const std::string &name);

} // namespace pm::robot
