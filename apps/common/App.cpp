#include "pm/app/App.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <iostream>
#include <sstream>

#include <visp3/core/vpException.h>

#include "pm/core/Error.h"
#include "pm/io/DataDir.h"

#ifndef PM_SOURCE_DATA_DIR
#define PM_SOURCE_DATA_DIR ""
#endif
#ifndef PM_INSTALL_DATA_DIR
#define PM_INSTALL_DATA_DIR ""
#endif

namespace pm::app {

namespace {

// argv with the old spellings replaced ("--old v" and "--old=v"), one notice per old name.
std::vector<std::string> renameArguments(const std::string &program, int argc, char **argv, const std::vector<Renamed> &renamed)
{
  std::vector<std::string> args(argv, argv + argc);
  std::vector<bool> noticed(renamed.size(), false);
  for (std::size_t i = 1; i < args.size(); ++i)
    for (std::size_t r = 0; r < renamed.size(); ++r) {
      const Renamed &n = renamed[r];
      const bool joined = args[i].rfind(n.old + "=", 0) == 0;
      if (args[i] != n.old && !joined)
        continue;
      const std::string value = joined ? args[i].substr(n.old.size() + 1) : (i + 1 < args.size() ? args[i + 1] : "");
      if (!n.values.empty() && std::find(n.values.begin(), n.values.end(), value) == n.values.end())
        continue;
      args[i] = joined ? n.now + "=" + value : n.now;
      if (!noticed[r])
        std::cerr << program << ": " << n.old << (n.values.empty() ? "" : " " + value) << " is deprecated, use " << n.now
                  << (n.values.empty() ? "" : " " + value) << std::endl;
      noticed[r] = true;
      break;
    }
  return args;
}

} // namespace

int run(CLI::App &app, int argc, char **argv, const std::function<int()> &body, const std::vector<Renamed> &renamed)
{
  try {
    if (renamed.empty()) {
      app.parse(argc, argv);
    } else {
      std::vector<std::string> args = renameArguments(app.get_name(), argc, argv, renamed);
      std::vector<char *> ptrs;
      for (std::string &a : args)
        ptrs.push_back(a.data());
      app.parse(static_cast<int>(ptrs.size()), ptrs.data());
    }
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
  } catch (const pm::core::Error &e) {
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

std::string dataDir() { return io::dataDir(PM_SOURCE_DATA_DIR, PM_INSTALL_DATA_DIR); }

std::string dataPath(const std::string &relative) { return dataDir() + "/" + relative; }

bool isImagePattern(const std::vector<std::string> &values)
{
  return values.size() == 1 && values.front().find('%') != std::string::npos;
}

std::vector<std::string> imageFiles(const std::vector<std::string> &values, int firstFrame)
{
  if (!isImagePattern(values))
    return values;
  std::vector<std::string> files;
  for (long k = firstFrame; std::filesystem::exists(frameFileName(values.front(), k)); ++k)
    files.push_back(frameFileName(values.front(), k));
  if (files.empty())
    throw pm::core::Error("no image " + frameFileName(values.front(), firstFrame) + " (the pattern " + values.front() + " from frame " +
                    std::to_string(firstFrame) + ")");
  return files;
}

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
