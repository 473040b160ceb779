# The installed Python package: `cmake --install --component python` into a scratch prefix, then Debian's python3
# imports vtkao with PYTHONPATH=<prefix>/<site dir> only (not the build tree) beside Debian's
# vtkmodules, checks it was loaded from the prefix, and renders the example from there.
# -DBUILD_TREE=<build dir> -DWORK=<scratch> -DPYTHON=<python3> -DSITE=<site dir suffix>
# -DEXAMPLE=<hao_example.py> -DCONFIG=<config>
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_TREE}" --prefix "${WORK}/prefix"
    --config "${CONFIG}" --component python
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${err}")
endif ()
set(site "${WORK}/prefix/${SITE}")
file(GLOB modules "${site}/vtkao/*.so")
if (NOT EXISTS "${site}/vtkao/__init__.py" OR NOT modules)
  message(FATAL_ERROR "no Python package under ${site}/vtkao")
endif ()
message(STATUS "installed: ${modules}")
set(ENV{PYTHONPATH} "${site}")
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
execute_process(COMMAND "${PYTHON}" -c
  "import vtkao, sys; from vtkao import vtkHybridAmbientOcclusionPass as P; p = P(); assert vtkao.__file__.startswith(sys.argv[1]), vtkao.__file__; print('ok: imported', p.GetClassName(), 'from', vtkao.__file__)"
  "${site}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "import from the install prefix failed:\n${out}\n${err}")
endif ()
message(STATUS "${out}")
execute_process(COMMAND "${PYTHON}" "${EXAMPLE}" "${WORK}/installed.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/installed.png")
  message(FATAL_ERROR "the example failed against the install prefix:\n${out}\n${err}")
endif ()
message(STATUS "ok: the example rendered with the installed package: ${out}")
