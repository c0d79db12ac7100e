# PM_SANITIZE=ON builds every target (ours) with ASan + UBSan; UB aborts the test that hit it.
if(PM_SANITIZE)
  set(_pm_san -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${_pm_san})
  add_link_options(-fsanitize=address,undefined)
  message(STATUS "visp-photomodel: building with AddressSanitizer + UndefinedBehaviorSanitizer")
endif()
