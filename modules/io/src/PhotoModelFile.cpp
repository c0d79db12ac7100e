#include "pm/io/PhotoModelFile.h"

#include <fstream>

#include <nlohmann/json.hpp>

#include "JsonFormat.h"
#include "pm/core/Error.h"
#include "pm/io/StagedFiles.h"

using nlohmann::json;

namespace pm::io {

namespace {

constexpr const char *kFormat = "visp-photomodel-model";

json pointsToJson(const std::vector<ModelPoint> &pts, bool withZ)
{
  json a = json::array();
  for (const auto &p : pts)
    a.push_back(withZ ? json{p.x, p.y, p.z, p.hue, p.u, p.v} : json{p.x, p.y, p.hue, p.u, p.v});
  return a;
}

std::vector<ModelPoint> pointsFromJson(const json &a, const char *name, bool withZ)
{
  const std::string shape = withZ ? "[x_mm, y_mm, z_mm, hue_deg, u_px, v_px]" : "[x_mm, y_mm, hue_deg, u_px, v_px]";
  if (!a.is_array())
    throw Error(std::string("\"") + name + "\" must be an array of " + shape);
  std::vector<ModelPoint> pts;
  pts.reserve(a.size());
  const std::size_t n = withZ ? 6 : 5, k = withZ ? 1 : 0;
  for (const auto &e : a) {
    if (!e.is_array() || e.size() != n)
      throw Error(std::string("every point of \"") + name + "\" must be " + shape);
    ModelPoint p;
    p.x = e[0].get<float>();
    p.y = e[1].get<float>();
    p.z = withZ ? e[2].get<float>() : 0.f;
    p.hue = e[2 + k].get<float>();
    p.u = e[3 + k].get<float>();
    p.v = e[4 + k].get<float>();
    pts.push_back(p);
  }
  return pts;
}

} // namespace

std::string photoModelToJson(const PhotoModel &m)
{
  const bool depth = m.hasDepth();
  json j{{"format", kFormat},
         {"version", !m.views.empty() ? 3 : depth ? 2 : 1},
         {"distance_mm", m.distanceMm},
         {"camera", {{"px", m.px}, {"py", m.py}, {"u0", m.u0}, {"v0", m.v0}, {"width", m.photoWidth}, {"height", m.photoHeight}}},
         {"centroid_px", {m.centroidU, m.centroidV}},
         {"background_hue_deg", m.backgroundHue},
         {"target_hue_deg", m.targetHue},
         {"s_in", pointsToJson(m.inner, depth)},
         {"s_out", pointsToJson(m.outer, depth)}};
  if (depth) {
    j["origin_in_hand_mm"] = {m.originInHandMm[0], m.originInHandMm[1], m.originInHandMm[2]};
    j["depth_range_mm"] = {m.depthRangeMm[0], m.depthRangeMm[1]};
    j["n_in_dropped"] = m.nInDropped;
  }
  if (!m.views.empty()) {
    j["camera_mm"] = {m.cameraMm[0], m.cameraMm[1], m.cameraMm[2]};
    json views = json::array();
    for (const ModelView &v : m.views)
      views.push_back({{"camera_mm", {v.cameraMm[0], v.cameraMm[1], v.cameraMm[2]}},
                       {"s_in", pointsToJson(v.inner, true)},
                       {"s_out", pointsToJson(v.outer, true)}});
    j["views"] = views;
  }
  return j.dump() + "\n";
}

void savePhotoModel(const PhotoModel &m, const std::string &path) { writeTextFile(path, photoModelToJson(m)); }

PhotoModel loadPhotoModel(const std::string &path)
{
  std::ifstream f(path);
  if (!f)
    throw Error("photo-model file '" + path + "' does not exist or cannot be read");
  PhotoModel m;
  try {
    const json j = json::parse(f);
    const int version = detail::checkFormat(j, kFormat, 3);
    m.distanceMm = j.at("distance_mm").get<double>();
    const json &c = j.at("camera");
    m.px = c.at("px").get<double>();
    m.py = c.at("py").get<double>();
    m.u0 = c.at("u0").get<double>();
    m.v0 = c.at("v0").get<double>();
    m.photoWidth = c.at("width").get<unsigned>();
    m.photoHeight = c.at("height").get<unsigned>();
    const auto cen = j.at("centroid_px").get<std::vector<double>>();
    if (cen.size() != 2)
      throw Error("\"centroid_px\" must be [u, v]");
    m.centroidU = cen[0];
    m.centroidV = cen[1];
    m.backgroundHue = j.at("background_hue_deg").get<float>();
    m.targetHue = j.value("target_hue_deg", 0.f);
    m.inner = pointsFromJson(j.at("s_in"), "s_in", version >= 2);
    m.outer = pointsFromJson(j.at("s_out"), "s_out", version >= 2);
    if (version >= 2) {
      const auto o = j.at("origin_in_hand_mm").get<std::vector<double>>();
      const auto r = j.at("depth_range_mm").get<std::vector<double>>();
      if (o.size() != 3 || r.size() != 2)
        throw Error("\"origin_in_hand_mm\" must be [x, y, z] and \"depth_range_mm\" [near, far]");
      for (int i = 0; i < 3; ++i)
        m.originInHandMm[i] = o[static_cast<std::size_t>(i)];
      m.depthRangeMm[0] = r[0];
      m.depthRangeMm[1] = r[1];
      m.nInDropped = j.value("n_in_dropped", 0);
    }
    if (version == 3) {
      auto camera = [](const json &entry, double out[3]) {
        const auto v = entry.get<std::vector<double>>();
        if (v.size() != 3)
          throw Error("\"camera_mm\" must be [x, y, z]");
        for (int i = 0; i < 3; ++i)
          out[i] = v[static_cast<std::size_t>(i)];
      };
      camera(j.at("camera_mm"), m.cameraMm);
      const json &views = j.at("views");
      if (!views.is_array() || views.empty())
        throw Error("\"views\" must be a non-empty array of {camera_mm, s_in, s_out}");
      for (const json &v : views) {
        ModelView mv;
        camera(v.at("camera_mm"), mv.cameraMm);
        mv.inner = pointsFromJson(v.at("s_in"), "s_in", true);
        mv.outer = pointsFromJson(v.at("s_out"), "s_out", true);
        m.views.push_back(std::move(mv));
      }
    }
  } catch (const Error &e) {
    throw Error("photo-model file '" + path + "' is corrupt: " + e.what());
  } catch (const json::exception &e) {
    throw Error("photo-model file '" + path + "' is corrupt: " + e.what());
  }
  m.validate("'" + path + "'");
  return m;
}

} // namespace pm::io
