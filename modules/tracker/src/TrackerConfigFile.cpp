#include "pm/tracker/TrackerConfigFile.h"

#include <algorithm>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"

using nlohmann::json;

namespace pm::tracker {

// The confidence model's kind as its name ("auto", "flat", ..., see toString(ConfidenceKind)).
void to_json(json &j, const ConfidenceKind &k) { j = toString(k); }
void from_json(const json &j, ConfidenceKind &k) { k = confidenceKindFromString(j.get<std::string>()); }

namespace {
constexpr const char *kFormat = "visp-photomodel-tracker";
constexpr long long kVersion = 2; //!< the version written; version 1 (flat keys) is read too

//! The refinement chain's section: its stages in their order.
template <typename V> void refinementKeys(V &v, RefinementParams &r)
{
  precise::PreciseParams &q = r.precise.stage;
  v.section("precise", [&](V &s) {
     s.value("enabled", r.precise.enabled)
         .value("max_drop_q", r.precise.maxDropQ)
         .value("max_move_mm", r.precise.maxMoveMm)
         .value("max_move_deg", r.precise.maxMoveDeg)
         .value("restart_mm", r.precise.restartMm)
         .value("restart_deg", r.precise.restartDeg)
         .value("look_for_hidden_below", r.precise.lookForHiddenBelow)
         .value("landing_width_deg", r.precise.landingWidthDeg)
         .value("learn_aside_min_confidence", r.precise.learnAsideMinConfidence)
         .section("stage", [&](V &t) {
           t.value("lines", q.lines)
               .value("scales", q.scales)
               .value("sigmas_px", q.sigmasPx)
               .value("near_scales", q.nearScales)
               .value("near_sigmas_px", q.nearSigmasPx)
               .value("interior_max_scale", q.interiorMaxScale)
               .value("updates_per_scale", q.updatesPerScale)
               .value("function_length", q.shape.functionLength)
               .value("distribution_length", q.shape.distributionLength)
               .value("amplitude", q.shape.amplitude)
               .value("slope", q.shape.slope)
               .value("min_continuous", q.minContinuous)
               .value("regularisation_rotation", q.regularisationRotation)
               .value("regularisation_translation", q.regularisationTranslation)
               .value("learning_rate", q.learningRate)
               .value("histogram_skip_px", q.histogramSkipPx)
               .value("histogram_max_px", q.histogramMaxPx)
               .value("min_lines", q.minLines)
               .value("interior_points", q.interiorPoints)
               .value("interior_sigma", q.interiorSigma)
               .value("interior_weight", q.interiorWeight);
         });
   }).section("motion_prediction", [&](V &m) {
    m.value("gain", r.motion.gain).value("max_step_mm", r.motion.maxStepMm).value("max_step_deg", r.motion.maxStepDeg);
  }).section("ascent", [&](V &a) {
    a.value("max_evaluations", r.ascent.climb.maxEvaluations)
        .value("first_step_px", r.ascent.climb.firstStepPx)
        .value("max_step_px", r.ascent.climb.maxStepPx)
        .value("min_step_px", r.ascent.climb.minStepPx)
        .value("grow", r.ascent.climb.grow)
        .value("shrink", r.ascent.climb.shrink)
        .value("max_drop", r.ascent.maxDrop);
  });
  for (const auto &named : {std::pair<const char *, TiltFilterParams *>{"tilt_filter", &r.tiltFilter},
                             std::pair<const char *, TiltFilterParams *>{"tilt_filter_all_around", &r.tiltFilterAllAround}}) {
    TiltFilterParams *filter = named.second; // not a structured binding: a lambda may not capture one in C++17
    v.section(named.first, [filter](V &t) { t.value("alpha", filter->alpha).value("beta", filter->beta).value("gate_deg", filter->gateDeg); });
  }
}

/*!
  Every key of the file (version 2), once, in a section per part of the tracker: \e v.value(key, field)
  for a value, \e v.section(key, f) for an object whose keys f lists. The reader and the writer below
  both walk this list.
*/
template <typename V> void eachKey(V &v, TrackerParams &p)
{
  v.section("fitness", [&](V &q) {
     q.value("in_tol_deg", p.fitness.inTolDeg)
         .value("in_bg_tol_deg", p.fitness.inBgTolDeg)
         .value("out_bg_tol_deg", p.fitness.outBgTolDeg)
         .value("in_match", p.fitness.inMatch)
         .value("in_background", p.fitness.inBackground)
         .value("in_other", p.fitness.inOther)
         .value("out_background", p.fitness.outBackground)
         .value("out_other", p.fitness.outOther)
         .value("off_image", p.fitness.offImage)
         .value("min_saturation", p.fitness.minSaturation)
         .value("stereo_visibility", p.fitness.stereoVisibility)
         .value("max_hidden_share", p.fitness.maxHiddenShare);
   })
      .section("search", [&](V &s) {
        s.value("budget_evaluations", p.search.budgetEvaluations)
            .value("budget_ms", p.search.budgetMs)
            .value("reject_margin_q", p.search.rejectMarginQ)
            .value("coarse", p.search.coarse)
            .value("init_spread", p.search.initSpread)
            .value("avoid_frames", p.search.avoidFrames)
            .value("avoid_mm", p.search.avoidMm)
            .value("avoid_deg", p.search.avoidDeg)
            .section("space", [&](V &w) { w.value("lo", p.search.space.lo).value("hi", p.search.space.hi); })
            .section("rmga", [&](V &g) {
              g.value("population", p.search.ga.population)
                  .value("elite", p.search.ga.elite)
                  .value("tournament", p.search.ga.tournament)
                  .value("crossover_rate", p.search.ga.crossoverRate)
                  .value("mutation_per_bit", p.search.ga.mutationPerBit)
                  .value("predict_motion", p.search.ga.predictMotion)
                  .value("restart_generations", p.search.ga.restartGenerations)
                  .value("seed", p.search.ga.seed);
            });
      })
      .section("lock", [&](V &l) {
        l.value("quality", p.lock.quality)
            .value("confidence", p.lock.confidence)
            .value("lost_quality", p.lock.lostQuality)
            .value("lost_frames", p.lock.lostFrames)
            .value("drop_after_frames", p.lock.dropAfterFrames)
            .value("doubt_confidence", p.lock.doubtConfidence)
            .value("doubt_frames", p.lock.doubtFrames);
      })
      .section("background", [&](V &b) {
        b.value("learn", p.background.learn)
            .value("rate", p.background.rate)
            .value("window_deg", p.background.windowDeg)
            .value("switch_deg", p.background.switchDeg)
            .value("min_samples", p.background.minSamples);
      })
      .section("steady", [&](V &s) {
        s.value("budget_fraction", p.steady.budgetFraction)
            .value("after_frames", p.steady.afterFrames)
            .value("quality_drop", p.steady.qualityDrop)
            .value("escalation", p.steady.escalation)
            .value("hue_margin_px", p.steady.hueMarginPx);
      })
      .section("verifier", [&](V &c) {
        c.value("evaluations", p.verifier.evaluations)
            .value("budget_fraction", p.verifier.budgetFraction)
            .value("margin", p.verifier.margin)
            .value("switch_margin", p.verifier.switchMargin)
            .value("far_mm", p.verifier.farMm)
            .value("far_deg", p.verifier.farDeg)
            .value("same_object_mm", p.verifier.sameObjectMm)
            .value("reverify_after_frames", p.verifier.reverifyAfterFrames)
            .value("reverify_below_confidence", p.verifier.reverifyBelowConfidence);
      })
      .section("refinement", [&](V &r) { refinementKeys(r, p.refinement); })
      .section("judgement", [&](V &j) {
        j.section("confidence", [&](V &c) {
           c.value("kind", p.judgement.confidence.kind)
               .value("weights", p.judgement.confidence.weights)
               .value("bias", p.judgement.confidence.bias)
               .value("threshold", p.judgement.confidence.threshold);
         }).section("uncertainty", [&](V &u) { 
           u.value("scale", p.judgement.uncertainty.scale)
               .value("floor", p.judgement.uncertainty.floor)
               .value("model_error_gain", p.judgement.uncertainty.modelErrorGain)
               .value("model_error_width_deg", p.judgement.uncertainty.modelErrorWidthDeg);
         });
      });
}

/*!
  Reads one JSON object of the file: each value() reads its key if present and records it as
  known; done() refuses any other key, so that a misspelt one is an error, not a default kept.
*/
class Reader
{
public:
  Reader(const json &j, std::string where) : m_j(j), m_where(std::move(where))
  {
    if (!m_j.is_object())
      throw core::Error("expected an object" + m_where);
  }
  template <typename T> Reader &value(const char *key, T &v)
  {
    m_known.emplace_back(key);
    if (m_j.contains(key))
      v = m_j.at(key).get<T>();
    return *this;
  }
  Reader &known(const char *key)
  {
    m_known.emplace_back(key);
    return *this;
  }
  template <typename F> Reader &section(const char *key, F read)
  {
    m_known.emplace_back(key);
    if (m_j.contains(key)) {
      Reader s(m_j.at(key), std::string(" in \"") + key + "\"");
      read(s);
      s.done();
    }
    return *this;
  }
  void done() const
  {
    for (auto it = m_j.begin(); it != m_j.end(); ++it)
      if (std::find(m_known.begin(), m_known.end(), it.key()) == m_known.end())
        throw core::Error("unknown key \"" + it.key() + "\"" + m_where);
  }

private:
  const json &m_j;
  std::string m_where;
  std::vector<std::string> m_known;
};

//! Writes every key into a JSON object.
class Writer
{
public:
  template <typename T> Writer &value(const char *key, const T &v)
  {
    j[key] = v;
    return *this;
  }
  template <typename F> Writer &section(const char *key, F write)
  {
    Writer s;
    write(s);
    j[key] = std::move(s.j);
    return *this;
  }
  json j = json::object();
};

/*!
  A file of version 1 (flat keys, before the tracker's parts had their sections) as version 2:
  each key moved to its part's section. The keys of the refiners that are gone (the local simplex,
  RM-GA's own refinement) are dropped; \e notice says so. An unknown key stays where it is, for the
  reader to refuse.
*/
json fromVersion1(json j, std::string &notice)
{
  static const std::vector<std::pair<const char *, std::vector<const char *>>> moves = {
      {"budget_ms", {"search", "budget_ms"}}, {"budget_evaluations", {"search", "budget_evaluations"}},
      {"reject_margin_q", {"search", "reject_margin_q"}}, {"coarse_search", {"search", "coarse"}},
      {"init_spread", {"search", "init_spread"}}, {"search_space", {"search", "space"}}, {"rmga", {"search", "rmga"}},
      {"lock_quality", {"lock", "quality"}}, {"lock_confidence", {"lock", "confidence"}},
      {"lost_quality", {"lock", "lost_quality"}}, {"lost_frames", {"lock", "lost_frames"}},
      {"steady_budget_fraction", {"steady", "budget_fraction"}}, {"steady_after_frames", {"steady", "after_frames"}},
      {"steady_quality_drop", {"steady", "quality_drop"}}, {"steady_escalation", {"steady", "escalation"}},
      {"steady_hue_margin_px", {"steady", "hue_margin_px"}},
      {"verify_evaluations", {"verifier", "evaluations"}}, {"verify_budget_fraction", {"verifier", "budget_fraction"}},
      {"verify_margin", {"verifier", "margin"}}, {"verify_switch_margin", {"verifier", "switch_margin"}},
      {"verify_far_mm", {"verifier", "far_mm"}}, {"verify_far_deg", {"verifier", "far_deg"}},
      {"verify_same_object_mm", {"verifier", "same_object_mm"}},
      {"reverify_after_frames", {"verifier", "reverify_after_frames"}},
      {"reverify_below_confidence", {"verifier", "reverify_below_confidence"}},
      {"precise_stage", {"refinement", "precise", "enabled"}}, {"precise_max_drop_q", {"refinement", "precise", "max_drop_q"}},
      {"precise_max_move_mm", {"refinement", "precise", "max_move_mm"}},
      {"precise_max_move_deg", {"refinement", "precise", "max_move_deg"}},
      {"precise_restart_mm", {"refinement", "precise", "restart_mm"}},
      {"precise_restart_deg", {"refinement", "precise", "restart_deg"}}, {"precise", {"refinement", "precise", "stage"}},
      {"smooth_ascent", {"refinement", "ascent"}}, {"smooth_ascent_max_drop", {"refinement", "ascent", "max_drop"}},
      {"tilt_filter", {"refinement", "tilt_filter"}}, {"tilt_filter_all_around", {"refinement", "tilt_filter_all_around"}},
      {"confidence", {"judgement", "confidence"}}, {"uncertainty", {"judgement", "uncertainty"}}};
  std::vector<std::string> dropped;
  for (const char *gone : {"smooth_refine_evaluations", "smooth_refine_max_drop"})
    if (j.erase(gone) > 0)
      dropped.emplace_back(gone);
  if (j.contains("rmga") && j["rmga"].is_object() && j["rmga"].erase("refine_evaluations") > 0)
    dropped.emplace_back("rmga.refine_evaluations");
  json out = json::object();
  for (const auto &[from, path] : moves) {
    if (!j.contains(from))
      continue;
    json *at = &out;
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
      at = &(*at)[path[k]];
    json &to = (*at)[path.back()];
    if (to.is_object() && j[from].is_object())
      to.update(j[from]); // smooth_ascent's keys beside smooth_ascent_max_drop
    else
      to = j[from];
    j.erase(from);
  }
  for (auto it = j.begin(); it != j.end(); ++it) { // format, version and fitness keep their place
    if (it.key() != "format" && it.key() != "version" && it.key() != "fitness")
      throw core::Error("unknown key \"" + it.key() + "\"");
    out[it.key()] = it.value();
  }
  notice = "version 1 (flat keys) read as version 2 (a section per part of the tracker, see docs/file-formats.md)";
  if (!dropped.empty()) {
    notice += "; ignored, their refiners are gone:";
    for (const std::string &d : dropped)
      notice += " " + d;
  }
  return out;
}
} // namespace

namespace {

/*!
  The configuration \e j over \e defaults, named \e source in errors. \e header: "format" and
  "version" required (a file); without, they may be left out (the current version's keys).
*/
TrackerParams fromJson(json j, const TrackerParams &defaults, const std::string &source, bool header, std::string *notice)
{
  TrackerParams p = defaults;
  try {
    if (!j.is_object())
      throw core::Error("it must be an object of keys");
    if (!header && !j.contains("format"))
      j["format"] = kFormat;
    if (!header && !j.contains("version"))
      j["version"] = kVersion;
    if (j.value("format", "") != kFormat)
      throw core::Error(std::string("\"format\" must be \"") + kFormat + "\"");
    const json version = j.value("version", json());
    if (!version.is_number_integer() || (version.get<long long>() != 1 && version.get<long long>() != kVersion))
      throw core::Error("unsupported \"version\" (this program reads versions 1 and 2)");
    std::string upgraded;
    if (version.get<long long>() == 1)
      j = fromVersion1(std::move(j), upgraded);
    Reader top(j, "");
    top.known("format").known("version");
    eachKey(top, p);
    top.done();
    const json &c = j.value("judgement", json::object()).value("confidence", json::object());
    if (c.is_object() && c.contains("weights") && !c.contains("kind"))
      p.judgement.confidence.kind = ConfidenceKind::Custom; // weights written by hand are meant to be used
    p.validate();
    if (notice)
      *notice = upgraded.empty() ? std::string() : source + ": " + upgraded;
  } catch (const core::Error &e) {
    throw core::Error(source + ": " + e.what());
  } catch (const json::exception &e) {
    throw core::Error(source + " is not valid: " + e.what());
  }
  return p;
}

} // namespace

TrackerParams loadTrackerConfig(const std::string &path, const TrackerParams &defaults, std::string *notice)
{
  std::ifstream f(path);
  if (!f)
    throw core::Error("tracker configuration '" + path + "' does not exist or cannot be read");
  json j;
  try {
    j = json::parse(f);
  } catch (const json::exception &e) {
    throw core::Error("tracker configuration '" + path + "' is not valid: " + e.what());
  }
  return fromJson(std::move(j), defaults, "tracker configuration '" + path + "'", true, notice);
}

TrackerParams trackerParamsFromJson(const std::string &text, const TrackerParams &defaults)
{
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception &e) {
    throw core::Error(std::string("tracker parameters are not valid JSON: ") + e.what());
  }
  return fromJson(std::move(j), defaults, "tracker parameters", false, nullptr);
}

std::string trackerConfigToJson(const TrackerParams &params)
{
  TrackerParams p = params; // eachKey takes the fields by reference; the writer only reads them
  Writer w;
  w.value("format", kFormat).value("version", kVersion);
  eachKey(w, p);
  return w.j.dump(2) + "\n";
}

} // namespace pm::tracker
