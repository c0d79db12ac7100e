#include "pm/io/RigFile.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>
#include <visp3/core/vpException.h>

#include "JsonFormat.h"
#include "pm/core/Error.h"
#include "pm/io/CameraFile.h"
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
    throw core::Error("hMc needs translation_mm and thetau_deg of 3 numbers each");
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

vpCameraParameters vispDistortionModel(const core::PinholeCamera &camera)
{
  const vpCameraParameters &cam = camera.cam;
  vpCameraParameters out;
  if (camera.distortion.isVispModel()) {
    const double k = camera.distortion.coefficients.empty() ? 0.0 : camera.distortion.coefficients[0];
    // kdu: ViSP's inverse (distorted to undistorted), fitted as below.
    double num = 0, den = 0;
    const double rMax = std::hypot(std::max(cam.get_u0(), camera.width - cam.get_u0()) / cam.get_px(),
                                   std::max(cam.get_v0(), camera.height - cam.get_v0()) / cam.get_py());
    for (int i = 1; i <= 200; ++i) {
      const double r = rMax * i / 200.0, rd = r * (1 + k * r * r);
      num += rd * rd * rd * (r - rd);
      den += rd * rd * rd * rd * rd * rd;
    }
    out.initPersProjWithDistortion(cam.get_px(), cam.get_py(), cam.get_u0(), cam.get_v0(), k, den > 0 ? num / den : 0.0);
    return out;
  }
  // Least squares over the image's radii: r (1 + kud r^2) against the lens's distorted radius,
  // and r_d (1 + kdu r_d^2) against the ideal one.
  const double rCorner = std::hypot(std::max(cam.get_u0(), camera.width - cam.get_u0()) / cam.get_px(),
                                    std::max(cam.get_v0(), camera.height - cam.get_v0()) / cam.get_py());
  double nu = 0, du = 0, nd = 0, dd = 0;
  for (int i = 1; i <= 200; ++i) {
    const double rd = rCorner * i / 200.0; // a raw radius inside the image
    const vpImagePoint ideal = camera.distortion.undistort(cam, vpImagePoint(cam.get_v0(), cam.get_u0() + rd * cam.get_px()));
    const double r = (ideal.get_u() - cam.get_u0()) / cam.get_px();
    nu += r * r * r * (rd - r);
    du += r * r * r * r * r * r;
    nd += rd * rd * rd * (r - rd);
    dd += rd * rd * rd * rd * rd * rd;
  }
  out.initPersProjWithDistortion(cam.get_px(), cam.get_py(), cam.get_u0(), cam.get_v0(), du > 0 ? nu / du : 0.0,
                                 dd > 0 ? nd / dd : 0.0);
  return out;
}

core::CameraRig loadCameraRig(const std::string &path)
{
  std::ifstream f(path);
  if (!f)
    throw core::Error("rig file '" + path + "' does not exist or cannot be read");
  core::CameraRig rig;
  try {
    const json j = json::parse(f);
    detail::checkFormat(j, kFormat, 2);
    const fs::path dir = fs::path(path).parent_path();
    const fs::path xml = j.contains("intrinsics_xml") ? dir / j.at("intrinsics_xml").get<std::string>() : fs::path();
    if (!xml.empty() && !fs::is_regular_file(xml))
      throw core::Error("the intrinsics file '" + xml.string() + "' does not exist");
    const json &cams = j.at("cameras");
    if (!cams.is_array() || cams.empty() || cams.size() > core::CameraRig::kMaxCameras)
      throw core::Error("\"cameras\" must list 1 to " + std::to_string(core::CameraRig::kMaxCameras) + " cameras");
    for (const json &cj : cams) {
      core::PinholeCamera c;
      c.name = cj.at("name").get<std::string>();
      const int w = cj.at("image_width").get<int>(), h = cj.at("image_height").get<int>();
      if (w <= 0 || h <= 0)
        throw core::Error("camera '" + c.name + "': image size must be positive");
      c.width = static_cast<unsigned>(w);
      c.height = static_cast<unsigned>(h);
      c.hMc = poseFromJson(cj.at("hMc"));
      // The camera's own intrinsics file (any format readCameraFile knows), else the rig's ViSP XML.
      const fs::path file = cj.contains("intrinsics") ? dir / cj.at("intrinsics").get<std::string>() : xml;
      if (file.empty())
        throw core::Error("camera '" + c.name + "' has no \"intrinsics\" file and the rig no \"intrinsics_xml\"");
      const CameraFile in = readCameraFile(file.string(), c.name, c.width, c.height);
      c.cam = in.camera.cam;
      c.distortion = in.camera.distortion;
      rig.cameras.push_back(std::move(c));
    }
    rig.validate();
  } catch (const core::Error &e) {
    throw core::Error("rig file '" + path + "': " + e.what());
  } catch (const json::exception &e) {
    throw core::Error("rig file '" + path + "' is not a valid rig: " + e.what());
  } catch (const vpException &e) {
    throw core::Error("rig file '" + path + "': cannot read its intrinsics: " + e.getStringMessage());
  }
  return rig;
}

