#include "pm/lab/TrustCache.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/trust/PassCalibration.h"

namespace pm::lab {

namespace {

namespace fs = std::filesystem;

//! FNV-1a, 64 bits: a key for a cache the suite empties, not a defence against anyone.
class Fnv
{
public:
  void bytes(const void *p, std::size_t n)
  {
    const auto *b = static_cast<const unsigned char *>(p);
    for (std::size_t i = 0; i < n; ++i)
      m_h = (m_h ^ b[i]) * 0x100000001b3ull;
  }
  void number(double x) { bytes(&x, sizeof x); }
  void text(const std::string &s)
  {
    number(static_cast<double>(s.size()));
    bytes(s.data(), s.size());
  }
  void image(const vpImage<vpRGBa> &I)
  {
    number(I.getWidth());
    number(I.getHeight());
    if (I.getSize() > 0)
      bytes(I.bitmap, sizeof(vpRGBa) * I.getSize());
  }
  void matrix(const vpHomogeneousMatrix &M)
  {
    for (unsigned r = 0; r < 4; ++r)
      for (unsigned c = 0; c < 4; ++c)
        number(M[r][c]);
  }
  std::uint64_t value() const { return m_h; }

private:
  std::uint64_t m_h = 0xcbf29ce484222325ull;
};

void camera(Fnv &h, const core::PinholeCamera &c)
{
  h.text(c.name);
  for (double x : {c.cam.get_px(), c.cam.get_py(), c.cam.get_u0(), c.cam.get_v0()})
    h.number(x);
  h.number(c.width);
  h.number(c.height);
  h.matrix(c.hMc);
  h.number(static_cast<double>(c.distortion.coefficients.size()));
  for (double k : c.distortion.coefficients)
    h.number(k);
}

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

TrustCache TrustCache::fromEnvironment()
{
  const char *dir = std::getenv("PM_TRUST_CACHE");
  return TrustCache(dir ? dir : "");
}

TrustCache::TrustCache(std::string dir) : m_dir(std::move(dir)) {}

std::string TrustCache::keyOf(const core::StereoRig &rig, const std::vector<model::PassView> &pass, const core::PhotoModel &model)
{
  Fnv h;
  h.text("trust calibration 1: lab defaults"); // the calibration's and the tracker's parameters
  camera(h, rig.left);
  camera(h, rig.right);
  for (const model::PassView &v : pass) {
    h.text(v.name);
    h.matrix(v.fMh);
    for (const vpImage<vpRGBa> *I : {&v.left, &v.right, &v.backgroundLeft, &v.backgroundRight})
      h.image(*I);
  }
  core::PhotoModel untrusted = model;
  untrusted.trust = core::TrustCalibration();
  h.text(io::photoModelToJson(untrusted));
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << h.value();
  return s.str();
}

std::optional<LabTrust> TrustCache::find(const std::string &key) const
{
  if (!enabled())
    return std::nullopt;
  std::ifstream f(fs::path(m_dir) / (key + ".json"), std::ios::binary);
  if (!f)
    return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(f);
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
  if (!enabled() || !t.trust.measured)
    return;
  const nlohmann::json j = {{"trust_calibration", nlohmann::json::parse(io::trustCalibrationToJson(t.trust))},
                            {"cue_shifts_order", namesOf(t.trust.cueShifts)},
                            {"right_readings_order", namesOf(t.trust.rightReadings)},
                            {"tries_csv", t.triesCsv}};
  std::error_code ec;
  fs::create_directories(m_dir, ec);
  try {
    io::writeTextFile((fs::path(m_dir) / (key + ".json")).string(), j.dump());
  } catch (const core::Error &) {
    // a folder that cannot be written is a cache that keeps nothing
  }
}

TrustCache::KeyLock::KeyLock(const TrustCache &cache, const std::string &key)
{
  if (!cache.enabled())
    return;
  std::error_code ec;
  fs::create_directories(cache.m_dir, ec);
  m_fd = ::open((fs::path(cache.m_dir) / ("." + key + ".lock")).c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (m_fd >= 0 && ::flock(m_fd, LOCK_EX) != 0) {
    ::close(m_fd);
    m_fd = -1; // no lock: the calibration is made twice, never wrong
  }
}

TrustCache::KeyLock::~KeyLock()
{
  if (m_fd >= 0) {
    ::flock(m_fd, LOCK_UN);
    ::close(m_fd);
  }
}

LabTrust calibrateLabTrust(const core::StereoRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                           const model::PassMeasurements &measured, const core::PhotoModel &model, const std::function<void()> &onStep)
{
  const TrustCache cache = TrustCache::fromEnvironment();
  const std::string key = cache.enabled() ? TrustCache::keyOf(rig, pass, model) : "";
  auto stepAll = [&] {
    for (std::size_t k = trust::calibrationSteps(pass.size()); k > 0 && onStep; --k)
      onStep();
  };
  if (std::optional<LabTrust> found = cache.find(key)) {
    stepAll();
    return *found;
  }
  const TrustCache::KeyLock lock(cache, key); // another program making it now: wait for it
  if (std::optional<LabTrust> found = cache.find(key)) {
    stepAll();
    return *found;
  }
  LabTrust t;
  std::vector<trust::PassTry> tries;
  t.trust = trust::calibrateFromPass(rig, pass, params, measured, tracker::TrackerParams(), trust::CalibrationParams(), onStep, &t.why, &tries);
  if (t.trust.measured)
    t.triesCsv = trust::triesCsv(tries, t.trust);
  cache.store(key, t);
  return t;
}

} // namespace pm::lab
