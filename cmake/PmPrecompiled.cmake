# Precompiled headers: every program and every test is one translation unit that parses the same
# external headers (ViSP, OpenCV, Eigen, nlohmann-json, and CLI11 or GoogleTest) before a line of
# its own. pm_precompile(<group> <target> <headers>...) compiles them once per group, in the group's
# first target, and every later target of the group reuses that result (same flags within a group).
# The targets of a group must share their compile definitions (GCC refuses a header precompiled
# under other -D's, -Winvalid-pch says so). It halves the build of apps/ and tests/, which CI makes
# twice (Release and the sanitizers).
option(PM_PCH "Precompile the external headers the programs and the tests share" ON)

function(pm_precompile group target)
  if(NOT PM_PCH)
    return()
  endif()
  get_property(owner GLOBAL PROPERTY PM_PCH_OWNER_${group})
  if(owner)
    target_precompile_headers(${target} REUSE_FROM ${owner})
  else()
    target_precompile_headers(${target} PRIVATE ${ARGN})
    set_property(GLOBAL PROPERTY PM_PCH_OWNER_${group} ${target})
  endif()
  # A precompiled header that does not fit is skipped silently by GCC: make it say so.
  target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Winvalid-pch>)
endfunction()

# What the sources of a module parse (a module of six sources or more precompiles them, alone).
set(PM_PCH_MODULE
  <algorithm> <array> <cmath> <cstdint> <functional> <memory> <string> <vector>
  <visp3/core/vpCameraParameters.h> <visp3/core/vpColVector.h> <visp3/core/vpHomogeneousMatrix.h>
  <visp3/core/vpImage.h> <visp3/core/vpMatrix.h> <visp3/core/vpRGBa.h>)

# What every pm-* program and every test parses, with CLI11 or GoogleTest.
set(PM_PCH_EXTERNAL ${PM_PCH_MODULE}
  <filesystem> <fstream> <iostream> <map> <optional> <random> <sstream>
  <nlohmann/json.hpp> <opencv2/core.hpp> <visp3/core/vpThetaUVector.h>)
