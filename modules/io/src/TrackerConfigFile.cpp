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

template <typename T> void get(const json &j, const char *key, T &v)
{
  if (j.contains(key))
    v = j.at(key).get<T>();
}

void checkKeys(const json &j, const std::vector<std::string> &known, const std::string &where)
{
  for (auto it = j.begin(); it != j.end(); ++it)
    if (std::find(known.begin(), known.end(), it.key()) == known.end())
      throw Error("unknown key \"" + it.key() + "\"" + where);
}
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
    checkKeys(j, {"format", "version", "budget_ms", "budget_evaluations", "lock_quality", "lock_confidence", "lost_quality", "lost_frames",
                  "init_spread", "steady_budget_fraction", "steady_after_frames", "steady_quality_drop", "steady_hue_margin_px", "steady_escalation", "smooth_refine_evaluations", "smooth_refine_max_drop", "smooth_ascent",
                  "smooth_ascent_max_drop", "tilt_filter", "reject_margin_q", "coarse_search", "verify_evaluations",
                  "verify_budget_fraction", "verify_margin", "verify_switch_margin", "verify_far_mm", "verify_far_deg",
                  "verify_same_object_mm", "reverify_after_frames", "reverify_below_confidence", "confidence", "search_space", "rmga",
                  "fitness"}, "");
    get(j, "budget_ms", p.budgetMs);
    get(j, "budget_evaluations", p.budgetEvaluations);
    get(j, "lock_quality", p.lockQuality);
    get(j, "lock_confidence", p.lockConfidence);
    get(j, "lost_quality", p.lostQuality);
    get(j, "lost_frames", p.lostFrames);
    get(j, "init_spread", p.initSpread);
    get(j, "steady_budget_fraction", p.steadyBudgetFraction);
    get(j, "steady_after_frames", p.steadyAfterFrames);
    get(j, "steady_quality_drop", p.steadyQualityDrop);
    get(j, "steady_hue_margin_px", p.steadyHueMarginPx);
    get(j, "steady_escalation", p.steadyEscalation);
    get(j, "smooth_refine_evaluations", p.smoothRefineEvaluations);
    get(j, "smooth_refine_max_drop", p.smoothRefineMaxDrop);
    if (j.contains("smooth_ascent")) {
      const json &a = j.at("smooth_ascent");
      checkKeys(a, {"max_evaluations", "first_step_px", "max_step_px", "min_step_px", "grow", "shrink"}, " in \"smooth_ascent\"");
      get(a, "max_evaluations", p.smoothAscent.maxEvaluations);
      get(a, "first_step_px", p.smoothAscent.firstStepPx);
      get(a, "max_step_px", p.smoothAscent.maxStepPx);
      get(a, "min_step_px", p.smoothAscent.minStepPx);
      get(a, "grow", p.smoothAscent.grow);
      get(a, "shrink", p.smoothAscent.shrink);
    }
    get(j, "smooth_ascent_max_drop", p.smoothAscentMaxDrop);
    get(j, "reject_margin_q", p.rejectMarginQ);
    get(j, "coarse_search", p.coarseSearch);
    if (j.contains("tilt_filter")) {
      const json &t = j.at("tilt_filter");
      checkKeys(t, {"alpha", "beta", "gate_deg"}, " in \"tilt_filter\"");
      get(t, "alpha", p.tiltFilter.alpha);
      get(t, "beta", p.tiltFilter.beta);
      get(t, "gate_deg", p.tiltFilter.gateDeg);
    }
    get(j, "verify_evaluations", p.verifyEvaluations);
    get(j, "verify_budget_fraction", p.verifyBudgetFraction);
    get(j, "verify_margin", p.verifyMargin);
    get(j, "verify_switch_margin", p.verifySwitchMargin);
    get(j, "verify_far_mm", p.verifyFarMm);
    get(j, "verify_far_deg", p.verifyFarDeg);
    get(j, "verify_same_object_mm", p.verifySameObjectMm);
    get(j, "reverify_after_frames", p.reverifyAfterFrames);
    get(j, "reverify_below_confidence", p.reverifyBelowConfidence);
    if (j.contains("confidence")) {
      const json &c = j.at("confidence");
      checkKeys(c, {"weights", "bias", "threshold"}, " in \"confidence\"");
      get(c, "weights", p.confidence.weights);
      get(c, "bias", p.confidence.bias);
      get(c, "threshold", p.confidence.threshold);
    }
    if (j.contains("search_space")) {
      const json &s = j.at("search_space");
      checkKeys(s, {"lo", "hi"}, " in \"search_space\"");
      get(s, "lo", p.space.lo);
      get(s, "hi", p.space.hi);
    }
    if (j.contains("rmga")) {
      const json &g = j.at("rmga");
      checkKeys(g, {"population", "elite", "tournament", "crossover_rate", "mutation_per_bit", "predict_motion",
                    "refine_evaluations", "restart_generations", "seed"}, " in \"rmga\"");
      get(g, "population", p.ga.population);
      get(g, "elite", p.ga.elite);
      get(g, "tournament", p.ga.tournament);
      get(g, "crossover_rate", p.ga.crossoverRate);
      get(g, "mutation_per_bit", p.ga.mutationPerBit);
      get(g, "predict_motion", p.ga.predictMotion);
      get(g, "refine_evaluations", p.ga.refineEvaluations);
      get(g, "restart_generations", p.ga.restartGenerations);
      get(g, "seed", p.ga.seed);
    }
    if (j.contains("fitness")) {
      const json &q = j.at("fitness");
      checkKeys(q, {"in_tol_deg", "in_bg_tol_deg", "out_bg_tol_deg", "in_match", "in_background", "in_other",
                    "out_background", "out_other", "off_image", "min_saturation"}, " in \"fitness\"");
      get(q, "in_tol_deg", p.fitness.inTolDeg);
      get(q, "in_bg_tol_deg", p.fitness.inBgTolDeg);
      get(q, "out_bg_tol_deg", p.fitness.outBgTolDeg);
      get(q, "in_match", p.fitness.inMatch);
      get(q, "in_background", p.fitness.inBackground);
      get(q, "in_other", p.fitness.inOther);
      get(q, "out_background", p.fitness.outBackground);
      get(q, "out_other", p.fitness.outOther);
      get(q, "off_image", p.fitness.offImage);
      get(q, "min_saturation", p.fitness.minSaturation);
    }
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
