#include "pm/io/RigFile.h"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>
#include <visp3/core/vpException.h>

#include "JsonFormat.h"
#include "pm/core/Error.h"
#include "pm/io/CameraXml.h"
#include "pm/io/StagedFiles.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace pm::io {

namespace {

constexpr const char *kFormat = "visp-photomodel-rig";

vpHomogeneousMatrix poseFromJson(const json &j)
{
  const auto t = j.at("translation_mm").get<std::vector<double>>();
  const auto r = j.at("thetau_deg").get<std::vector<double>>();
  if (t.size() != 3 || r.size() != 3)
    throw Error("hMc needs translation_mm and thetau_deg of 3 numbers each");
  const double d2r = M_PI / 180.0;
  return vpHomogeneousMatrix(t[0] * 1e-3, t[1] * 1e-3, t[2] * 1e-3, r[0] * d2r, r[1] * d2r, r[2] * d2r);
}

json poseToJson(const vpHomogeneousMatrix &M)
{
  const vpTranslationVector t = M.getTranslationVector();
  const vpThetaUVector r = M.getThetaUVector();
  const double r2d = 180.0 / M_PI;
  return json{{"translation_mm", {t[0] * 1e3, t[1] * 1e3, t[2] * 1e3}},
              {"thetau_deg", {r[0] * r2d, r[1] * r2d, r[2] * r2d}}};
}

} // namespace

StereoRig loadRig(const std::string &path)
{
  std::ifstream f(path);
  if (!f)
    throw Error("rig file '" + path + "' does not exist or cannot be read");
  StereoRig rig;
  try {
    const json j = json::parse(f);
    detail::checkFormat(j, kFormat);
    const fs::path xml = fs::path(path).parent_path() / j.at("intrinsics_xml").get<std::string>();
    if (!fs::is_regular_file(xml))
      throw Error("the intrinsics file '" + xml.string() + "' does not exist");
    const json &cams = j.at("cameras");
    if (!cams.is_array() || cams.size() != 2)
      throw Error("\"cameras\" must list exactly two cameras, left then right");
    RigCamera *dst[2] = {&rig.left, &rig.right};
    for (std::size_t i = 0; i < 2; ++i) {
      RigCamera &c = *dst[i];
      c.name = cams[i].at("name").get<std::string>();
      const int w = cams[i].at("image_width").get<int>(), h = cams[i].at("image_height").get<int>();
      if (w <= 0 || h <= 0)
        throw Error("camera '" + c.name + "': image size must be positive");
      c.width = static_cast<unsigned>(w);
      c.height = static_cast<unsigned>(h);
      c.hMc = poseFromJson(cams[i].at("hMc"));
      c.cam = readCameraXml(xml.string(), c.name, c.width, c.height);
    }
    rig.validate();
  } catch (const Error &e) {
    throw Error("rig file '" + path + "': " + e.what());
  } catch (const json::exception &e) {
    throw Error("rig file '" + path + "' is not a valid rig: " + e.what());
  } catch (const vpException &e) {
    throw Error("rig file '" + path + "': cannot read its intrinsics: " + e.getStringMessage());
  }
  return rig;
}

void saveRig(const StereoRig &rig, const std::string &rigJsonPath, const std::string &xmlName,
             const std::string &description)
{
  rig.validate();
  const fs::path dir = fs::path(rigJsonPath).parent_path();
  const fs::path xml = dir / xmlName;
  const fs::path xmlTmp = dir / (".partial-" + xmlName);
  std::error_code ec;
  fs::remove(xmlTmp, ec);
  json cams = json::array();
  for (const RigCamera *c : {&rig.left, &rig.right}) {
    try {
      writeCameraXml(c->cam, xmlTmp.string(), c->name, c->width, c->height);
    } catch (const Error &) {
      fs::remove(xmlTmp, ec);
      throw;
    }
    cams.push_back({{"name", c->name}, {"image_width", c->width}, {"image_height", c->height}, {"hMc", poseToJson(c->hMc)}});
  }
  json j{{"format", kFormat}, {"version", 1}, {"intrinsics_xml", xmlName}, {"cameras", cams}};
  if (!description.empty())
    j["description"] = description;
  fs::rename(xmlTmp, xml, ec);
  if (ec)
    throw Error("cannot write the intrinsics file '" + xml.string() + "': " + ec.message());
  writeTextFile(rigJsonPath, j.dump(2) + "\n");
}

} // namespace pm::io
