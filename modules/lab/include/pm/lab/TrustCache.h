#pragma once
/*!
  \file TrustCache.h
  The trust calibrations a run of the test suite has made already, so that the suite's many lab
  models of the same pass calibrate their trust once (pm::trust::calibrateFromPass() builds six
  held-out models: two thirds of a lab model's time). Off unless the environment variable
  PM_TRUST_CACHE names a folder; CTest names one in the build tree and empties it before every run
  (the trust_cache fixture of tests/CMakeLists.txt), so that a cached calibration is always one the
  code under test made.

  The rules it holds:
  - An entry is found only for the same pass (every image and hand pose of every view), the same rig
    and the same model built from them (its every point: a change of the build's parameters shows
    there), calibrated with the default tracker and calibration parameters (the lab's).
  - It returns what the calibration returned, to the last bit (JSON keeps a double's 17 digits).
  - It never fails a run: a folder that cannot be read or written is a cache that finds nothing.
  - Two programs that need the same calibration at once make it once: the second waits on the
    key's lock (KeyLock) and then finds what the first stored.

  \code
    // what calibrateLabTrust() does:
    const pm::lab::TrustCache cache = pm::lab::TrustCache::fromEnvironment();
    const std::string key = pm::lab::TrustCache::keyOf(rig, pass, b.model);
    std::optional<pm::lab::LabTrust> t = cache.find(key);
    if (!t) {
      std::vector<pm::trust::PassTry> tries;
      t = pm::lab::LabTrust();
      t->trust = pm::trust::calibrateFromPass(rig, pass, params, measured, pm::tracker::TrackerParams(), pm::trust::CalibrationParams(),
                                              nullptr, nullptr, &tries);
      t->triesCsv = pm::trust::triesCsv(tries, t->trust);
      cache.store(key, *t);
    }
  \endcode
*/
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoRig.h"
#include "pm/core/TrustCalibration.h"
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

//! A folder of trust calibrations keyed by what they were made from (see TrustCache.h).
class TrustCache
{
public:
  //! The folder PM_TRUST_CACHE names, or none (a cache that finds and keeps nothing).
  static TrustCache fromEnvironment();
  //! \e dir (created when something is stored; empty: none).
  explicit TrustCache(std::string dir = "");

  //! The key of the calibration of \e model, built from \e pass taken by \e rig (16 hex digits).
  static std::string keyOf(const core::StereoRig &rig, const std::vector<model::PassView> &pass, const core::PhotoModel &model);
  //! The calibration stored under \e key, if any (an entry that does not read is none).
  std::optional<LabTrust> find(const std::string &key) const;
  //! Stores \e t under \e key when it was measured (io::writeTextFile: a reader never sees half of it; hold the key's lock).
  void store(const std::string &key, const LabTrust &t) const;

  //! Holds \e key's lock (flock) while it lives: another process or thread locking the same key waits.
  class KeyLock
  {
  public:
    //! Waits for \e key's lock in \e cache's folder and takes it (nothing for a cache without a folder).
    KeyLock(const TrustCache &cache, const std::string &key);
    //! Releases the lock.
    ~KeyLock();
    KeyLock(const KeyLock &) = delete;
    KeyLock &operator=(const KeyLock &) = delete;

  private:
    int m_fd = -1;
  };
  //! True when it has a folder (false: it finds and keeps nothing).
  bool enabled() const { return !m_dir.empty(); }

private:
  std::string m_dir;
};

/*!
  The trust of \e model, built from \e pass with \e params (and its \e measured views), calibrated as
  pm-make-model calibrates it (pm::trust::calibrateFromPass(), its default parameters; \e onStep as
  there, every step at once when found), through the cache of the environment (TrustCache::fromEnvironment()).
*/
LabTrust calibrateLabTrust(const core::StereoRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                           const model::PassMeasurements &measured, const core::PhotoModel &model,
                           const std::function<void()> &onStep = nullptr);

} // namespace pm::lab
