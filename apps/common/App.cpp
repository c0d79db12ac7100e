#include "pm/app/App.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <iostream>
#include <sstream>

#include <visp3/core/vpException.h>

#include "pm/core/Error.h"

#ifndef PM_SOURCE_DATA_DIR
#define PM_SOURCE_DATA_DIR ""
#endif
#ifndef PM_INSTALL_DATA_DIR
#define PM_INSTALL_DATA_DIR ""
#endif

namespace pm::app {

int run(CLI::App &app, int argc, char **argv, const std::function<int()> &body)
{
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp &e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp &e) {
    return app.exit(e);
  } catch (const CLI::ParseError &e) {
    std::cerr << app.get_name() << ": usage error: " << e.what() << " (see --help)" << std::endl;
    return 2;
  }
  try {
    return body();
  } catch (const CLI::ParseError &e) {
    std::cerr << app.get_name() << ": usage error: " << e.what() << " (see --help)" << std::endl;
    return 2;
  } catch (const pm::Error &e) {
    std::cerr << "error: " << e.what() << std::endl;
  } catch (const vpException &e) {
    std::cerr << "error: " << e.getStringMessage() << std::endl;
  } catch (const std::exception &e) {
    std::cerr << "error: " << e.what() << std::endl;
  } catch (...) {
    std::cerr << "error: unexpected failure" << std::endl;
  }
  return 1;
}

std::string dataDir()
{
  namespace fs = std::filesystem;
  if (const char *env = std::getenv("PM_DATA_DIR"); env && *env)
    return env;
  for (const char *d : {PM_SOURCE_DATA_DIR, PM_INSTALL_DATA_DIR})
    if (*d && fs::is_directory(d))
      return d;
  return "data";
}

std::string dataPath(const std::string &relative) { return dataDir() + "/" + relative; }

std::vector<double> parseNumbers(const std::string &text, std::size_t n, const std::string &what)
{
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size() && item.find_first_not_of(" \t", used) != std::string::npos)
        throw std::invalid_argument(item);
    } catch (const std::exception &) {
      throw CLI::ValidationError(what, "'" + item + "' is not a number");
    }
  }
  if (v.size() != n)
    throw CLI::ValidationError(what, "expects " + std::to_string(n) + " comma-separated numbers, got '" + text + "'");
  return v;
}

double residentMemoryMb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) {
      std::istringstream in(line.substr(6));
      double kb = 0;
      if (in >> kb)
        return kb / 1024.0;
    }
  return std::numeric_limits<double>::quiet_NaN();
}

} // namespace pm::app
