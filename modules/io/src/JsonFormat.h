#pragma once
// Private to pm_io: the header every JSON file of ours starts with.
#include <string>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"

namespace pm::io::detail {

/*!
  Throws pm::core::Error unless \e j is an object with "format" = \e format and a "version" from 1 to
  \e maxVersion; returns the version.
*/
inline int checkFormat(const nlohmann::json &j, const char *format, int maxVersion = 1)
{
  if (!j.is_object() || j.value("format", "") != format)
    throw core::Error(std::string("\"format\" must be \"") + format + "\"");
  const nlohmann::json v = j.value("version", nlohmann::json());
  if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > maxVersion)
    throw core::Error("unsupported \"version\" (this program reads versions 1 to " + std::to_string(maxVersion) + ")");
  return static_cast<int>(v.get<long long>());
}

} // namespace pm::io::detail
