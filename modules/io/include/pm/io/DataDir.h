#pragma once
/*!
  \file DataDir.h
  Where the shipped data (rigs, trajectories, calibration boards) is found: the programs' and the
  Python module's one rule.

  \code
      const std::string rig = pm::io::dataDir(PM_SOURCE_DATA_DIR, PM_INSTALL_DATA_DIR) + "/rig/pa10_stereo.json";
  \endcode
*/
#include <string>

namespace pm::io {

/*!
  $PM_DATA_DIR when set; else \e sourceDir (the source tree's data/, while it exists), else
  \e installDir (share/visp-photomodel of the installed package) when it exists; else "data".
*/
std::string dataDir(const std::string &sourceDir, const std::string &installDir);

} // namespace pm::io
