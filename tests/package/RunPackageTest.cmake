# Installs the build into a temporary prefix, then configures and builds a small ViSP program
# outside the tree that finds us with find_package(visp-photomodel) and runs it.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/consumer -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(rc)
  message(FATAL_ERROR "the consumer failed")
endif()
# The Python module as installed: imported from the prefix's dist-packages, with its stubs beside it.
if(PYTHON_EXE)
  if(NOT EXISTS ${WORK_DIR}/prefix/${PYTHON_DIR}/visp_photomodel-stubs/__init__.pyi)
    message(FATAL_ERROR "the Python module's stubs are not installed in ${PYTHON_DIR}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${WORK_DIR}/prefix/${PYTHON_DIR}
                          ${PYTHON_EXE} -c "import visp_photomodel as pm; print('python:', pm.__file__, pm.load_rig(pm.data_path('rig/pa10_stereo.json')))"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}${err}")
  if(rc OR NOT out MATCHES "prefix/${PYTHON_DIR}/visp_photomodel")
    message(FATAL_ERROR "the installed Python module does not import from the prefix")
  endif()
endif()
file(REMOVE_RECURSE ${WORK_DIR})
