# oasis_add_catalog(TARGET SPEC [BASENAME NAME] [WITH_BINARY])
#
# Compiles SPEC with oasisc at build time (like protobuf_generate) into C++ tables and makes
# TARGET a static library holding them, linked to the header-only runtime. A robot program
# needs three lines:
#
#   oasis_add_catalog(treat_catalog specs/go1_treat.oasis)
#   add_executable(robot robot.cpp)
#   target_link_libraries(robot PRIVATE treat_catalog)
#
# and then `#include "go1_treat_catalog.hpp"` and `go1_treat::catalog()`. The files are
# generated in the build tree (never the source tree) and regenerated when the spec, a PRISM
# program it imports (`import "robot.nm";`, found when CMake configures) or oasisc changes. BASENAME names the files (default: the spec's file name + "_catalog").
# WITH_BINARY also writes the binary catalog from the same compile, as
# ${CMAKE_CURRENT_BINARY_DIR}/TARGET.catalog/MODEL.bin (MODEL: the spec's `mdp` name, by
# convention its file name), for a program that links the tables and also loads or ships the
# file; one compile instead of two.
#
# In this repository the compiler is the `oasisc` target; in an installed package (find_package
# (oasis)) it is the imported oasis::oasisc. The cache variable OASIS_CATALOG_COMPILER, when it
# names an existing oasisc, is used instead, like a host tool when cross-compiling: the asan
# preset points it at the default build's optimised oasisc, since the sanitised one takes about
# 60 times longer (ten minutes on 2 cores for specs/go1_treat.oasis) to write the same tables.
function(oasis_add_catalog target spec)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "WITH_BINARY" "BASENAME" "")
  get_property(told GLOBAL PROPERTY OASIS_CATALOG_COMPILER_TOLD)
  if(OASIS_CATALOG_COMPILER AND NOT EXISTS "${OASIS_CATALOG_COMPILER}" AND NOT told)
    message(STATUS "OASIS_CATALOG_COMPILER (${OASIS_CATALOG_COMPILER}) does not exist: catalogs "
                   "are compiled with this tree's oasisc")
    set_property(GLOBAL PROPERTY OASIS_CATALOG_COMPILER_TOLD TRUE)
  endif()
  if(OASIS_CATALOG_COMPILER AND EXISTS "${OASIS_CATALOG_COMPILER}")
    set(compiler_file "${OASIS_CATALOG_COMPILER}")
    set(compiler_depends "${OASIS_CATALOG_COMPILER}")
  elseif(TARGET oasisc)
    set(compiler_file "$<TARGET_FILE:oasisc>")
    set(compiler_depends oasisc)
  elseif(TARGET oasis::oasisc)
    set(compiler_file "$<TARGET_FILE:oasis::oasisc>")
    set(compiler_depends oasis::oasisc)
  else()
    message(FATAL_ERROR "oasis_add_catalog(${target}) needs oasisc, the compiler: this oasis was "
                        "built or installed without it (OASIS_BUILD_COMPILER=OFF). Compile the "
                        "catalog elsewhere and load its .bin with rt::LoadedCatalog instead.")
  endif()
  get_filename_component(spec_path "${spec}" ABSOLUTE)
  get_filename_component(stem "${spec}" NAME_WE)
  if(NOT ARG_BASENAME)
    set(ARG_BASENAME "${stem}_catalog")
  endif()
  # A directory of its own: compile replaces it as a whole (support/staged_directory.hpp).
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/${target}.catalog")
  set(outputs "${out_dir}/${ARG_BASENAME}.hpp" "${out_dir}/${ARG_BASENAME}.cpp")
  set(formats cpp)
  if(ARG_WITH_BINARY)
    set(formats cpp,bin)
    list(APPEND outputs "${out_dir}/${stem}.bin")
  endif()
  # A spec may import a PRISM program: the catalog depends on it too. The spec is read here, so
  # an edit to it configures again, to find a new import.
  get_filename_component(spec_dir "${spec_path}" DIRECTORY)
  set(imported_files "")
  file(STRINGS "${spec_path}" import_lines REGEX "^[ \t]*import[ \t]+\"[^\"]+\"")
  foreach(line IN LISTS import_lines)
    string(REGEX REPLACE "^[ \t]*import[ \t]+\"([^\"]+)\".*" "\\1" imported "${line}")
    get_filename_component(imported "${imported}" ABSOLUTE BASE_DIR "${spec_dir}")
    list(APPEND imported_files "${imported}")
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${spec_path}")
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND "${compiler_file}" compile "${spec_path}" -o "${out_dir}" --format ${formats}
            --basename "${ARG_BASENAME}" --progress never
    DEPENDS ${compiler_depends} "${spec_path}" ${imported_files}
    COMMENT "oasisc: compiling the catalog of ${spec}"
    VERBATIM)
  add_library(${target} STATIC "${out_dir}/${ARG_BASENAME}.hpp" "${out_dir}/${ARG_BASENAME}.cpp")
  target_include_directories(${target} PUBLIC "${out_dir}")
  target_link_libraries(${target} PUBLIC oasis::runtime)
  target_compile_features(${target} PUBLIC cxx_std_17)
endfunction()
