# pm_add_module(<name> SOURCES ... DEPENDS ...)
# One library per folder of modules/: headers in include/pm/<name>/, sources in src/.
# The library is exported as pm::<name> and installed with its headers.
function(pm_add_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  set(target pm_${name})
  add_library(${target} ${M_SOURCES})
  add_library(pm::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME pm_${name} EXPORT_NAME ${name}
                                             POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${M_DEPENDS} PRIVATE ${M_PRIVATE_DEPENDS})
  target_compile_features(${target} PUBLIC cxx_std_17)
  pm_set_warnings(${target})
  list(LENGTH M_SOURCES n)
  if(n GREATER_EQUAL 6) # below that, compiling the header costs about what it saves
    pm_precompile(module_${name} ${target} ${PM_PCH_MODULE})
  endif()
  install(TARGETS ${target} EXPORT visp-photomodelTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/pm DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()
