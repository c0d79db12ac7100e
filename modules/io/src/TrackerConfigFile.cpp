#include "pm/io/TrackerConfigFile.h"

#include <algorithm>
#include <fstream>

#include <nlohmann/json.hpp>

#include "JsonFormat.h"
#include "pm/core/Error.h"

using nlohmann::json;

namespace pm::io {

namespace {
constexpr const char *kFormat = "visp-photomodel-tracker";

/*!
  One JSON object of the file: each get() reads a key if present and records it as known;
  done() refuses any other key, so that a misspelt one is an error, not a default silently kept.
*/
class Section
{
public:
  Section(const json &j, std::string where) : m_j(j), m_where(std::move(where)) {}
  template <typename T> Section &get(const char *key, T &v)
  {
    m_known.emplace_back(key);
    if (m_j.contains(key))
      v = m_j.at(key).get<T>();
    return *this;
  }
  //! A key read elsewhere.
  Section &known(const char *key)
  {
    m_known.emplace_back(key);
    return *this;
  }
  //! The object under \e key, if present, read by \e read(Section &) and checked.
  template <typename F> Section &section(const char *key, F read)
  {
    m_known.emplace_back(key);
    if (m_j.contains(key)) {
      Section s(m_j.at(key), std::string(" in \"") + key + "\"");
      read(s);
      s.done();
    }
    return *this;
  }
  void done() const
  {
    for (auto it = m_j.begin(); it != m_j.end(); ++it)
      if (std::find(m_known.begin(), m_known.end(), it.key()) == m_known.end())
        throw Error("unknown key \"" + it.key() + "\"" + m_where);
  }

private:
  const json &m_j;
  std::string m_where;
  std::vector<std::string> m_known;
};
} // namespace

TrackerParams loadTrackerConfig(const std::string &path, const TrackerParams &defaults)
{
  std::ifstream f(path);
  if (!f)
    throw Error("tracker configuration '" + path + "' does not exist or cannot be read");
  TrackerParams p = defaults;
  try {
    const json j = json::parse(f);
    detail::checkFormat(j, kFormat);
    Section top(j, "");
    top.known("format").known("version"); // checked above
    top.get("budget_ms", p.budgetMs)
        .get("budget_evaluations", p.budgetEvaluations)
        .get("lock_quality", p.lockQuality)
        .get("lock_confidence", p.lockConfidence)
        .get("lost_quality", p.lostQuality)
        .get("lost_frames", p.lostFrames)
        .get("init_spread", p.initSpread)
        .get("steady_budget_fraction", p.steadyBudgetFraction)
        .get("steady_after_frames", p.steadyAfterFrames)
        .get("steady_quality_drop", p.steadyQualityDrop)
        .get("steady_hue_margin_px", p.steadyHueMarginPx)
        .get("steady_escalation", p.steadyEscalation)
        .get("smooth_refine_evaluations", p.smoothRefineEvaluations)
        .get("smooth_refine_max_drop", p.smoothRefineMaxDrop);
    top.section("smooth_ascent", [&](Section &a) {
      a.get("max_evaluations", p.smoothAscent.maxEvaluations)
          .get("first_step_px", p.smoothAscent.firstStepPx)
          .get("max_step_px", p.smoothAscent.maxStepPx)
          .get("min_step_px", p.smoothAscent.minStepPx)
          .get("grow", p.smoothAscent.grow)
          .get("shrink", p.smoothAscent.shrink);
    });
    top.get("smooth_ascent_max_drop", p.smoothAscentMaxDrop)
        .get("reject_margin_q", p.rejectMarginQ)
        .get("coarse_search", p.coarseSearch);
    top.section("tilt_filter", [&](Section &t) {
      t.get("alpha", p.tiltFilter.alpha).get("beta", p.tiltFilter.beta).get("gate_deg", p.tiltFilter.gateDeg);
    });
    top.section("tilt_filter_all_around", [&](Section &t) {
      t.get("alpha", p.tiltFilterAllAround.alpha).get("beta", p.tiltFilterAllAround.beta).get("gate_deg", p.tiltFilterAllAround.gateDeg);
    });
    top.get("verify_evaluations", p.verifyEvaluations)
        .get("verify_budget_fraction", p.verifyBudgetFraction)
        .get("verify_margin", p.verifyMargin)
        .get("verify_switch_margin", p.verifySwitchMargin)
        .get("verify_far_mm", p.verifyFarMm)
        .get("verify_far_deg", p.verifyFarDeg)
        .get("verify_same_object_mm", p.verifySameObjectMm)
        .get("reverify_after_frames", p.reverifyAfterFrames)
        .get("reverify_below_confidence", p.reverifyBelowConfidence);
    top.section("confidence", [&](Section &c) {
      c.get("weights", p.confidence.weights).get("bias", p.confidence.bias).get("threshold", p.confidence.threshold);
    });
    top.section("search_space", [&](Section &s) { s.get("lo", p.space.lo).get("hi", p.space.hi); });
    top.section("rmga", [&](Section &g) {
      g.get("population", p.ga.population)
          .get("elite", p.ga.elite)
          .get("tournament", p.ga.tournament)
          .get("crossover_rate", p.ga.crossoverRate)
          .get("mutation_per_bit", p.ga.mutationPerBit)
          .get("predict_motion", p.ga.predictMotion)
          .get("refine_evaluations", p.ga.refineEvaluations)
          .get("restart_generations", p.ga.restartGenerations)
          .get("seed", p.ga.seed);
    });
    top.section("fitness", [&](Section &q) {
      q.get("in_tol_deg", p.fitness.inTolDeg)
          .get("in_bg_tol_deg", p.fitness.inBgTolDeg)
          .get("out_bg_tol_deg", p.fitness.outBgTolDeg)
          .get("in_match", p.fitness.inMatch)
          .get("in_background", p.fitness.inBackground)
          .get("in_other", p.fitness.inOther)
          .get("out_background", p.fitness.outBackground)
          .get("out_other", p.fitness.outOther)
          .get("off_image", p.fitness.offImage)
          .get("min_saturation", p.fitness.minSaturation);
    });
    top.done();
    p.validate();
  } catch (const Error &e) {
    throw Error("tracker configuration '" + path + "': " + e.what());
  } catch (const json::exception &e) {
    throw Error("tracker configuration '" + path + "' is not valid: " + e.what());
  }
  return p;
}

std::string trackerConfigToJson(const TrackerParams &p)
{
  const json j{{"format", kFormat},
               {"version", 1},
               {"budget_ms", p.budgetMs},
               {"budget_evaluations", p.budgetEvaluations},
               {"lock_quality", p.lockQuality},
               {"lock_confidence", p.lockConfidence},
               {"lost_quality", p.lostQuality},
               {"lost_frames", p.lostFrames},
               {"init_spread", p.initSpread},
               {"steady_budget_fraction", p.steadyBudgetFraction},
               {"steady_after_frames", p.steadyAfterFrames},
               {"steady_quality_drop", p.steadyQualityDrop},
               {"steady_hue_margin_px", p.steadyHueMarginPx},
               {"steady_escalation", p.steadyEscalation},
               {"smooth_refine_evaluations", p.smoothRefineEvaluations},
               {"smooth_refine_max_drop", p.smoothRefineMaxDrop},
               {"smooth_ascent",
                {{"max_evaluations", p.smoothAscent.maxEvaluations},
                 {"first_step_px", p.smoothAscent.firstStepPx},
                 {"max_step_px", p.smoothAscent.maxStepPx},
                 {"min_step_px", p.smoothAscent.minStepPx},
                 {"grow", p.smoothAscent.grow},
                 {"shrink", p.smoothAscent.shrink}}},
               {"smooth_ascent_max_drop", p.smoothAscentMaxDrop},
               {"reject_margin_q", p.rejectMarginQ},
               {"coarse_search", p.coarseSearch},
               {"tilt_filter", {{"alpha", p.tiltFilter.alpha}, {"beta", p.tiltFilter.beta}, {"gate_deg", p.tiltFilter.gateDeg}}},
               {"tilt_filter_all_around", {{"alpha", p.tiltFilterAllAround.alpha}, {"beta", p.tiltFilterAllAround.beta}, {"gate_deg", p.tiltFilterAllAround.gateDeg}}},
               {"verify_evaluations", p.verifyEvaluations},
               {"verify_budget_fraction", p.verifyBudgetFraction},
               {"verify_margin", p.verifyMargin},
               {"verify_switch_margin", p.verifySwitchMargin},
               {"verify_far_mm", p.verifyFarMm},
               {"verify_far_deg", p.verifyFarDeg},
               {"verify_same_object_mm", p.verifySameObjectMm},
               {"reverify_after_frames", p.reverifyAfterFrames},
               {"reverify_below_confidence", p.reverifyBelowConfidence},
               {"confidence", {{"weights", p.confidence.weights}, {"bias", p.confidence.bias}, {"threshold", p.confidence.threshold}}},
               {"search_space", {{"lo", p.space.lo}, {"hi", p.space.hi}}},
               {"rmga",
                {{"population", p.ga.population},
                 {"elite", p.ga.elite},
                 {"tournament", p.ga.tournament},
                 {"crossover_rate", p.ga.crossoverRate},
                 {"mutation_per_bit", p.ga.mutationPerBit},
                 {"predict_motion", p.ga.predictMotion},
                 {"refine_evaluations", p.ga.refineEvaluations},
                 {"restart_generations", p.ga.restartGenerations},
                 {"seed", p.ga.seed}}},
               {"fitness",
                {{"in_tol_deg", p.fitness.inTolDeg},
                 {"in_bg_tol_deg", p.fitness.inBgTolDeg},
                 {"out_bg_tol_deg", p.fitness.outBgTolDeg},
                 {"in_match", p.fitness.inMatch},
                 {"in_background", p.fitness.inBackground},
                 {"in_other", p.fitness.inOther},
                 {"out_background", p.fitness.outBackground},
                 {"out_other", p.fitness.outOther},
                 {"off_image", p.fitness.offImage},
                 {"min_saturation", p.fitness.minSaturation}}}};
  return j.dump(2) + "\n";
}

} // namespace pm::io
