# drillflex_precompile(<target> [TEST])
# With DRILLFLEX_PCH, the headers nearly every translation unit parses (Eigen's core, geometry and
# sparse modules, fmt and the standard library; GoogleTest for TEST targets) are precompiled once per
# target instead of parsed by each of its sources: the parse of Eigen alone is ~2 s of a
# translation unit's ~5 s. Each target compiles its own header with its own flags, so the sanitizer
# and assertion builds stay consistent.
function(drillflex_precompile target)
  if(NOT DRILLFLEX_PCH)
    return()
  endif()
  set(headers <algorithm> <cmath> <functional> <memory> <optional> <string> <vector>
              <Eigen/Core> <Eigen/Geometry> <Eigen/SparseCore> <fmt/format.h>)
  if("TEST" IN_LIST ARGN)
    list(APPEND headers <gtest/gtest.h>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

# drillflex_layer(<layer> [DEPENDS <targets>...])
# One library target per layer, drillflex_<layer>, from src/<layer>/*.cpp. A layer that has only
# headers so far is an INTERFACE target, so the layer graph stays the same as the code grows.
function(drillflex_layer layer)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(sources)
    add_library(drillflex_${layer} STATIC ${sources})
    target_link_libraries(drillflex_${layer} PUBLIC ${ARG_DEPENDS})
    drillflex_precompile(drillflex_${layer})
  else()
    add_library(drillflex_${layer} INTERFACE)
    target_link_libraries(drillflex_${layer} INTERFACE ${ARG_DEPENDS})
  endif()
endfunction()

# drillflex_test_code(<target>)
# A test or validation executable: with DRILLFLEX_SANITIZE and DRILLFLEX_SANITIZE_TESTS off, its own
# sources compile without the sanitizers' instrumentation (the engine it links stays instrumented).
# With DRILLFLEX_UNITY_TESTS its sources compile DRILLFLEX_UNITY_BATCH at a time as one translation
# unit (CMake's unity build): a test file spends most of its compile on instantiating the same
# GoogleTest and Eigen templates, which a batch instantiates once.
function(drillflex_test_code target)
  if(DRILLFLEX_SANITIZE AND NOT DRILLFLEX_SANITIZE_TESTS)
    set_property(TARGET ${target} PROPERTY DRILLFLEX_TEST_CODE ON)
  endif()
  if(DRILLFLEX_UNITY_TESTS)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${DRILLFLEX_UNITY_BATCH})
  endif()
endfunction()
