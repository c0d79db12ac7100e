# PM_SANITIZE=ON builds every target (ours) with ASan + UBSan; UB aborts the test that hit it.
if(PM_SANITIZE)
  set(_pm_san -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${_pm_san})
  add_link_options(-fsanitize=address,undefined)
  message(STATUS "visp-photomodel: building with AddressSanitizer + UndefinedBehaviorSanitizer")
endif()

# pm_unoptimised_drivers(): in the sanitizers' build, the targets made after it in the calling folder
# compile unoptimised (-O0, after the build type's -O2). For the tests, the programs and the
# benchmarks: they drive the modules, whose code (kept at -O2) is where the time is spent, and
# instrumented code at -O2 is what makes this build long (a test file 37 s at -O2, 14 s at -O0).
# The sanitizers check them just the same. Nothing in the other builds.
function(pm_unoptimised_drivers)
  if(PM_SANITIZE)
    set_property(DIRECTORY APPEND PROPERTY COMPILE_OPTIONS -O0)
  endif()
endfunction()

# PM_FUZZ=ON: every target of ours instrumented for libFuzzer, with ASan + UBSan (clang only).
# Line tables only (after RelWithDebInfo's -g, the last wins), as in the sanitizers' build: a crash's
# stack still names function, file and line (inlined frames too); full debug information only makes
# CI's build from scratch longer.
if(PM_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PM_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  if(PM_SANITIZE)
    message(FATAL_ERROR "PM_FUZZ already builds with the sanitizers: leave PM_SANITIZE off")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -gline-tables-only)
  add_link_options(-fsanitize=address,undefined)
  message(STATUS "visp-photomodel: building the fuzz targets (libFuzzer + ASan + UBSan)")
endif()
