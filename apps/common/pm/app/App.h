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

#include "pm/capture/ImageSequenceSource.h"

#include <CLI/CLI.hpp>

namespace pm::app {

//! Parses the command line and runs \e body under the exit-status contract above.
int run(CLI::App &app, int argc, char **argv, const std::function<int()> &body);

//! The shipped data folder: $PM_DATA_DIR, else the source tree's data/, else the installed one.
std::string dataDir();
//! dataDir() + "/" + relative.
std::string dataPath(const std::string &relative);

//! The file name of frame \e index from a printf-style pattern (pm::capture::frameFileName).
using capture::frameFileName;

//! Parses "a,b,c,..." into exactly \e n numbers; throws CLI::ValidationError otherwise.
std::vector<double> parseNumbers(const std::string &text, std::size_t n, const std::string &what);

//! This process's resident memory (VmRSS of /proc/self/status) in MB; NaN where it cannot be read.
double residentMemoryMb();

} // namespace pm::app
