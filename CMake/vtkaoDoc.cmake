# API documentation: `cmake --build <build> --target doc` writes <build>/Documentation/html when
# Doxygen is installed (apt-get install doxygen). Without Doxygen there is no doc target.
find_package(Doxygen QUIET)
if (DOXYGEN_FOUND)
  set(vtkao_doc_output "${CMAKE_BINARY_DIR}/Documentation")
  configure_file("${CMAKE_CURRENT_LIST_DIR}/../Documentation/Doxyfile.in"
    "${vtkao_doc_output}/Doxyfile" @ONLY)
  add_custom_target(doc
    COMMAND Doxygen::doxygen "${vtkao_doc_output}/Doxyfile"
    WORKING_DIRECTORY "${vtkao_doc_output}"
    COMMENT "Doxygen: ${vtkao_doc_output}/html/index.html"
    VERBATIM)
  if (BUILD_TESTING)
    # The API documentation builds without a warning.
    add_test(NAME vtkao-Doc
      COMMAND "${CMAKE_COMMAND}" --build "${CMAKE_BINARY_DIR}" --target doc)
  endif ()
else ()
  message(STATUS "vtkao: Doxygen not found: no `doc` target (optional)")
endif ()
