# Finds what the Python module (python/) needs and sets the default of
# MESHDIFF_BUILD_PYTHON: a Python 3 interpreter that can import numpy and has
# its C headers, and pybind11 (Debian: python3-numpy, python3-dev, pybind11-dev).
#
# The interpreter: the one given by -DPython3_EXECUTABLE, -DPython_EXECUTABLE or
# -DPYTHON_EXECUTABLE if any (and only it); otherwise the first of
# /usr/bin/python3 (Debian's) and python3 on PATH that can import numpy. The
# python3 first on PATH may be another installation without numpy (pyenv),
# which is why /usr/bin/python3 comes first. The choice is in the cache as
# MESHDIFF_PYTHON_EXECUTABLE (scripts/test.sh runs pytest with it).
#
# Sets MESHDIFF_PYTHON_FOUND, MESHDIFF_PYTHON_WHY_NOT and, when found,
# MESHDIFF_PYTHON_EXECUTABLE, and finds pybind11 with that interpreter.

set(MESHDIFF_PYTHON_FOUND OFF)
set(MESHDIFF_PYTHON_WHY_NOT "")

set(_md_given "")
foreach(_md_var Python3_EXECUTABLE Python_EXECUTABLE PYTHON_EXECUTABLE)
    if(${_md_var} AND NOT _md_given)
        set(_md_given "${${_md_var}}")
    endif()
endforeach()
if(_md_given)
    set(_md_candidates "${_md_given}")
else()
    find_program(_md_path_python3 NAMES python3 NO_CACHE)
    set(_md_candidates /usr/bin/python3)
    if(_md_path_python3)
        list(APPEND _md_candidates "${_md_path_python3}")
    endif()
    list(REMOVE_DUPLICATES _md_candidates)
endif()

# Exit 0: numpy and Python.h; 3: numpy but no headers; anything else: no numpy.
set(_md_probe "import os, sys, sysconfig, numpy
inc = sysconfig.get_config_var('INCLUDEPY') or ''
sys.exit(0 if os.path.exists(os.path.join(inc, 'Python.h')) else 3)")
set(_md_tried "")
foreach(_md_py IN LISTS _md_candidates)
    if(NOT EXISTS "${_md_py}")
        string(APPEND _md_tried " ${_md_py} (missing)")
        continue()
    endif()
    execute_process(COMMAND "${_md_py}" -c "${_md_probe}" RESULT_VARIABLE _md_rc OUTPUT_QUIET ERROR_QUIET)
    if(_md_rc EQUAL 0)
        set(MESHDIFF_PYTHON_EXECUTABLE "${_md_py}" CACHE INTERNAL "the Python interpreter of the meshdiff module")
        set(MESHDIFF_PYTHON_FOUND ON)
        break()
    elseif(_md_rc EQUAL 3)
        string(APPEND _md_tried " ${_md_py} (numpy, but no Python.h: install python3-dev)")
    else()
        string(APPEND _md_tried " ${_md_py} (cannot import numpy)")
    endif()
endforeach()

if(NOT MESHDIFF_PYTHON_FOUND)
    set(MESHDIFF_PYTHON_WHY_NOT "no usable Python 3 interpreter; tried:${_md_tried} (Debian: python3-numpy python3-dev)")
else()
    # pybind11's FindPython mode, with the interpreter chosen above.
    set(PYBIND11_FINDPYTHON ON)
    set(Python_EXECUTABLE "${MESHDIFF_PYTHON_EXECUTABLE}")
    find_package(pybind11 2.6 CONFIG QUIET)
    if(NOT pybind11_FOUND)
        set(MESHDIFF_PYTHON_FOUND OFF)
        set(MESHDIFF_PYTHON_WHY_NOT "pybind11 not found (Debian: pybind11-dev)")
    endif()
endif()
