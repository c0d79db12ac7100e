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

/*!
  The file name of frame \e index from a pattern with one printf-style integer field ("%d" or
  "%0Nd"; "%%" is a literal %). Throws Error for any other pattern (never passed to printf).
*/
std::string frameFileName(const std::string &pattern, int index)
{
  std::string out;
  int fields = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out += pattern[i];
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out += '%';
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    int width = 0;
    bool zero = j < pattern.size() && pattern[j] == '0';
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
      width = width * 10 + (pattern[j++] - '0');
    if (j >= pattern.size() || pattern[j] != 'd' || ++fields > 1)
      throw Error("the image pattern '" + pattern + "' must hold exactly one frame-number field, %d or %0Nd (e.g. L_%04d.png)");
    std::string num = std::to_string(index);
    if (static_cast<int>(num.size()) < width)
      num.insert(0, static_cast<std::size_t>(width) - num.size(), zero ? '0' : ' ');
    out += num;
    i = j;
  }
  if (fields != 1)
    throw Error("the image pattern '" + pattern + "' must hold exactly one frame-number field, %d or %0Nd (e.g. L_%04d.png)");
  return out;
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
