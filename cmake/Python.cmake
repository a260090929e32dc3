# The Python module `gsp` (python/): built when pybind11 (Debian's pybind11-dev) is found,
# for Debian's /usr/bin/python3 (which has numpy) unless Python_EXECUTABLE says otherwise:
# the `python3` first on PATH may be another interpreter without numpy. pip builds pass
# their own interpreter (setup.py).
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the gsp module is built for")
endif()
set(PYBIND11_FINDPYTHON ON)
find_package(pybind11 2.6 CONFIG QUIET)
option(GSP_BUILD_PYTHON "Build the Python module gsp (needs pybind11)" ${pybind11_FOUND})
if(GSP_BUILD_PYTHON)
  if(NOT pybind11_FOUND)
    message(FATAL_ERROR "GSP_BUILD_PYTHON needs pybind11 (Debian: apt-get install pybind11-dev python3-dev)")
  endif()
  # The static libraries end up inside a shared object. -fno-semantic-interposition keeps
  # GCC inlining and calling our own functions directly, as in a non-PIC build.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  add_compile_options($<$<CXX_COMPILER_ID:GNU>:-fno-semantic-interposition>)
endif()
