#pragma once
/*!
  \file StagedFiles.h
  Output files that appear only when a run succeeds. stage("model.json") returns a hidden
  temporary path in the output folder to write to; commit() renames every staged file to
  its final name; anything not committed is deleted when the object goes away (an error, an
  exception), so no half-written file is ever left behind as if complete.
*/
#include <string>
#include <vector>

namespace pm::io {

/*!
  Output files staged in a folder until commit() (see StagedFiles.h):

  \code
#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"

int main()
{
  pm::io::StagedFiles out("results");
  pm::io::writeTextFile(out.stage("summary.json"), "{}\n");
  pm::io::writeImage(vpImage<unsigned char>(480, 640, 0), out.stage("mask.png"));
  out.commit(); // both files appear; an exception before this line leaves neither
}
  \endcode
*/
class StagedFiles
{
public:
  //! Creates \e dir (and parents) if missing. Throws pm::core::Error if it cannot.
  explicit StagedFiles(const std::string &dir);
  //! Deletes the staged files unless commit() succeeded.
  ~StagedFiles();
  StagedFiles(const StagedFiles &) = delete;
  StagedFiles &operator=(const StagedFiles &) = delete;

  //! A temporary path for \e name (which keeps its extension, so writers that pick the format from it work).
  std::string stage(const std::string &name);
  //! The final path of \e name in the folder.
  std::string finalPath(const std::string &name) const;
  //! Renames every staged file to its final name; if one was never written, none (throws pm::core::Error naming it).
  void commit();
  //! The output folder, as given to the constructor.
  const std::string &dir() const { return m_dir; }

private:
  std::string m_dir;
  std::vector<std::string> m_names;
  bool m_committed = false;
};

//! Writes \e text to \e path through a temporary file and a rename. Throws pm::core::Error.
void writeTextFile(const std::string &path, const std::string &text);

} // namespace pm::io
