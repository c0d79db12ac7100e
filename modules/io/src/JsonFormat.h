#pragma once
// Private to pm_io: the header every JSON file of ours starts with.
#include <string>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"

namespace pm::io::detail {

//! Throws pm::Error unless \e j is an object with "format" = \e format and "version" = 1.
inline void checkFormat(const nlohmann::json &j, const char *format)
{
  if (!j.is_object() || j.value("format", "") != format)
    throw Error(std::string("\"format\" must be \"") + format + "\"");
  if (j.value("version", 0) != 1)
    throw Error("unsupported \"version\" (this program reads version 1)");
}

} // namespace pm::io::detail
