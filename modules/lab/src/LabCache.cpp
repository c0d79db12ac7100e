#include "pm/lab/LabCache.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "pm/core/Error.h"
#include "pm/io/StagedFiles.h"

namespace pm::lab {

namespace fs = std::filesystem;

CacheKey &CacheKey::bytes(const void *p, std::size_t n)
{
  const auto *b = static_cast<const unsigned char *>(p);
  for (std::size_t i = 0; i < n; ++i)
    m_h = (m_h ^ b[i]) * 0x100000001b3ull;
  return *this;
}

CacheKey &CacheKey::text(const std::string &s)
{
  number(static_cast<double>(s.size()));
  return bytes(s.data(), s.size());
}

CacheKey &CacheKey::image(const vpImage<vpRGBa> &I)
{
  number(I.getWidth());
  number(I.getHeight());
  return I.getSize() > 0 ? bytes(I.bitmap, sizeof(vpRGBa) * I.getSize()) : *this;
}

CacheKey &CacheKey::matrix(const vpHomogeneousMatrix &M)
{
  for (unsigned r = 0; r < 4; ++r)
    for (unsigned c = 0; c < 4; ++c)
      number(M[r][c]);
  return *this;
}

CacheKey &CacheKey::camera(const core::PinholeCamera &c)
{
  text(c.name);
  for (double x : {c.cam.get_px(), c.cam.get_py(), c.cam.get_u0(), c.cam.get_v0()})
    number(x);
  number(c.width);
  number(c.height);
  matrix(c.hMc);
  number(static_cast<double>(c.distortion.coefficients.size()));
  for (double k : c.distortion.coefficients)
    number(k);
  return *this;
}

CacheKey &CacheKey::rig(const core::CameraRig &rig)
{
  for (const core::PinholeCamera &c : rig.cameras)
    camera(c);
  return *this;
}

CacheKey &CacheKey::pass(const std::vector<model::PassView> &pass)
{
  for (const model::PassView &v : pass) {
    text(v.name);
    matrix(v.fMh);
    for (const vpImage<vpRGBa> *I : {&v.left, &v.right, &v.backgroundLeft, &v.backgroundRight})
      image(*I);
  }
  return *this;
}

std::string CacheKey::hex() const
{
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << m_h;
  return s.str();
}

LabCache LabCache::fromEnvironment()
{
  const char *dir = std::getenv("PM_LAB_CACHE");
  return LabCache(dir ? dir : "");
}

LabCache::LabCache(std::string dir) : m_dir(std::move(dir)) {}

std::optional<std::string> LabCache::read(const std::string &name) const
{
  if (!enabled())
    return std::nullopt;
  std::ifstream f(fs::path(m_dir) / name, std::ios::binary);
  if (!f)
    return std::nullopt;
  std::ostringstream s;
  s << f.rdbuf();
  if (!f && !f.eof())
    return std::nullopt;
  return s.str();
}

std::string LabCache::pathOf(const std::string &name) const { return enabled() ? (fs::path(m_dir) / name).string() : ""; }

void LabCache::write(const std::string &name, const std::string &text) const
{
  if (!enabled())
    return;
  std::error_code ec;
  fs::create_directories(m_dir, ec);
  try {
    io::writeTextFile((fs::path(m_dir) / name).string(), text);
  } catch (const core::Error &) {
    // a folder that cannot be written is a cache that keeps nothing
  }
}

LabCache::KeyLock::KeyLock(const LabCache &cache, const std::string &key)
{
  if (!cache.enabled())
    return;
  std::error_code ec;
  fs::create_directories(cache.m_dir, ec);
  m_fd = ::open((fs::path(cache.m_dir) / ("." + key + ".lock")).c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
  if (m_fd >= 0 && ::flock(m_fd, LOCK_EX) != 0) {
    ::close(m_fd);
    m_fd = -1; // no lock: the entry is made twice, never wrong
  }
}

LabCache::KeyLock::~KeyLock()
{
  if (m_fd >= 0) {
    ::flock(m_fd, LOCK_UN);
    ::close(m_fd);
  }
}

} // namespace pm::lab
