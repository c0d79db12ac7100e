#pragma once
/*!
  \file ModelCache.h
  The lab's all-around models a run of the test suite has built already (a LabCache folder,
  LabCache.h), so that the suite's tests and tutorials that track the same toy from the same pass
  build its model once: pm::lab::makeSimulatedAllAroundModel() looks here first.

  Besides the folder's rules (LabCache.h):
  - An entry is found only for the same pass (every image and hand pose of every view), the same rig,
    the same build parameters (io::allAroundParamsToJson(), every field) and the same choice of
    calibrating the trust.
  - It gives back what the build gave, to the last bit: the model (model.json's text, with its
    trust), the model frame in the world (fMm) and the first view's left silhouette.

  \code
    // what makeSimulatedAllAroundModel() does:
    const pm::lab::ModelCache cache = pm::lab::ModelCache::fromEnvironment();
    const std::string key = pm::lab::ModelCache::keyOf(rig, pass.views, params, calibrateTrust);
    const pm::lab::CachedModel m = pm::lab::findOrMake<pm::lab::CachedModel>(
        cache.folder(), key, [&](const std::string &k) { return cache.find(k); },
        [&] {
          const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass.views, params);
          return pm::lab::CachedModel{b.model, b.fMm, b.silhouettes[0]};
        },
        [&](const std::string &k, const pm::lab::CachedModel &made) { cache.store(k, made); });
  \endcode
*/
#include <optional>
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/CameraRig.h"
#include "pm/lab/LabCache.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassView.h"

namespace pm::lab {

//! What the lab keeps of an all-around build (see ModelCache.h).
struct CachedModel
{
  core::PhotoModel model;                 //!< the model, with its trust when it was calibrated
  vpHomogeneousMatrix fMm;                //!< the model frame in the world frame of the pass (metres)
  vpImage<unsigned char> region;          //!< the first view's left silhouette
};

//! All-around models in a LabCache folder, keyed by what they were built from (see ModelCache.h).
class ModelCache
{
public:
  //! The folder of LabCache::fromEnvironment() (PM_LAB_CACHE), or none.
  static ModelCache fromEnvironment() { return ModelCache(LabCache::fromEnvironment()); }
  //! In \e folder.
  explicit ModelCache(LabCache folder = LabCache()) : m_folder(std::move(folder)) {}

  //! The key of the model built from \e pass taken by \e rig with \e params (16 hex digits).
  static std::string keyOf(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                           bool calibrateTrust);
  //! The model stored under \e key, if any (an entry that does not read is none).
  std::optional<CachedModel> find(const std::string &key) const;
  //! Stores \e m under \e key (hold the key's lock: LabCache::KeyLock).
  void store(const std::string &key, const CachedModel &m) const;
  //! The folder it keeps its entries in.
  const LabCache &folder() const { return m_folder; }

private:
  LabCache m_folder;
};

} // namespace pm::lab
