#include "pm/lab/ModelCache.h"

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/io/AllAroundParamsJson.h"
#include "pm/io/PhotoModelFile.h"

namespace pm::lab {

namespace {

//! \e I as runs of equal pixels: [width, height, value, count, value, count, ...].
std::vector<long> runsOf(const vpImage<unsigned char> &I)
{
  std::vector<long> r{static_cast<long>(I.getWidth()), static_cast<long>(I.getHeight())};
  for (unsigned k = 0; k < I.getSize(); ++k) {
    if (r.size() > 2 && r[r.size() - 2] == I.bitmap[k])
      ++r.back();
    else
      r.insert(r.end(), {I.bitmap[k], 1});
  }
  return r;
}

vpImage<unsigned char> imageOf(const std::vector<long> &r)
{
  if (r.size() < 2 || r.size() % 2 != 0 || r[0] < 0 || r[1] < 0)
    throw core::Error("the cached silhouette does not read");
  vpImage<unsigned char> I(static_cast<unsigned>(r[1]), static_cast<unsigned>(r[0]));
  std::size_t k = 0;
  for (std::size_t i = 2; i < r.size(); i += 2) {
    if (r[i] < 0 || r[i] > 255 || r[i + 1] < 1 || k + static_cast<std::size_t>(r[i + 1]) > I.getSize())
      throw core::Error("the cached silhouette does not read");
    std::fill(I.bitmap + k, I.bitmap + k + r[i + 1], static_cast<unsigned char>(r[i]));
    k += static_cast<std::size_t>(r[i + 1]);
  }
  if (k != I.getSize())
    throw core::Error("the cached silhouette does not read");
  return I;
}

} // namespace

std::string ModelCache::keyOf(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                              bool calibrateTrust)
{
  return CacheKey("all-around model 1").rig(rig).pass(pass).text(io::allAroundParamsToJson(params)).number(calibrateTrust ? 1 : 0).hex();
}

std::optional<CachedModel> ModelCache::find(const std::string &key) const
{
  const std::optional<std::string> frame = m_folder.read(key + ".frame.json");
  if (!frame)
    return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(*frame);
    CachedModel m;
    const auto fMm = j.at("fMm").get<std::vector<double>>();
    if (fMm.size() != 16)
      return std::nullopt;
    for (unsigned k = 0; k < 16; ++k)
      m.fMm[k / 4][k % 4] = fMm[k];
    m.region = imageOf(j.at("region_runs").get<std::vector<long>>());
    m.model = io::loadPhotoModel(m_folder.pathOf(key + ".model.json"));
    return m;
  } catch (const std::exception &) {
    return std::nullopt; // an entry that does not read is none
  }
}

void ModelCache::store(const std::string &key, const CachedModel &m) const
{
  std::vector<double> fMm;
  for (unsigned k = 0; k < 16; ++k)
    fMm.push_back(m.fMm[k / 4][k % 4]);
  m_folder.write(key + ".model.json", io::photoModelToJson(m.model, io::ModelDigits::Exact));
  m_folder.write(key + ".frame.json", nlohmann::json{{"fMm", fMm}, {"region_runs", runsOf(m.region)}}.dump()); // last: find() reads it first
}

} // namespace pm::lab
