#pragma once
/*!
  \file LabCache.h
  A folder of what the lab made already, keyed by what it was made from, so that a run of the test
  suite makes each lab model (ModelCache.h) and each trust calibration (TrustCache.h) once instead of
  in every test and tutorial that needs it. Off unless the environment variable PM_LAB_CACHE names a
  folder: scripts/test.sh names one after a hash of the sources, so that an entry is always one that
  the code under test made.

  The rules it holds:
  - A key (CacheKey) is a 64-bit FNV-1a hash of everything the entry was made from: the rig's
    cameras, every image and hand pose of the pass, the parameters, named by what the entry is.
  - It never fails a run: a folder that cannot be read or written is a cache that finds nothing;
    an entry is written whole or not at all (io::writeTextFile), so a reader never sees half of one.
  - Two programs that need the same entry at once make it once: the second waits on the key's lock
    (KeyLock) and then finds what the first stored.

  \code
    const pm::lab::LabCache cache = pm::lab::LabCache::fromEnvironment();
    const std::string key = pm::lab::CacheKey("my entry 1").rig(rig).pass(pass).hex();
    const std::string text = pm::lab::findOrMake<std::string>(
        cache, key, [&](const std::string &k) { return cache.read(k + ".txt"); },
        [] { return std::string("what was made"); },
        [&](const std::string &k, const std::string &made) { cache.write(k + ".txt", made); });
  \endcode
*/
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraRig.h"
#include "pm/model/PassView.h"

namespace pm::lab {

//! The key of a cache entry: FNV-1a (64 bits) over what the entry was made from (see LabCache.h).
class CacheKey
{
public:
  //! A key for an entry of kind \e what (name it with a version: a change of format is a new kind).
  explicit CacheKey(const std::string &what) { text(what); }
  //! Adds \e n bytes at \e p.
  CacheKey &bytes(const void *p, std::size_t n);
  //! Adds \e x (its 8 bytes: a change in its last bit is another key).
  CacheKey &number(double x) { return bytes(&x, sizeof x); }
  //! Adds \e s with its length.
  CacheKey &text(const std::string &s);
  //! Adds \e I's size and every pixel.
  CacheKey &image(const vpImage<vpRGBa> &I);
  //! Adds \e M's 16 numbers.
  CacheKey &matrix(const vpHomogeneousMatrix &M);
  //! Both cameras: name, intrinsics, image size, pose on the hand, lens distortion.
  CacheKey &rig(const core::CameraRig &rig);
  //! Every view: its name, hand pose and the four images (with and without the target).
  CacheKey &pass(const std::vector<model::PassView> &pass);
  //! 16 hex digits.
  std::string hex() const;

private:
  CacheKey &camera(const core::PinholeCamera &c);
  std::uint64_t m_h = 0xcbf29ce484222325ull;
};

//! A folder of entries named by their keys (see LabCache.h).
class LabCache
{
public:
  //! The folder PM_LAB_CACHE names, or none (a cache that finds and keeps nothing).
  static LabCache fromEnvironment();
  //! \e dir (created when something is stored; empty: none).
  explicit LabCache(std::string dir = "");
  //! True when it has a folder (false: it finds and keeps nothing).
  bool enabled() const { return !m_dir.empty(); }
  //! The text of entry \e name (a file name in the folder), if there is one.
  std::optional<std::string> read(const std::string &name) const;
  //! The path of entry \e name (for a reader of files; empty without a folder).
  std::string pathOf(const std::string &name) const;
  //! Writes entry \e name whole (or not at all, silently: a cache never fails a run).
  void write(const std::string &name, const std::string &text) const;

  //! Holds \e key's lock (flock) while it lives: another process or thread locking the same key waits.
  class KeyLock
  {
  public:
    //! Waits for \e key's lock in \e cache's folder and takes it (nothing for a cache without a folder).
    KeyLock(const LabCache &cache, const std::string &key);
    //! Releases the lock.
    ~KeyLock();
    KeyLock(const KeyLock &) = delete;
    KeyLock &operator=(const KeyLock &) = delete;

  private:
    int m_fd = -1;
  };

private:
  std::string m_dir;
};

/*!
  Entry \e key of \e cache, of type T: what \e find(key) gives back (a std::optional<T>); else, with
  the key's lock held, what it gives back now (another program made it meanwhile); else what
  \e make() makes, handed to \e store(key, made) before it is returned. Without a folder: \e make()
  alone. The one way the lab's caches look up an entry (the rules of LabCache.h).
*/
template <class T, class Find, class Make, class Store>
T findOrMake(const LabCache &cache, const std::string &key, const Find &find, const Make &make, const Store &store)
{
  if (!cache.enabled())
    return make();
  if (std::optional<T> found = find(key))
    return std::move(*found);
  const LabCache::KeyLock lock(cache, key); // another program making it now: wait for it
  if (std::optional<T> found = find(key))
    return std::move(*found);
  T made = make();
  store(key, made);
  return made;
}

} // namespace pm::lab
