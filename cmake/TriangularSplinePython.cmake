# The Python module `tspline` (python/), built when pybind11 and a Python 3 with numpy are
# found: TRIANGULAR_SPLINE_BUILD_PYTHON defaults to ON then (top level only).
#
# The interpreter is the first of Python3_EXECUTABLE (if given), `python3` on PATH and
# /usr/bin/python3 that imports numpy: a python3 earlier on PATH without numpy (pyenv,
# a virtual environment) would build a module that its tests cannot import.
if(NOT DEFINED Python3_EXECUTABLE)
  find_program(TRIANGULAR_SPLINE_PATH_PYTHON NAMES python3)
  foreach(candidate ${TRIANGULAR_SPLINE_PATH_PYTHON} /usr/bin/python3)
    if(EXISTS ${candidate})
      execute_process(COMMAND ${candidate} -c "import numpy" RESULT_VARIABLE numpy_missing
                      OUTPUT_QUIET ERROR_QUIET)
      if(numpy_missing EQUAL 0)
        set(Python3_EXECUTABLE ${candidate} CACHE FILEPATH "Python 3 interpreter (with numpy)")
        break()
      endif()
    endif()
  endforeach()
endif()

set(triangular_spline_python_found OFF)
if(DEFINED Python3_EXECUTABLE)
  find_package(Python3 3.7 QUIET COMPONENTS Interpreter Development.Module)
  if(Python3_FOUND)
    # pybind11 then uses FindPython3's result (its "new" mode), not FindPythonLibs.
    find_package(pybind11 2.6 CONFIG QUIET)
    if(pybind11_FOUND)
      set(triangular_spline_python_found ON)
    endif()
  endif()
endif()

if(TRIANGULAR_SPLINE_IS_TOP_LEVEL)
  set(triangular_spline_python_default ${triangular_spline_python_found})
else()
  set(triangular_spline_python_default OFF)
endif()
option(TRIANGULAR_SPLINE_BUILD_PYTHON "Build the Python module tspline (pybind11)"
       ${triangular_spline_python_default})
# Debian's layout: /usr/lib/python3/dist-packages for the prefix /usr; for any other prefix
# P, PYTHONPATH=P/lib/python3/dist-packages.
set(TRIANGULAR_SPLINE_PYTHON_INSTALL_DIR "lib/python3/dist-packages"
    CACHE STRING "Where cmake --install puts the Python package, relative to the prefix")

if(TRIANGULAR_SPLINE_BUILD_PYTHON)
  if(NOT triangular_spline_python_found)
    message(FATAL_ERROR "TRIANGULAR_SPLINE_BUILD_PYTHON needs pybind11 (Debian: pybind11-dev) "
                        "and Python 3 with numpy and its headers (python3-dev, python3-numpy)")
  endif()
  message(STATUS "Python module tspline: ${Python3_EXECUTABLE} (${Python3_VERSION}), "
                 "pybind11 ${pybind11_VERSION}")
  add_subdirectory(python)
else()
  message(STATUS "Python module tspline: not built (TRIANGULAR_SPLINE_BUILD_PYTHON is OFF; it "
                 "needs pybind11-dev and python3-numpy)")
endif()
