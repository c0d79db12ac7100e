#include "pm/io/DataDir.h"

#include <cstdlib>
#include <filesystem>

namespace pm::io {

std::string dataDir(const std::string &sourceDir, const std::string &installDir)
{
  if (const char *env = std::getenv("PM_DATA_DIR"); env && *env)
    return env;
  for (const std::string &d : {sourceDir, installDir})
    if (!d.empty() && std::filesystem::is_directory(d))
      return d;
  return "data";
}

} // namespace pm::io