core::StereoRig loadRig(const std::string &path)
{
  const core::CameraRig rig = loadCameraRig(path);
  try {
    return rig.stereo();
  } catch (const core::Error &e) {
    throw core::Error("rig file '" + path + "': " + e.what());
  }
}

void saveRig(const core::CameraRig &rig, const std::string &rigJsonPath, const std::string &xmlName,
             const std::string &description)
{
  rig.validate();
  const fs::path dir = fs::path(rigJsonPath).parent_path();
  const fs::path xml = dir / xmlName;
  const fs::path xmlTmp = dir / (".partial-" + xmlName);
  std::error_code ec;
  fs::remove(xmlTmp, ec);
  json cams = json::array();
  bool exactFiles = false;
  std::vector<std::pair<fs::path, fs::path>> written; // staged, final
  const auto cleanUp = [&] {
    fs::remove(xmlTmp, ec);
    for (const auto &w : written)
      fs::remove(w.first, ec);
  };
  for (const core::PinholeCamera &camera : rig.cameras) {
    const core::PinholeCamera *c = &camera;
    json cj{{"name", c->name}, {"image_width", c->width}, {"image_height", c->height}, {"hMc", poseToJson(c->hMc)}};
    try {
      // ViSP's XML: the pinhole model, or ViSP's one-coefficient model of the lens (exact when
      // the lens is one, a least-squares fit otherwise).
      writeCameraXml(c->distortion.isNone() ? c->cam : vispDistortionModel(*c), xmlTmp.string(), c->name, c->width, c->height);
      if (!c->distortion.isVispModel()) {
        // A lens ViSP's model cannot hold: the exact one in OpenCV's YAML, which the rig then names.
        const std::string name = fs::path(rigJsonPath).stem().string() + "_" + c->name + ".yml";
        const fs::path tmp = dir / (".partial-" + name);
        writeOpenCvCameraFile(*c, tmp.string());
        written.emplace_back(tmp, dir / name);
        cj["intrinsics"] = name;
        exactFiles = true;
      }
    } catch (const core::Error &) {
      cleanUp();
      throw;
    }
    cams.push_back(cj);
  }
  json j{{"format", kFormat}, {"version", exactFiles ? 2 : 1}, {"intrinsics_xml", xmlName}, {"cameras", cams}};
  if (!description.empty())
    j["description"] = description;
  for (const auto &w : written) {
    fs::rename(w.first, w.second, ec);
    if (ec)
      throw core::Error("cannot write the intrinsics file '" + w.second.string() + "': " + ec.message());
  }
  fs::rename(xmlTmp, xml, ec);
  if (ec)
    throw core::Error("cannot write the intrinsics file '" + xml.string() + "': " + ec.message());
  writeTextFile(rigJsonPath, j.dump(2) + "\n");
}

} // namespace pm::io
