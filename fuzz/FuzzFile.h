#pragma once
/*!
  \file FuzzFile.h
  Our loaders read files, libFuzzer hands out bytes: each fuzz target writes its input into a
  scratch file of its own process and calls the loader on that path. A loader may refuse any
  input, but only with pm::core::Error: anything else escaping (another exception type, a sanitizer
  report, a crash, an allocation over libFuzzer's limit) is a finding.
*/
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "pm/core/Error.h"

namespace pm::fuzz {

//! A folder of this process's own under the system's temporary folder, made on first use.
inline const std::filesystem::path &scratchDir()
{
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("pm-fuzz-" + std::to_string(::getpid()));
    std::error_code ec;
    std::filesystem::remove_all(d, ec); // a folder left by an earlier process of the same pid (its files would be reused)
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

//! Writes \e size bytes into \e name under scratchDir(); returns the path.
inline std::string writeScratch(const std::string &name, const std::uint8_t *data, std::size_t size)
{
  const std::string path = (scratchDir() / name).string();
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
  return path;
}

inline std::string writeScratch(const std::string &name, const std::string &text)
{
  return writeScratch(name, reinterpret_cast<const std::uint8_t *>(text.data()), text.size());
}

//! Runs \e load: a pm::core::Error is a refusal, which is fine; anything else escapes, a finding.
template <class Load>
void loadOrRefuse(Load &&load)
{
  try {
    load();
  } catch (const pm::core::Error &) {
  }
}

} // namespace pm::fuzz
