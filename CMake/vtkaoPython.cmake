# The Python package `vtkao`:  from vtkao import vtkHybridAmbientOcclusionPass
# Included by the top-level CMakeLists.txt after the vtk_module_build calls.
#
# The package goes to <build>/${VTKAO_PYTHON_SITE_PACKAGES} and to
# <prefix>/${VTKAO_PYTHON_SITE_PACKAGES} on install. The default, lib/python3/dist-packages,
# is the layout of Debian's python3-vtk9 (/usr/lib/python3/dist-packages/vtkmodules): with
# PYTHONPATH=<prefix>/lib/python3/dist-packages, Debian's /usr/bin/python3 imports vtkao next
# to its own vtkmodules (and a /usr install needs no PYTHONPATH at all).
option(VTKAO_WRAP_PYTHON "Build the Python package vtkao (needs VTK's Python wrapping tools)" ON)
set(VTKAO_PYTHON_SITE_PACKAGES "lib/python3/dist-packages" CACHE STRING
  "Where the Python package vtkao goes, relative to the build tree and the install prefix")
set(vtkao_python_enabled OFF)
if (NOT VTKAO_WRAP_PYTHON)
  return ()
endif ()

find_package(Python3 QUIET COMPONENTS Interpreter Development.Module)
# A second find_package(VTK) adds the Python components to the ones found at the top.
find_package(VTK 9.1 QUIET COMPONENTS Python WrappingPythonCore)
if (NOT Python3_FOUND OR NOT TARGET VTK::WrappingPythonCore OR NOT TARGET VTK::WrapPython)
  message(WARNING
    "vtkao: Python 3 development files or VTK's Python wrapping were not found, so the Python "
    "package vtkao is not built (install python3-dev and python3-vtk9, pass "
    "-DPython3_EXECUTABLE=/usr/bin/python3, or configure with -DVTKAO_WRAP_PYTHON=OFF).")
  return ()
endif ()
set(vtkao_python_enabled ON)

# The modules are static libraries linked into the Python extension modules.
vtkao_position_independent_modules()

# A function: the shared-library setting below stays local to it.
function (vtkao_wrap_python)
  # Shared extension modules (the default follows BUILD_SHARED_LIBS, off in this project).
  set(BUILD_SHARED_LIBS ON)
  vtk_module_wrap_python(
    MODULES             ${vtkao_requested_modules}
    TARGET              vtkAO::vtkaoPython
    PYTHON_PACKAGE      vtkao
    MODULE_DESTINATION  "${VTKAO_PYTHON_SITE_PACKAGES}"
    LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    SOABI               "${Python3_SOABI}"
    BUILD_STATIC        OFF
    INSTALL_HEADERS     OFF)
endfunction ()
vtkao_wrap_python()

# __init__.py: one `from .<module> import *` per wrapped module.
set(vtkao_python_imports "")
foreach (vtkao_module IN LISTS vtkao_requested_modules)
  _vtk_module_get_module_property("${vtkao_module}" PROPERTY "library_name" VARIABLE vtkao_library)
  string(APPEND vtkao_python_imports "from .${vtkao_library} import *  # ${vtkao_module}\n")
endforeach ()
set(vtkao_python_has_reference False)
if (vtkao_build_reference)
  set(vtkao_python_has_reference True)
endif ()
set(vtkao_python_dir "${CMAKE_BINARY_DIR}/${VTKAO_PYTHON_SITE_PACKAGES}/vtkao")
configure_file("${CMAKE_CURRENT_LIST_DIR}/vtkao__init__.py.in" "${vtkao_python_dir}/__init__.py"
  @ONLY)
install(FILES "${vtkao_python_dir}/__init__.py"
  DESTINATION "${VTKAO_PYTHON_SITE_PACKAGES}/vtkao" COMPONENT python)

# The Python tests: /usr/bin/python3 (Python3_EXECUTABLE) with PYTHONPATH set to the build tree.
if (BUILD_TESTING)
  add_subdirectory("${CMAKE_CURRENT_SOURCE_DIR}/Testing/Python"
    "${CMAKE_BINARY_DIR}/Testing/Python")
endif ()
