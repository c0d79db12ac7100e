#include "pm/robot/ArmCatalog.h"

#include "pm/core/Error.h"
#include "pm/robot/Afma6Model.h"
#include "pm/robot/Pa10Model.h"
#include "pm/robot/Viper850Model.h"

namespace pm::robot {

std::vector<std::string> armNames() { return {"pa10", "viper850", "afma6"}; }

std::unique_ptr<ArmModel> makeArmModel(const std::string &name)
{
  if (name == "pa10")
    return std::make_unique<Pa10Model>();
  if (name == "viper850")
    return std::make_unique<Viper850Model>();
  if (name == "afma6")
    return std::make_unique<Afma6Model>();
  throw core::Error("unknown robot '" + name + "' (one of: pa10, viper850, afma6)");
}

} // namespace pm::robot
