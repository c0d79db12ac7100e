#include "pm/lab/RenderedScene.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"

namespace pm::lab {

namespace fs = std::filesystem;

namespace {

vpHomogeneousMatrix matrixFromJson(const nlohmann::json &rows, const std::string &what)
{
  if (!rows.is_array() || rows.size() != 4)
    throw core::Error(what + ": a pose must be 4 rows of 4 numbers");
  vpHomogeneousMatrix M;
  for (unsigned i = 0; i < 4; ++i) {
    if (!rows[i].is_array() || rows[i].size() != 4)
      throw core::Error(what + ": a pose must be 4 rows of 4 numbers");
    for (unsigned j = 0; j < 4; ++j)
      M[i][j] = rows[i][j].get<double>();
  }
  if (!M.isAnHomogeneousMatrix(1e-6))
    throw core::Error(what + ": a pose is not rigid");
  return M;
}

} // namespace

std::vector<core::Phi> RenderedScene::truthInModelFrame(const vpHomogeneousMatrix &fMm) const
{
  const vpHomogeneousMatrix oMm = fMo.inverse() * fMm;
  std::vector<core::Phi> truth;
  truth.reserve(hMo.size());
  for (const vpHomogeneousMatrix &M : hMo)
    truth.push_back(core::fromHomogeneousMatrix(M * oMm));
  return truth;
}

RenderedScene openRenderedScene(const std::string &dirName, bool peer)
{
  const fs::path dir(dirName), spec = dir / "scene.json";
  if (!fs::is_regular_file(spec))
    throw core::Error("no " + spec.string() + ": not a scene of pm-export-scene");
  RenderedScene s;
  s.dir = dirName;
  s.rigPath = (dir / "rig.json").string();
  s.viewsDir = (dir / (peer ? "lab_views" : "views")).string();
  const fs::path seq = dir / (peer ? "lab_sequence" : "sequence");
  s.leftPattern = (seq / "left_%04d.png").string();
  s.rightPattern = (seq / "right_%04d.png").string();
  if (!fs::is_directory(s.viewsDir) || !fs::is_regular_file(seq / "truth.csv"))
    throw core::Error("the scene " + dirName + " is not rendered yet (no " + s.viewsDir + " or " + (seq / "truth.csv").string() +
                      "): blender -b --factory-startup -P scripts/cycles/render.py -- " + dirName);
  try {
    std::ifstream in(spec);
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.at("format") != "visp-photomodel-scene")
      throw core::Error(spec.string() + " is not a scene of pm-export-scene");
    s.fMo = matrixFromJson(j.at("pass").at("fMo"), spec.string());
    for (const auto &f : j.at("sequence").at("frames")) {
      const auto &p = f.at("hMo_phi");
      s.hMo.push_back(core::toHomogeneousMatrix(
          {p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>(), p.at(3).get<double>(), p.at(4).get<double>(), p.at(5).get<double>()}));
    }
    const auto &t = j.at("target");
    s.target = t.at("code").get<std::string>();
    s.description = "scene " + dir.filename().string() + " (" + t.at("code").get<std::string>() + " " + t.at("name").get<std::string>() +
                    "), " + (peer ? "our renderer" : "another renderer");
  } catch (const nlohmann::json::exception &e) {
    throw core::Error(spec.string() + ": " + e.what());
  }
  if (s.hMo.empty())
    throw core::Error(spec.string() + ": the sequence has no frame");
  return s;
}

std::string renderedScenesDir()
{
  if (const char *d = std::getenv("PM_CYCLES_DIR"); d && *d)
    return d;
  const char *home = std::getenv("HOME");
  return std::string(home && *home ? home : ".") + "/.cache/visp-photomodel/cycles";
}

} // namespace pm::lab
