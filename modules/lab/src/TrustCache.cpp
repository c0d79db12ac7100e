#include "pm/lab/TrustCache.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/trust/PassCalibration.h"

namespace pm::lab {

namespace {

using Named = std::vector<std::pair<std::string, double>>;

std::vector<std::string> namesOf(const Named &v)
{
  std::vector<std::string> n;
  for (const auto &x : v)
    n.push_back(x.first);
  return n;
}

//! \e v put back in the order of \e names (a JSON object keeps its keys sorted).
void inOrder(Named &v, const std::vector<std::string> &names)
{
  if (names.size() != v.size())
    throw core::Error("the cached entry's names do not match");
  Named out;
  for (const std::string &n : names) {
    const auto it = std::find_if(v.begin(), v.end(), [&n](const auto &x) { return x.first == n; });
    if (it == v.end())
      throw core::Error("the cached entry's names do not match");
    out.push_back(*it);
  }
  v = std::move(out);
}

} // namespace

TrustCache TrustCache::fromEnvironment() { return TrustCache(LabCache::fromEnvironment()); }

std::string TrustCache::keyOf(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const core::PhotoModel &model)
{
  core::PhotoModel untrusted = model;
  untrusted.trust = core::TrustCalibration();
  // the calibration's and the tracker's parameters: the lab's defaults
  return CacheKey("trust calibration 3: lab defaults, with the range (RangeBias.h), near misses held at 0.9").rig(rig).pass(pass).text(io::photoModelToJson(untrusted)).hex();
}

std::optional<LabTrust> TrustCache::find(const std::string &key) const
{
  const std::optional<std::string> text = m_folder.read(key + ".trust.json");
  if (!text)
    return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(*text);
    LabTrust t;
    t.trust = io::trustCalibrationFromJson(j.at("trust_calibration").dump());
    t.triesCsv = j.at("tries_csv").get<std::string>();
    inOrder(t.trust.cueShifts, j.at("cue_shifts_order").get<std::vector<std::string>>());
    inOrder(t.trust.rightReadings, j.at("right_readings_order").get<std::vector<std::string>>());
    return t;
  } catch (const std::exception &) {
    return std::nullopt; // an entry that does not read is none
  }
}

void TrustCache::store(const std::string &key, const LabTrust &t) const
{
  if (!t.trust.measured)
    return;
  const nlohmann::json j = {{"trust_calibration", nlohmann::json::parse(io::trustCalibrationToJson(t.trust))},
                            {"cue_shifts_order", namesOf(t.trust.cueShifts)},
                            {"right_readings_order", namesOf(t.trust.rightReadings)},
                            {"tries_csv", t.triesCsv}};
  m_folder.write(key + ".trust.json", j.dump());
}

LabTrust calibrateLabTrust(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                           const model::PassMeasurements &measured, const core::PhotoModel &model, const std::function<void()> &onStep)
{
  const TrustCache cache = TrustCache::fromEnvironment();
  const std::string key = cache.folder().enabled() ? TrustCache::keyOf(rig, pass, model) : "";
  auto stepAll = [&] {
    for (std::size_t k = trust::calibrationSteps(pass.size()); k > 0 && onStep; --k)
      onStep();
  };
  const auto find = [&](const std::string &k) {
    std::optional<LabTrust> found = cache.find(k);
    if (found)
      stepAll(); // the progress a calibration would have shown
    return found;
  };
  const auto make = [&] {
    LabTrust t;
    std::vector<trust::PassTry> tries;
    t.trust = trust::calibrateFromPass(rig, pass, params, measured, tracker::TrackerParams(), trust::CalibrationParams(), onStep, &t.why, &tries);
    if (t.trust.measured)
      t.triesCsv = trust::triesCsv(tries, t.trust);
    return t;
  };
  return findOrMake<LabTrust>(cache.folder(), key, find, make, [&](const std::string &k, const LabTrust &t) { cache.store(k, t); });
}

} // namespace pm::lab
