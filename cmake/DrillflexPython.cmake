# Whether the Python module (python/) is built: DRILLFLEX_PYTHON. It needs pybind11 (Debian's
# pybind11-dev) and the Python headers (python3-dev), found for Debian's /usr/bin/python3 unless
# Python_EXECUTABLE names another interpreter (pip install . passes its own). Without them the module is
# skipped with a message and the rest builds as before. Not in a sanitizer build: an ASan-instrumented
# module loads only into a python started with the ASan runtime preloaded (.ci/run leaves it out).
set(DRILLFLEX_PYTHON OFF)
if(NOT DRILLFLEX_BUILD_PYTHON)
  return()
endif()
if(DRILLFLEX_SANITIZE)
  message(STATUS "drillflex: the Python module is not built with DRILLFLEX_SANITIZE")
  return()
endif()
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python 3.9 COMPONENTS Interpreter Development.Module QUIET)
if(Python_FOUND)
  find_package(pybind11 2.10 CONFIG QUIET)
endif()
if(NOT Python_FOUND OR NOT pybind11_FOUND)
  message(STATUS "drillflex: the Python module is skipped (pybind11 and the Python headers not found: "
                 "scripts/install-deps installs pybind11-dev and python3-dev)")
  return()
endif()
message(STATUS "drillflex: the Python module for ${Python_EXECUTABLE} (${Python_VERSION}), pybind11 ${pybind11_VERSION}")
set(DRILLFLEX_PYTHON ON)
# The module is a shared object, so every layer it links compiles position-independent.
# -fno-semantic-interposition keeps GCC inlining and calling the layers' own functions directly, as in an
# executable (nothing interposes them); measured in docs/python.md.
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
add_compile_options($<$<CXX_COMPILER_ID:GNU,Clang>:-fno-semantic-interposition>)
