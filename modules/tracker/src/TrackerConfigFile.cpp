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

/*!
  Every key of the file, once: \e v.value(key, field) for a value, \e v.section(key, f) for an
  object whose keys f lists. The reader and the writer below both walk this list.
*/
template <typename V> void eachKey(V &v, TrackerParams &p)
{
  v.value("budget_ms", p.budgetMs)
      .value("budget_evaluations", p.budgetEvaluations)
      .value("lock_quality", p.lockQuality)
      .value("lock_confidence", p.lockConfidence)
      .value("lost_quality", p.lostQuality)
      .value("lost_frames", p.lostFrames)
      .value("init_spread", p.initSpread)
      .value("steady_budget_fraction", p.steadyBudgetFraction)
      .value("steady_after_frames", p.steadyAfterFrames)
      .value("steady_quality_drop", p.steadyQualityDrop)
      .value("steady_hue_margin_px", p.steadyHueMarginPx)
      .value("steady_escalation", p.steadyEscalation)
      .value("smooth_refine_evaluations", p.smoothRefineEvaluations)
      .value("smooth_refine_max_drop", p.smoothRefineMaxDrop)
      .section("smooth_ascent", [&](V &a) {
        a.value("max_evaluations", p.smoothAscent.maxEvaluations)
            .value("first_step_px", p.smoothAscent.firstStepPx)
            .value("max_step_px", p.smoothAscent.maxStepPx)
            .value("min_step_px", p.smoothAscent.minStepPx)
            .value("grow", p.smoothAscent.grow)
            .value("shrink", p.smoothAscent.shrink);
      })
      .value("smooth_ascent_max_drop", p.smoothAscentMaxDrop)
      .value("reject_margin_q", p.rejectMarginQ)
      .value("coarse_search", p.coarseSearch)
      .value("precise_stage", p.preciseStage)
      .value("precise_max_drop_q", p.preciseMaxDropQ)
      .value("precise_max_move_mm", p.preciseMaxMoveMm)
      .value("precise_max_move_deg", p.preciseMaxMoveDeg)
      .value("precise_restart_mm", p.preciseRestartMm)
      .value("precise_restart_deg", p.preciseRestartDeg)
      .section("precise", [&](V &q) {
        q.value("lines", p.precise.lines)
            .value("scales", p.precise.scales)
            .value("sigmas_px", p.precise.sigmasPx)
            .value("near_scales", p.precise.nearScales)
            .value("near_sigmas_px", p.precise.nearSigmasPx)
            .value("interior_max_scale", p.precise.interiorMaxScale)
            .value("updates_per_scale", p.precise.updatesPerScale)
            .value("function_length", p.precise.shape.functionLength)
            .value("distribution_length", p.precise.shape.distributionLength)
            .value("amplitude", p.precise.shape.amplitude)
            .value("slope", p.precise.shape.slope)
            .value("min_continuous", p.precise.minContinuous)
            .value("regularisation_rotation", p.precise.regularisationRotation)
            .value("regularisation_translation", p.precise.regularisationTranslation)
            .value("learning_rate", p.precise.learningRate)
            .value("histogram_skip_px", p.precise.histogramSkipPx)
            .value("histogram_max_px", p.precise.histogramMaxPx)
            .value("min_lines", p.precise.minLines)
            .value("interior_points", p.precise.interiorPoints)
            .value("interior_sigma", p.precise.interiorSigma)
            .value("interior_weight", p.precise.interiorWeight);
      });
  for (const auto &named : {std::pair<const char *, TiltFilterParams *>{"tilt_filter", &p.tiltFilter},
                             std::pair<const char *, TiltFilterParams *>{"tilt_filter_all_around", &p.tiltFilterAllAround}}) {
    TiltFilterParams *filter = named.second; // not a structured binding: a lambda may not capture one in C++17
    v.section(named.first, [filter](V &t) { t.value("alpha", filter->alpha).value("beta", filter->beta).value("gate_deg", filter->gateDeg); });
  }
  v.value("verify_evaluations", p.verifyEvaluations)
      .value("verify_budget_fraction", p.verifyBudgetFraction)
      .value("verify_margin", p.verifyMargin)
      .value("verify_switch_margin", p.verifySwitchMargin)
      .value("verify_far_mm", p.verifyFarMm)
      .value("verify_far_deg", p.verifyFarDeg)
      .value("verify_same_object_mm", p.verifySameObjectMm)
      .value("reverify_after_frames", p.reverifyAfterFrames)
      .value("reverify_below_confidence", p.reverifyBelowConfidence)
      .section("confidence", [&](V &c) {
        c.value("kind", p.confidence.kind).value("weights", p.confidence.weights).value("bias", p.confidence.bias).value("threshold", p.confidence.threshold);
      })
      .section("uncertainty", [&](V &u) { u.value("scale", p.uncertainty.scale).value("floor", p.uncertainty.floor); })
      .section("search_space", [&](V &s) { s.value("lo", p.space.lo).value("hi", p.space.hi); })
      .section("rmga", [&](V &g) {
        g.value("population", p.ga.population)
            .value("elite", p.ga.elite)
            .value("tournament", p.ga.tournament)
            .value("crossover_rate", p.ga.crossoverRate)
            .value("mutation_per_bit", p.ga.mutationPerBit)
            .value("predict_motion", p.ga.predictMotion)
            .value("refine_evaluations", p.ga.refineEvaluations)
            .value("restart_generations", p.ga.restartGenerations)
            .value("seed", p.ga.seed);
      })
      .section("fitness", [&](V &q) {
        q.value("in_tol_deg", p.fitness.inTolDeg)
            .value("in_bg_tol_deg", p.fitness.inBgTolDeg)
            .value("out_bg_tol_deg", p.fitness.outBgTolDeg)
            .value("in_match", p.fitness.inMatch)
            .value("in_background", p.fitness.inBackground)
            .value("in_other", p.fitness.inOther)
            .value("out_background", p.fitness.outBackground)
            .value("out_other", p.fitness.outOther)
            .value("off_image", p.fitness.offImage)
            .value("min_saturation", p.fitness.minSaturation);
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
} // namespace

TrackerParams loadTrackerConfig(const std::string &path, const TrackerParams &defaults)
{
  std::ifstream f(path);
  if (!f)
    throw core::Error("tracker configuration '" + path + "' does not exist or cannot be read");
  TrackerParams p = defaults;
  try {
    const json j = json::parse(f);
    if (!j.is_object() || j.value("format", "") != kFormat)
      throw core::Error(std::string("\"format\" must be \"") + kFormat + "\"");
    const json version = j.value("version", json());
    if (!version.is_number_integer() || version.get<long long>() != 1)
      throw core::Error("unsupported \"version\" (this program reads version 1)");
    Reader top(j, "");
    top.known("format").known("version");
    eachKey(top, p);
    top.done();
    const json &c = j.value("confidence", json::object());
    if (c.is_object() && c.contains("weights") && !c.contains("kind"))
      p.confidence.kind = ConfidenceKind::Custom; // weights written by hand are meant to be used

    p.validate();
  } catch (const core::Error &e) {
    throw core::Error("tracker configuration '" + path + "': " + e.what());
  } catch (const json::exception &e) {
    throw core::Error("tracker configuration '" + path + "' is not valid: " + e.what());
  }
  return p;
}

std::string trackerConfigToJson(const TrackerParams &params)
{
  TrackerParams p = params; // eachKey takes the fields by reference; the writer only reads them
  Writer w;
  w.value("format", kFormat).value("version", 1);
  eachKey(w, p);
  return w.j.dump(2) + "\n";
}

} // namespace pm::tracker
