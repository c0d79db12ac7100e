#include "pm/io/PhotoModelFile.h"

#include <array>
#include <cmath>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "JsonFormat.h"
#include "pm/core/Error.h"
#include "pm/io/StagedFiles.h"

using nlohmann::json;

namespace pm::io {

namespace {

constexpr const char *kFormat = "visp-photomodel-model";
constexpr std::size_t kViewpointViews = 16; //!< from this many views a model is written as version 4

json pointsToJson(const std::vector<core::ModelPoint> &pts, bool withZ)
{
  json a = json::array();
  for (const auto &p : pts)
    a.push_back(withZ ? json{p.x, p.y, p.z, p.hue, p.u, p.v} : json{p.x, p.y, p.hue, p.u, p.v});
  return a;
}

std::vector<core::ModelPoint> pointsFromJson(const json &a, const char *name, bool withZ)
{
  const std::string shape = withZ ? "[x_mm, y_mm, z_mm, hue_deg, u_px, v_px]" : "[x_mm, y_mm, hue_deg, u_px, v_px]";
  if (!a.is_array())
    throw core::Error(std::string("\"") + name + "\" must be an array of " + shape);
  std::vector<core::ModelPoint> pts;
  pts.reserve(a.size());
  const std::size_t n = withZ ? 6 : 5, k = withZ ? 1 : 0;
  for (const auto &e : a) {
    if (!e.is_array() || e.size() != n)
      throw core::Error(std::string("every point of \"") + name + "\" must be " + shape);
    core::ModelPoint p;
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

//! A named list of numbers as a JSON object (the order kept by the names' own).
json namedToJson(const std::vector<std::pair<std::string, double>> &v)
{
  json o = json::object();
  for (const auto &[name, x] : v)
    o[name] = x;
  return o;
}

std::vector<std::pair<std::string, double>> namedFromJson(const json &o, const char *name)
{
  if (!o.is_object())
    throw core::Error(std::string("\"trust_calibration\": \"") + name + "\" must be an object of names and numbers");
  std::vector<std::pair<std::string, double>> v;
  for (const auto &[k, x] : o.items()) {
    if (!x.is_number() || !std::isfinite(x.get<double>()))
      throw core::Error(std::string("\"trust_calibration\": \"") + name + "\": \"" + k + "\" must be a finite number");
    v.emplace_back(k, x.get<double>());
  }
  return v;
}

//! "trust_calibration" (version 6): what the pass taught the confidence and the uncertainty (TrustCalibration.h).
json trustToJson(const core::TrustCalibration &t)
{
  return {{"cue_shifts", namedToJson(t.cueShifts)},
          {"right_readings", namedToJson(t.rightReadings)},
          {"sigma_gain", t.sigmaGain},
          {"guard", t.guard},
          {"confidence_offset", t.confidenceOffset},
          {"held_out_views", t.heldOutViews},
          {"right_examples", t.rightExamples},
          {"wrong_examples", t.wrongExamples},
          {"auroc", t.auroc},
          {"right_trusted", t.rightTrusted},
          {"right_trusted_shipped", t.rightTrustedShipped},
          {"wrong_trusted", t.wrongTrusted},
          {"wrong_max_confidence", t.wrongMaxConfidence},
          {"within_sigma", t.withinSigma},
          {"range_scale", t.rangeScale},
          {"range_cameras", t.rangeCameras},
          {"range_error_pct", t.rangeErrorPct},
          {"range_views", t.rangeViews},
          {"seconds", t.seconds}};
}

core::TrustCalibration trustFromJson(const json &j)
{
  core::TrustCalibration t;
  t.measured = true;
  t.cueShifts = namedFromJson(j.at("cue_shifts"), "cue_shifts");
  t.rightReadings = namedFromJson(j.at("right_readings"), "right_readings");
  const auto gain = j.at("sigma_gain").get<std::vector<double>>();
  if (gain.size() != 6)
    throw core::Error("\"trust_calibration\": \"sigma_gain\" must be six numbers (x, y, z, about x, y, z)");
  for (std::size_t i = 0; i < 6; ++i) {
    if (!(gain[i] > 0 && gain[i] < 100))
      throw core::Error("\"trust_calibration\": every \"sigma_gain\" must lie in (0, 100)");
    t.sigmaGain[i] = gain[i];
  }
  t.guard = j.at("guard").get<double>();
  t.confidenceOffset = j.value("confidence_offset", 0.0); // none before issue 58
  if (!(t.confidenceOffset <= 0 && t.confidenceOffset > -100))
    throw core::Error("\"trust_calibration\": \"confidence_offset\" must lie in (-100, 0]");
  t.rangeScale = j.value("range_scale", 1.0); // none before issue 58's range
  if (!(t.rangeScale > 0.9 && t.rangeScale < 1.1))
    throw core::Error("\"trust_calibration\": \"range_scale\" must lie in (0.9, 1.1)");
  t.rangeCameras = j.value("range_cameras", 0);
  if (t.rangeCameras < 0 || t.rangeCameras > 16)
    throw core::Error("\"trust_calibration\": \"range_cameras\" must lie in [0, 16]");
  t.rangeErrorPct = j.value("range_error_pct", 0.0);
  t.rangeViews = j.value("range_views", 0);
  t.heldOutViews = j.value("held_out_views", 0);
  t.rightExamples = j.value("right_examples", 0);
  t.wrongExamples = j.value("wrong_examples", 0);
  t.auroc = j.value("auroc", 0.0);
  t.rightTrusted = j.value("right_trusted", 0.0);
  t.rightTrustedShipped = j.value("right_trusted_shipped", 0.0);
  t.wrongTrusted = j.value("wrong_trusted", 0);
  t.wrongMaxConfidence = j.value("wrong_max_confidence", 0.0);
  if (j.contains("within_sigma")) {
    const auto w = j.at("within_sigma").get<std::vector<double>>();
    for (std::size_t i = 0; i < std::min<std::size_t>(6, w.size()); ++i)
      t.withinSigma[i] = w[i];
  }
  t.seconds = j.value("seconds", 0.0);
  return t;
}

//! How a model's numbers are written (ModelDigits): rounded to the format's steps, or every bit of them.
class Digits
{
public:
  explicit Digits(ModelDigits d) : m_exact(d == ModelDigits::Exact) {}
  //! A position, hue or distance to 0.01 (a double, so that it is written short): what is read back is what was deduplicated.
  double rounded(float x) const { return m_exact ? static_cast<double>(x) : std::round(static_cast<double>(x) * 100.0) / 100.0; }
  //! A normal's component to 0.0001.
  double normal(float x) const { return m_exact ? static_cast<double>(x) : std::round(static_cast<double>(x) * 1e4) / 1e4; }
  //! A pass landing's mm and deg to 0.001.
  double landing(double x) const { return m_exact ? x : std::round(x * 1000.0) / 1000.0; }

private:
  bool m_exact;
};

//! A contour's points as [x, y, z, nx, ny, nz, inside_mm, outside_mm] (positions to 0.01 mm, normals to 0.0001).
json contourToJson(const std::vector<core::ContourPoint> &c, const Digits &d)
{
  json a = json::array();
  for (const core::ContourPoint &p : c)
    a.push_back({d.rounded(p.x), d.rounded(p.y), d.rounded(p.z), d.normal(p.nx), d.normal(p.ny), d.normal(p.nz), d.rounded(p.insideMm),
                 d.rounded(p.outsideMm)});
  return a;
}

std::vector<core::ContourPoint> contourFromJson(const json &a)
{
  if (!a.is_array())
    throw core::Error("\"contour\" must be an array of [x_mm, y_mm, z_mm, nx, ny, nz, inside_mm, outside_mm]");
  std::vector<core::ContourPoint> c;
  c.reserve(a.size());
  for (const json &e : a) {
    if (!e.is_array() || e.size() != 8)
      throw core::Error("every point of \"contour\" must be [x_mm, y_mm, z_mm, nx, ny, nz, inside_mm, outside_mm]");
    core::ContourPoint p;
    p.x = e[0].get<float>(), p.y = e[1].get<float>(), p.z = e[2].get<float>();
    p.nx = e[3].get<float>(), p.ny = e[4].get<float>(), p.nz = e[5].get<float>();
    p.insideMm = e[6].get<float>(), p.outsideMm = e[7].get<float>();
    c.push_back(p);
  }
  return c;
}

//! A histogram as its non-zero bins, [[bin, value], ...].
json histogramToJson(const std::vector<float> &h)
{
  json a = json::array();
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] > 0)
      a.push_back({i, h[i]});
  return a;
}

std::vector<float> histogramFromJson(const json &a, std::size_t bins, const char *name)
{
  if (!a.is_array())
    throw core::Error(std::string("\"") + name + "\" must be an array of [bin, value]");
  std::vector<float> h(bins, 0.f);
  for (const json &e : a) {
    if (!e.is_array() || e.size() != 2 || !e[0].is_number_unsigned() || e[0].get<std::size_t>() >= bins)
      throw core::Error(std::string("every entry of \"") + name + "\" must be [bin, value] with a bin under " + std::to_string(bins));
    h[e[0].get<std::size_t>()] = e[1].get<float>();
  }
  return h;
}

//! Version 4: the S_in points of every view in one cloud, each view by index; S_out as positions. Version 5 adds each surface point's colour, the outlines and the colour histograms.
void writeViewpointModel(const core::PhotoModel &m, json &j, bool v5, const Digits &d)
{
  std::map<std::array<double, 7>, std::size_t> index;
  json surface = json::array();
  auto indices = [&](const std::vector<core::ModelPoint> &pts) {
    json a = json::array();
    for (const core::ModelPoint &p : pts) {
      const double hue = d.rounded(p.hue) >= 360.0 ? 0.0 : d.rounded(p.hue); // 359.996 rounds to 360: the same as 0
      const std::array<double, 7> key{d.rounded(p.x), d.rounded(p.y), d.rounded(p.z), hue, v5 ? p.r : 0.0, v5 ? p.g : 0.0, v5 ? p.b : 0.0};
      auto it = index.find(key);
      if (it == index.end()) {
        it = index.emplace(key, surface.size()).first;
        if (v5)
          surface.push_back({key[0], key[1], key[2], key[3], p.r, p.g, p.b});
        else
          surface.push_back({key[0], key[1], key[2], key[3]});
      }
      a.push_back(it->second);
    }
    return a;
  };
  auto positions = [&d](const std::vector<core::ModelPoint> &pts) {
    json a = json::array();
    for (const core::ModelPoint &p : pts)
      a.push_back({d.rounded(p.x), d.rounded(p.y), d.rounded(p.z)});
    return a;
  };
  j["s_in"] = indices(m.inner);
  j["s_out"] = positions(m.outer);
  if (v5)
    j["contour"] = contourToJson(m.contour, d);
  json views = json::array();
  for (const core::ModelView &v : m.views) {
    json e{{"camera_mm", {v.cameraMm[0], v.cameraMm[1], v.cameraMm[2]}}, {"s_in", indices(v.inner)}, {"s_out", positions(v.outer)}};
    if (v5)
      e["contour"] = contourToJson(v.contour, d);
    views.push_back(e);
  }
  j["views"] = views;
  j["surface"] = surface;
  if (v5 && !m.foregroundHistogram.empty())
    j["colour_histograms"] = {{"bins_per_channel", core::PhotoModel::kColourBins},
                              {"foreground", histogramToJson(m.foregroundHistogram)},
                              {"background", histogramToJson(m.backgroundHistogram)}};
  if (v5 && !m.passLandings.empty()) {
    const auto r = [&d](double x) { return d.landing(x); };
    json a = json::array();
    for (const core::PassLanding &l : m.passLandings)
      a.push_back({r(l.cameraMm[0]), r(l.cameraMm[1]), r(l.cameraMm[2]), r(l.offsetMm[0]), r(l.offsetMm[1]), r(l.offsetMm[2]),
                   r(l.offsetDeg[0]), r(l.offsetDeg[1]), r(l.offsetDeg[2])});
    j["pass_landings"] = a;
  }
  if (v5 && m.trust.measured)
    j["trust_calibration"] = trustToJson(m.trust);
}

//! "pass_landings": [[camera x, y, z (mm), offset x, y, z (mm), rotation x, y, z (deg)], ...] (version 5, optional).
std::vector<core::PassLanding> passLandingsFromJson(const json &a)
{
  if (!a.is_array())
    throw core::Error("\"pass_landings\" must be an array of [camera x, y, z, offset x, y, z, rotation x, y, z]");
  std::vector<core::PassLanding> out;
  for (const json &e : a) {
    if (!e.is_array() || e.size() != 9)
      throw core::Error("every entry of \"pass_landings\" must be [camera x, y, z (mm), offset x, y, z (mm), rotation x, y, z (deg)]");
    core::PassLanding l;
    for (std::size_t i = 0; i < 3; ++i) {
      l.cameraMm[i] = e[i].get<double>();
      l.offsetMm[i] = e[3 + i].get<double>();
      l.offsetDeg[i] = e[6 + i].get<double>();
    }
    out.push_back(l);
  }
  return out;
}

std::vector<core::ModelPoint> indexedPoints(const json &a, const std::vector<core::ModelPoint> &surface, const char *name)
{
  if (!a.is_array())
    throw core::Error(std::string("\"") + name + "\" must be an array of indices into \"surface\"");
  std::vector<core::ModelPoint> pts;
  pts.reserve(a.size());
  for (const json &e : a) {
    if (!e.is_number_unsigned() || e.get<std::size_t>() >= surface.size())
      throw core::Error(std::string("\"") + name + "\" holds an index outside \"surface\" (" + std::to_string(surface.size()) + " points)");
    pts.push_back(surface[e.get<std::size_t>()]);
  }
  return pts;
}

std::vector<core::ModelPoint> positionPoints(const json &a, float hue, const char *name)
{
  if (!a.is_array())
    throw core::Error(std::string("\"") + name + "\" must be an array of [x_mm, y_mm, z_mm]");
  std::vector<core::ModelPoint> pts;
  pts.reserve(a.size());
  for (const json &e : a) {
    if (!e.is_array() || e.size() != 3)
      throw core::Error(std::string("every point of \"") + name + "\" must be [x_mm, y_mm, z_mm]");
    core::ModelPoint p;
    p.x = e[0].get<float>();
    p.y = e[1].get<float>();
    p.z = e[2].get<float>();
    p.hue = hue;
    pts.push_back(p);
  }
  return pts;
}

} // namespace

std::string trustCalibrationToJson(const core::TrustCalibration &t) { return trustToJson(t).dump(1); }

core::TrustCalibration trustCalibrationFromJson(const std::string &text)
{
  try {
    return trustFromJson(json::parse(text));
  } catch (const json::exception &e) {
    throw core::Error(std::string("\"trust_calibration\": ") + e.what());
  }
}

std::string photoModelToJson(const core::PhotoModel &m, ModelDigits digits)
{
  const bool depth = m.hasDepth();
  const bool v5 = m.views.size() >= kViewpointViews && m.hasContours() && m.hasColours;
  json j{{"format", kFormat},
         {"version", v5 ? (m.trust.measured ? 6 : 5) : m.views.size() >= kViewpointViews ? 4 : !m.views.empty() ? 3 : depth ? 2 : 1},
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
  if (m.views.size() >= kViewpointViews) {
    j["camera_mm"] = {m.cameraMm[0], m.cameraMm[1], m.cameraMm[2]};
    writeViewpointModel(m, j, v5, Digits(digits));
  } else if (!m.views.empty()) {
    j["camera_mm"] = {m.cameraMm[0], m.cameraMm[1], m.cameraMm[2]};
    json views = json::array();
    for (const core::ModelView &v : m.views)
      views.push_back({{"camera_mm", {v.cameraMm[0], v.cameraMm[1], v.cameraMm[2]}},
                       {"s_in", pointsToJson(v.inner, true)},
                       {"s_out", pointsToJson(v.outer, true)}});
    j["views"] = views;
  }
  return j.dump() + "\n";
}

void savePhotoModel(const core::PhotoModel &m, const std::string &path) { writeTextFile(path, photoModelToJson(m)); }

core::PhotoModel loadPhotoModel(const std::string &path)
{
  std::ifstream f(path);
  if (!f)
    throw core::Error("photo-model file '" + path + "' does not exist or cannot be read");
  core::PhotoModel m;
  try {
    const json j = json::parse(f);
    const int version = detail::checkFormat(j, kFormat, 6);
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
      throw core::Error("\"centroid_px\" must be [u, v]");
    m.centroidU = cen[0];
    m.centroidV = cen[1];
    m.backgroundHue = j.at("background_hue_deg").get<float>();
    m.targetHue = j.value("target_hue_deg", 0.f);
    std::vector<core::ModelPoint> surface;
    if (version >= 4) {
      const json &s = j.at("surface");
      const char *shape = version == 4 ? "[x_mm, y_mm, z_mm, hue_deg]" : "[x_mm, y_mm, z_mm, hue_deg, r, g, b]";
      if (!s.is_array() || s.empty())
        throw core::Error(std::string("\"surface\" must be a non-empty array of ") + shape);
      for (const json &e : s) {
        if (!e.is_array() || e.size() != (version == 4 ? 4u : 7u))
          throw core::Error(std::string("every point of \"surface\" must be ") + shape);
        core::ModelPoint p;
        p.x = e[0].get<float>(), p.y = e[1].get<float>(), p.z = e[2].get<float>(), p.hue = e[3].get<float>();
        if (version >= 5) {
          for (std::size_t k = 4; k < 7; ++k)
            if (!e[k].is_number_unsigned() || e[k].get<unsigned>() > 255)
              throw core::Error("a surface point's colour must be three integers in [0, 255]");
          p.r = static_cast<unsigned char>(e[4].get<unsigned>());
          p.g = static_cast<unsigned char>(e[5].get<unsigned>());
          p.b = static_cast<unsigned char>(e[6].get<unsigned>());
        }
        surface.push_back(p);
      }
      m.inner = indexedPoints(j.at("s_in"), surface, "s_in");
      m.outer = positionPoints(j.at("s_out"), m.backgroundHue, "s_out");
    } else {
      m.inner = pointsFromJson(j.at("s_in"), "s_in", version >= 2);
      m.outer = pointsFromJson(j.at("s_out"), "s_out", version >= 2);
    }
    if (version >= 2) {
      const auto o = j.at("origin_in_hand_mm").get<std::vector<double>>();
      const auto r = j.at("depth_range_mm").get<std::vector<double>>();
      if (o.size() != 3 || r.size() != 2)
        throw core::Error("\"origin_in_hand_mm\" must be [x, y, z] and \"depth_range_mm\" [near, far]");
      for (int i = 0; i < 3; ++i)
        m.originInHandMm[i] = o[static_cast<std::size_t>(i)];
      m.depthRangeMm[0] = r[0];
      m.depthRangeMm[1] = r[1];
      m.nInDropped = j.value("n_in_dropped", 0);
    }
    if (version >= 3) {
      auto camera = [](const json &entry, double out[3]) {
        const auto v = entry.get<std::vector<double>>();
        if (v.size() != 3)
          throw core::Error("\"camera_mm\" must be [x, y, z]");
        for (int i = 0; i < 3; ++i)
          out[i] = v[static_cast<std::size_t>(i)];
      };
      camera(j.at("camera_mm"), m.cameraMm);
      const json &views = j.at("views");
      if (!views.is_array() || views.empty())
        throw core::Error("\"views\" must be a non-empty array of {camera_mm, s_in, s_out}");
      for (const json &v : views) {
        core::ModelView mv;
        camera(v.at("camera_mm"), mv.cameraMm);
        if (version >= 4) {
          mv.inner = indexedPoints(v.at("s_in"), surface, "s_in");
          mv.outer = positionPoints(v.at("s_out"), m.backgroundHue, "s_out");
          if (version >= 5)
            mv.contour = contourFromJson(v.at("contour"));
        } else {
          mv.inner = pointsFromJson(v.at("s_in"), "s_in", true);
          mv.outer = pointsFromJson(v.at("s_out"), "s_out", true);
        }
        m.views.push_back(std::move(mv));
      }
    }
    if (version >= 5) {
      m.hasColours = true;
      m.contour = contourFromJson(j.at("contour"));
      if (j.contains("colour_histograms")) {
        const json &h = j.at("colour_histograms");
        if (h.at("bins_per_channel").get<int>() != core::PhotoModel::kColourBins)
          throw core::Error("\"colour_histograms\" must have " + std::to_string(core::PhotoModel::kColourBins) + " bins per channel");
        const std::size_t bins = static_cast<std::size_t>(core::PhotoModel::kColourBins) * core::PhotoModel::kColourBins * core::PhotoModel::kColourBins;
        m.foregroundHistogram = histogramFromJson(h.at("foreground"), bins, "foreground");
        m.backgroundHistogram = histogramFromJson(h.at("background"), bins, "background");
      }
      if (j.contains("pass_landings"))
        m.passLandings = passLandingsFromJson(j.at("pass_landings"));
    }
    if (version >= 6)
      m.trust = trustFromJson(j.at("trust_calibration"));
  } catch (const core::Error &e) {
    throw core::Error("photo-model file '" + path + "' is corrupt: " + e.what());
  } catch (const json::exception &e) {
    throw core::Error("photo-model file '" + path + "' is corrupt: " + e.what());
  }
  m.validate("'" + path + "'");
  return m;
}

} // namespace pm::io
