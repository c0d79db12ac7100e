#pragma once
/*!
  \file TrustCache.h
  The trust calibrations a run of the test suite has made already (a LabCache folder, LabCache.h),
  so that the suite's many lab models of the same pass calibrate their trust once
  (pm::trust::calibrateFromPass() builds six held-out models: two thirds of a lab model's time).

  Besides the folder's rules (LabCache.h):
  - An entry is found only for the same pass (every image and hand pose of every view), the same rig
    and the same model built from them (its every point: a change of the build's parameters shows
    there), calibrated with the default tracker and calibration parameters (the lab's).
  - It returns what the calibration returned, to the last bit (JSON keeps a double's 17 digits).

  \code
    // what calibrateLabTrust() does:
    const pm::lab::TrustCache cache = pm::lab::TrustCache::fromEnvironment();
    const std::string key = pm::lab::TrustCache::keyOf(rig, pass, b.model);
    const pm::lab::LabTrust t = pm::lab::findOrMake<pm::lab::LabTrust>(
        cache.folder(), key, [&](const std::string &k) { return cache.find(k); },
        [&] {
          std::vector<pm::trust::PassTry> tries;
          pm::lab::LabTrust made;
          made.trust = pm::trust::calibrateFromPass(rig, pass, params, measured, pm::tracker::TrackerParams(),
                                                    pm::trust::CalibrationParams(), nullptr, nullptr, &tries);
          made.triesCsv = pm::trust::triesCsv(tries, made.trust);
          return made;
        },
        [&](const std::string &k, const pm::lab::LabTrust &made) { cache.store(k, made); });
  \endcode
*/
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pm/core/PhotoModel.h"
#include "pm/core/CameraRig.h"
#include "pm/core/TrustCalibration.h"
#include "pm/lab/LabCache.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassView.h"

namespace pm::lab {

//! A trust calibration and its tries, as trust_tries.csv holds them (pm::trust::triesCsv()).
struct LabTrust
{
  core::TrustCalibration trust; //!< what the pass taught (measured false: no right pose found; see why)
  std::string triesCsv;         //!< the tries (empty when not measured)
  std::string why;              //!< when not measured, why
};

//! Trust calibrations in a LabCache folder, keyed by what they were made from (see TrustCache.h).
class TrustCache
{
public:
  //! The folder of LabCache::fromEnvironment() (PM_LAB_CACHE), or none.
  static TrustCache fromEnvironment();
  //! In \e folder.
  explicit TrustCache(LabCache folder = LabCache()) : m_folder(std::move(folder)) {}

  //! The key of the calibration of \e model, built from \e pass taken by \e rig (16 hex digits).
  static std::string keyOf(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const core::PhotoModel &model);
  //! The calibration stored under \e key, if any (an entry that does not read is none).
  std::optional<LabTrust> find(const std::string &key) const;
  //! Stores \e t under \e key when it was measured (hold the key's lock: LabCache::KeyLock).
  void store(const std::string &key, const LabTrust &t) const;
  //! The folder it keeps its entries in.
  const LabCache &folder() const { return m_folder; }

private:
  LabCache m_folder;
};

/*!
  The trust of \e model, built from \e pass with \e params (and its \e measured views), calibrated as
  pm-make-model calibrates it (pm::trust::calibrateFromPass(), its default parameters; \e onStep as
  there, every step at once when found), through the cache of the environment (TrustCache::fromEnvironment()).
*/
LabTrust calibrateLabTrust(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                           const model::PassMeasurements &measured, const core::PhotoModel &model,
                           const std::function<void()> &onStep = nullptr);

} // namespace pm::lab
