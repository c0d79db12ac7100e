#pragma once
/*!
  \file App.h
  What every pm-* program shares: CLI11 set-up, the exit-status contract and the data folder.

  Exit status: 0 success (and --help); 2 usage error (one line on stderr); 1 runtime failure,
  printed as one line "error: <what, which file, what to do>". Nothing escapes as an
  uncaught exception or an abort.
*/
#include <functional>
#include <string>
#include <vector>

#include "pm/capture/ImageSequenceSource.h"

#include <CLI/CLI.hpp>

namespace pm::app {

//! An option's old spelling, kept for one release (docs/programs.md, "One vocabulary").
struct Renamed
{
  std::string old;                 //!< e.g. "--left-images"
  std::string now;                 //!< e.g. "--left"
  std::vector<std::string> values; //!< only when its value is one of these (empty: always)
};

/*!
  Parses the command line and runs \e body under the exit-status contract above. An argument
  spelled as one of \e renamed's old names is read as its new name, with one line on stderr:
  "pm-track: --left-images is deprecated, use --left".
*/
int run(CLI::App &app, int argc, char **argv, const std::function<int()> &body,
        const std::vector<Renamed> &renamed = {});

//! The shipped data folder: $PM_DATA_DIR, else the source tree's data/, else the installed one.
std::string dataDir();
//! dataDir() + "/" + relative.
std::string dataPath(const std::string &relative);

//! The file name of frame \e index from a printf-style pattern (pm::capture::frameFileName).
using capture::frameFileName;

/*!
  The image files of a --left or --right option: one printf pattern (e.g. "L_%04d.png": frames
  \e firstFrame, firstFrame + 1, ... while the file exists), one file, or several files in pair
  order. Throws pm::core::Error when a pattern matches no file.
*/
std::vector<std::string> imageFiles(const std::vector<std::string> &values, int firstFrame = 0);
//! True when \e values is one printf pattern (one value holding a '%').
bool isImagePattern(const std::vector<std::string> &values);

//! Parses "a,b,c,..." into exactly \e n numbers; throws CLI::ValidationError otherwise.
std::vector<double> parseNumbers(const std::string &text, std::size_t n, const std::string &what);

//! This process's resident memory (VmRSS of /proc/self/status) in MB; NaN where it cannot be read.
double residentMemoryMb();

} // namespace pm::app
