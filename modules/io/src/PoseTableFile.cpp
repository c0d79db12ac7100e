#include "pm/io/PoseTableFile.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "pm/core/Error.h"

namespace pm::io {

std::vector<std::pair<int, core::Phi>> readPoseTable(const std::string &path, const std::string &key)
{
  std::ifstream f(path);
  if (!f)
    throw core::Error("pose table '" + path + "' does not exist or cannot be read");
  const std::string header = key + ",x,y,z,e1,e2,e3";
  std::vector<std::pair<int, core::Phi>> rows;
  std::string line;
  int lineNo = 0;
  bool haveHeader = false;
  while (std::getline(f, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line.empty() || line[0] == '#')
      continue;
    const std::string where = "pose table '" + path + "', line " + std::to_string(lineNo) + ": ";
    if (!haveHeader) {
      if (line.rfind(header, 0) != 0)
        throw core::Error(where + "the header must be " + header);
      haveHeader = true;
      continue;
    }
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> c;
    while (std::getline(ss, cell, ',')) {
      try {
        std::size_t used = 0;
        c.push_back(std::stod(cell, &used));
        if (cell.find_first_not_of(" \t", used) != std::string::npos)
          throw std::invalid_argument(cell);
      } catch (const std::exception &) {
        throw core::Error(where + "'" + cell + "' is not a number");
      }
    }
    if (c.size() != 7)
      throw core::Error(where + "7 values expected (" + header + ")");
    if (!(std::fabs(c[0]) < 1e9) || c[0] != std::floor(c[0]))
      throw core::Error(where + "the " + key + " must be a whole number");
    const core::Phi p{c[1], c[2], c[3], c[4], c[5], c[6]};
    if (!p.isValid())
      throw core::Error(where + "invalid pose " + p.toString() + " (|eps| > 1?)");
    rows.emplace_back(static_cast<int>(c[0]), p);
  }
  if (rows.empty())
    throw core::Error("pose table '" + path + "' has no row");
  return rows;
}

std::vector<core::Phi> readWaypoints(const std::string &path, int maxSteps)
{
  std::vector<core::Phi> w;
  for (const auto &row : readPoseTable(path, "step"))
    w.push_back(row.second);
  if (maxSteps > 0 && maxSteps < static_cast<int>(w.size()))
    w.resize(static_cast<std::size_t>(maxSteps));
  return w;
}

} // namespace pm::io
