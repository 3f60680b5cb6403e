# oasis_test_target(TARGET [CXX17]): the build settings every GoogleTest executable of ours shares.
#
# Test sources took most of the build (about 20 s each of a 30-minute CI build on 2 cores) for
# programs that then run in a fraction of a second. Two settings cut that to about 5 s each:
# - No optimisation of the test sources themselves (-O0). The code under test keeps the build's
#   level: it lives in the libraries the tests link.
# - One precompiled header of GoogleTest, nlohmann/json and the standard headers the tests use,
#   built once per language level and reused by every test (REUSE_FROM needs the same flags: it
#   gets them from this function too). CMAKE_DISABLE_PRECOMPILE_HEADERS=ON (the clang-release
#   preset) builds without it, which catches a test that forgot an #include.
function(oasis_test_target target)
  cmake_parse_arguments(TEST "CXX17" "" "" ${ARGN})
  set(pch oasis_test_pch20)
  if(TEST_CXX17)
    set(pch oasis_test_pch17)
  endif()
  if(NOT TARGET ${pch})
    oasis_make_test_pch(${pch} ${TEST_CXX17})
  endif()
  oasis_test_flags(${target} ${TEST_CXX17})
  if(NOT target STREQUAL pch)
    target_precompile_headers(${target} REUSE_FROM ${pch})
  endif()
endfunction()

function(oasis_test_flags target cxx17)
  if(cxx17)
    set_target_properties(${target} PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON
                                               CXX_EXTENSIONS OFF)
  else()
    target_compile_features(${target} PRIVATE cxx_std_20)
  endif()
  target_compile_options(${target} PRIVATE -O0)
  oasis_set_warnings(${target})
endfunction()

function(oasis_make_test_pch pch cxx17)
  find_package(GTest REQUIRED)
  add_library(${pch} STATIC "${PROJECT_SOURCE_DIR}/tests/support/precompiled_headers.cpp")
  target_link_libraries(${pch} PRIVATE GTest::gtest)
  oasis_test_flags(${pch} "${cxx17}")
  set(headers <gtest/gtest.h> <algorithm> <array> <chrono> <cmath> <cstdint> <cstring>
              <filesystem> <fstream> <functional> <limits> <optional> <random> <sstream>
              <stdexcept> <string> <thread> <vector>)
  if(NOT cxx17)
    find_package(nlohmann_json 3.10 REQUIRED)
    target_link_libraries(${pch} PRIVATE nlohmann_json::nlohmann_json)
    list(APPEND headers <nlohmann/json.hpp>)
  endif()
  target_precompile_headers(${pch} PRIVATE ${headers})
endfunction()
