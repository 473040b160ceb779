# What the project's CMake projects share: the top-level one (CMakeLists.txt) and the ParaView
# plugin (Plugins/ParaView/CMakeLists.txt), which builds the same module sources.

# C++17, and a Release build unless a build type (or a multi-configuration generator) is given.
macro(vtkao_project_defaults)
  set(CMAKE_CXX_STANDARD 17)
  set(CMAKE_CXX_STANDARD_REQUIRED ON)
  if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
    set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
  endif ()
endmacro()

# vtk_module_build of one of the project's modules, as every package of it is built: headers in
# <include>/vtkao, CMake files in <lib>/cmake/vtkao, the project's version, SOVERSION 0 and
# Python wrapping when wanted (vtkao_enable_wrapping). TESTS names the module's test folder
# (relative to the module's directory), if it has one.
function(vtkao_module_build _vtkao_module)
  # Names of its own: the modules' and tests' directories are read in this scope.
  cmake_parse_arguments(PARSE_ARGV 1 _vtkao "" "PACKAGE;EXPORT;TESTS" "")
  set(_vtkao_tests "")
  if (_vtkao_TESTS)
    set(_vtkao_tests TEST_DIRECTORY_NAME "${_vtkao_TESTS}")
  endif ()
  vtk_module_build(
    MODULES             ${_vtkao_module}
    INSTALL_EXPORT      ${_vtkao_EXPORT}
    PACKAGE             ${_vtkao_PACKAGE}
    HEADERS_DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/vtkao"
    CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/vtkao"
    LIBRARY_NAME_SUFFIX ""
    VERSION             "${PROJECT_VERSION}"
    SOVERSION           "0"
    ENABLE_WRAPPING     ${vtkao_enable_wrapping}
    ${_vtkao_tests})
endfunction()

# The requested modules (vtkao_requested_modules) as position-independent code: static
# libraries linked into Python extension modules.
function(vtkao_position_independent_modules)
  foreach (vtkao_module IN LISTS vtkao_requested_modules)
    get_property(vtkao_target GLOBAL PROPERTY "_vtk_module_${vtkao_module}_target_name")
    if (vtkao_target AND TARGET "${vtkao_target}")
      set_property(TARGET "${vtkao_target}" PROPERTY POSITION_INDEPENDENT_CODE ON)
    endif ()
  endforeach ()
endfunction()
