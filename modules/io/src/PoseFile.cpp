#include "pm/io/PoseFile.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>
#include <visp3/core/vpPoseVector.h>

#include "pm/core/Error.h"
#include "pm/io/StagedFiles.h"

namespace pm::io {

vpHomogeneousMatrix parsePoseYaml(const std::string &text, const std::string &source)
{
  const std::string what = "the pose file '" + source + "' ";
  double v[6];
  try {
    const YAML::Node root = YAML::Load(text);
    if (!root.IsMap())
      throw core::Error(what + "is not a vpPoseVector in YAML (rows: 6, cols: 1, data: 6 values)");
    if (!root["rows"] || !root["cols"] || !root["data"])
      throw core::Error(what + "lacks rows, cols or data: not a vpPoseVector in YAML");
    const long rows = root["rows"].as<long>(), cols = root["cols"].as<long>();
    if (rows != 6 || cols != 1)
      throw core::Error(what + "holds a " + std::to_string(rows) + "x" + std::to_string(cols) +
                  " array: a vpPoseVector is 6x1 (x, y, z in metres, theta-u in radians)");
    const YAML::Node data = root["data"];
    if (!data.IsSequence() || data.size() != 6)
      throw core::Error(what + "must list 6 values under data");
    for (std::size_t i = 0; i < 6; ++i) {
      const YAML::Node row = data[i];
      const YAML::Node x = row.IsSequence() ? (row.size() == 1 ? row[0] : YAML::Node()) : row;
      if (!x.IsDefined() || !x.IsScalar())
        throw core::Error(what + "row " + std::to_string(i) + " of data is not one number");
      v[i] = x.as<double>();
    }
  } catch (const YAML::Exception &e) {
    throw core::Error(what + "is not valid YAML: " + e.what());
  }
  for (int i = 0; i < 6; ++i)
    if (!std::isfinite(v[i]))
      throw core::Error(what + "holds a value that is not finite");
  for (int i = 0; i < 3; ++i)
    if (std::fabs(v[i]) > 100)
      throw core::Error(what + "puts the hand " + std::to_string(v[i]) + " m away: the translation is in metres");
  if (std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]) > 2 * M_PI + 1e-6)
    throw core::Error(what + "holds a theta-u rotation over 2 pi: the rotation is in radians");
  return vpHomogeneousMatrix(vpPoseVector(v[0], v[1], v[2], v[3], v[4], v[5]));
}

vpHomogeneousMatrix readPoseYaml(const std::string &path)
{
  std::ifstream f(path, std::ios::binary);
  if (!f)
    throw core::Error("the pose file '" + path + "' does not exist or cannot be read");
  std::ostringstream ss;
  ss << f.rdbuf();
  if (ss.str().size() > (1u << 20))
    throw core::Error("the pose file '" + path + "' is over 1 MB: not a vpPoseVector");
  return parsePoseYaml(ss.str(), path);
}

std::string poseYamlText(const vpHomogeneousMatrix &M)
{
  const vpPoseVector p(M);
  std::ostringstream s;
  s.precision(17);
  s << "rows: 6\ncols: 1\ndata:\n";
  for (unsigned i = 0; i < 6; ++i)
    s << "  - [" << p[i] << "]\n";
  return s.str();
}

void writePoseYaml(const vpHomogeneousMatrix &M, const std::string &path) { writeTextFile(path, poseYamlText(M)); }

} // namespace pm::io
