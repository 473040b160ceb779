# Helpers of the command-line tests: the `cmake -P` scripts that run the vtkao program (VTKAO)
# in a scratch directory (WORK). A script includes this file, starts with vtkao_test_begin(),
# counts failed checks in `failures` (each reported with SEND_ERROR, so that the script goes on
# to the next case) and ends with vtkao_test_end().

# An empty WORK directory and no failure yet.
macro(vtkao_test_begin)
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
  set(failures 0)
endmacro()

# Fails the test if a check failed: "N <what> case(s) misbehaved".
macro(vtkao_test_end what)
  if (failures)
    message(FATAL_ERROR "${failures} ${what} case(s) misbehaved")
  endif ()
endmacro()

# Reports a failed check and counts it in the caller's `failures`.
function(vtkao_fail text)
  message(SEND_ERROR "${text}")
  math(EXPR failures "${failures} + 1")
  set(failures ${failures} PARENT_SCOPE)
endfunction()

# WORK/mesh.vtk: a floor (y = 0, half-width 1) and above it a ceiling (y = 0.5, half-width 3),
# one quad each, in one legacy file.
function(vtkao_write_floor_and_ceiling)
  file(WRITE "${WORK}/mesh.vtk" "# vtk DataFile Version 3.0\nmesh\nASCII\nDATASET POLYDATA\n"
    "POINTS 8 float\n-1 0 -1  -1 0 1  1 0 1  1 0 -1  -3 0.5 -3  -3 0.5 3  3 0.5 3  3 0.5 -3\n"
    "POLYGONS 2 10\n4 0 1 2 3\n4 4 5 6 7\n")
endfunction()

# A case of a list "NAME|ARGUMENTS": the name in @p name_var, the arguments (split as a shell
# would) in @p args_var.
function(vtkao_split_case case name_var args_var)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  separate_arguments(args UNIX_COMMAND "${args}")
  set(${name_var} "${name}" PARENT_SCOPE)
  set(${args_var} "${args}" PARENT_SCOPE)
endfunction()

# vtkao_expect_usage_error(NAME [TIMEOUT SECONDS] [LEFT GLOB ...] ARGS ARG ...): the program run
# with ARGS must exit non-zero, print one non-empty line on stderr and leave no file matching
# the LEFT patterns behind.
function(vtkao_expect_usage_error name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TIMEOUT" "LEFT;ARGS")
  set(timeout "")
  if (arg_TIMEOUT)
    set(timeout TIMEOUT ${arg_TIMEOUT})
  endif ()
  execute_process(COMMAND "${VTKAO}" ${arg_ARGS} ${timeout}
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  set(left "")
  if (arg_LEFT)
    file(GLOB left ${arg_LEFT})
  endif ()
  if (rc EQUAL 0 OR left OR err STREQUAL "" OR err MATCHES "\n")
    vtkao_fail("${name}: rc=${rc}, files left='${left}', stderr='${err}'")
    set(failures ${failures} PARENT_SCOPE)
  else ()
    message(STATUS "ok: ${name}: ${err}")
  endif ()
endfunction()

# A long run's progress on stderr (@p err) when stderr is a pipe, not a terminal: a start and an
# end line, without the terminal's "\r" redraws (vtkaoProgram.h).
function(vtkao_check_progress_lines label err)
  string(ASCII 13 cr)
  string(FIND "${err}" "${cr}" cr_at)
  if (NOT err MATCHES "baking \\.\\.\\.\n" OR NOT err MATCHES "baking done \\(100%\\)" OR
      NOT cr_at EQUAL -1)
    vtkao_fail("${label}no start and end progress lines (or a terminal bar) on stderr: '${err}'")
    set(failures ${failures} PARENT_SCOPE)
  endif ()
endfunction()

# The range of the AmbientOcclusion array of the .vtp file @p path, in @p lo_var and @p hi_var
# (empty when there is none).
function(vtkao_read_ao_range path lo_var hi_var)
  file(READ "${path}" vtp)
  string(REGEX MATCH
    "Name=\"AmbientOcclusion\"[^>]*RangeMin=\"([0-9.e+-]+)\"[^>]*RangeMax=\"([0-9.e+-]+)\""
    found "${vtp}")
  set(${lo_var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  set(${hi_var} "${CMAKE_MATCH_2}" PARENT_SCOPE)
  if (NOT found)
    set(${lo_var} "" PARENT_SCOPE)
    set(${hi_var} "" PARENT_SCOPE)
  endif ()
endfunction()

# Runs the program with ARGN; it must succeed and write @p output (else the test fails at once,
# with @p what, stdout and stderr). Its stdout in `stdout`.
function(vtkao_run_or_fail what output)
  execute_process(COMMAND "${VTKAO}" ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0 OR NOT EXISTS "${output}")
    message(FATAL_ERROR "${what} failed: rc=${rc}\n${out}\n${err}")
  endif ()
  set(stdout "${out}" PARENT_SCOPE)
endfunction()
