#include "pm/io/StagedFiles.h"

#include <filesystem>
#include <fstream>

#include "pm/core/Error.h"

namespace fs = std::filesystem;

namespace pm::io {

namespace {
std::string tempName(const std::string &name) { return ".partial-" + name; }
} // namespace

StagedFiles::StagedFiles(const std::string &dir) : m_dir(dir)
{
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw core::Error("cannot create the output folder '" + dir + "': " + (ec ? ec.message() : "not a folder"));
}

StagedFiles::~StagedFiles()
{
  if (m_committed)
    return;
  std::error_code ec;
  for (const auto &n : m_names)
    fs::remove(fs::path(m_dir) / tempName(n), ec);
}

std::string StagedFiles::stage(const std::string &name)
{
  m_names.push_back(name);
  return (fs::path(m_dir) / tempName(name)).string();
}

std::string StagedFiles::finalPath(const std::string &name) const { return (fs::path(m_dir) / name).string(); }

void StagedFiles::commit()
{
  // Every staged file first: a run whose outputs are incomplete commits none of them.
  for (const auto &n : m_names) {
    std::error_code ec;
    if (!fs::is_regular_file(fs::path(m_dir) / tempName(n), ec))
      throw core::Error("cannot write '" + finalPath(n) + "': it was never written");
  }
  for (const auto &n : m_names) {
    std::error_code ec;
    fs::rename(fs::path(m_dir) / tempName(n), fs::path(m_dir) / n, ec);
    if (ec)
      throw core::Error("cannot write '" + finalPath(n) + "': " + ec.message());
  }
  m_committed = true;
}

void writeTextFile(const std::string &path, const std::string &text)
{
  const fs::path p(path);
  const fs::path tmp = p.parent_path() / (".partial-" + p.filename().string());
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.flush();
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw core::Error("cannot write '" + path + "' (is the folder writable, is the disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, p, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw core::Error("cannot write '" + path + "': " + ec.message());
  }
}

} // namespace pm::io
