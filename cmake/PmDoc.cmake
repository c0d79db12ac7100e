# The API documentation (Doxygen): `cmake --build <build> --target doc` -> <build>/doc/html/index.html.
# Built from every module's public headers, README.md and docs/*.md; a warning fails the build.
find_package(Doxygen QUIET)
if(NOT DOXYGEN_FOUND)
  add_custom_target(doc COMMAND ${CMAKE_COMMAND} -E echo "error: doxygen not found; apt-get install doxygen graphviz"
                        COMMAND ${CMAKE_COMMAND} -E false)
  return()
endif()
file(GLOB pm_doc_include_dirs LIST_DIRECTORIES true ${PROJECT_SOURCE_DIR}/modules/*/include)
list(SORT pm_doc_include_dirs)
string(REPLACE ";" " " PM_DOC_INCLUDE_ROOTS "${pm_doc_include_dirs}")
set(PM_DOC_INPUT "${PM_DOC_INCLUDE_ROOTS} ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/docs")
set(PM_DOC_OUTPUT ${PROJECT_BINARY_DIR}/doc)
if(DOXYGEN_DOT_FOUND)
  set(PM_DOC_HAVE_DOT YES)
else()
  set(PM_DOC_HAVE_DOT NO)
endif()
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${PROJECT_BINARY_DIR}/Doxyfile @ONLY)
add_custom_target(doc COMMAND ${DOXYGEN_EXECUTABLE} ${PROJECT_BINARY_DIR}/Doxyfile
                  WORKING_DIRECTORY ${PROJECT_BINARY_DIR}
                  COMMENT "API documentation (Doxygen) -> ${PM_DOC_OUTPUT}/html/index.html" VERBATIM)
