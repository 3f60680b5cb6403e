# Installation: `cmake --install build --prefix P` puts the programs in P/bin, the runtime's
# headers in P/include/oasis, the CMake package (oasisConfig.cmake, its version file, the
# exported targets oasis::runtime and oasis::oasisc, oasis_add_catalog()) in
# P/lib/cmake/oasis, the shipped specs in P/share/oasis/specs and the documentation in
# P/share/doc/oasis, the Python module in P/lib/python3/dist-packages/oasis (with
# OASIS_BUILD_PYTHON). `cpack -G DEB` (in the build directory) makes a Debian package of the
# same files, its dependencies computed by dpkg-shlibdeps.
include(CMakePackageConfigHelpers)

set(OASIS_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/oasis")
install(EXPORT oasisTargets NAMESPACE oasis:: DESTINATION "${OASIS_CMAKE_DIR}")
configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/oasisConfig.cmake.in" "${PROJECT_BINARY_DIR}/oasisConfig.cmake"
  INSTALL_DESTINATION "${OASIS_CMAKE_DIR}")
# 0.x: a minor version may change the catalog schema, so only the same minor is compatible.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/oasisConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/oasisConfig.cmake" "${PROJECT_BINARY_DIR}/oasisConfigVersion.cmake"
              "${CMAKE_CURRENT_LIST_DIR}/OasisCatalog.cmake"
        DESTINATION "${OASIS_CMAKE_DIR}")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/specs/" DESTINATION "${CMAKE_INSTALL_DATADIR}/oasis/specs"
        FILES_MATCHING PATTERN "*.oasis")
install(FILES "${PROJECT_SOURCE_DIR}/README.md" DESTINATION "${CMAKE_INSTALL_DOCDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION "${CMAKE_INSTALL_DOCDIR}"
        FILES_MATCHING PATTERN "*.md")

# Each program's --help, as the documentation of its command line (share/doc/oasis/*.txt).
function(oasis_install_help program)
  if(NOT TARGET ${program})
    return()
  endif()
  set(help "${PROJECT_BINARY_DIR}/help/${program}.txt")
  add_custom_command(OUTPUT "${help}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${PROJECT_BINARY_DIR}/help"
    COMMAND $<TARGET_FILE:${program}> --help > "${help}"
    DEPENDS ${program}
    COMMENT "${program} --help"
    VERBATIM)
  add_custom_target(${program}_help ALL DEPENDS "${help}")
  install(FILES "${help}" DESTINATION "${CMAKE_INSTALL_DOCDIR}")
endfunction()
foreach(program IN ITEMS oasisc oasis-sim oasis-go1)
  oasis_install_help(${program})
endforeach()

set(CPACK_PACKAGE_NAME oasis)
set(CPACK_PACKAGE_VENDOR "oasis")
set(CPACK_PACKAGE_CONTACT "oasis maintainers <oasis@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_INSTALL_DIRECTORY oasis)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)  # Depends: from the programs' shared libraries
# The Python module (python/CMakeLists.txt) is built for Debian 12's python3 (3.11) and reads
# numpy and scipy; the shared libraries it links are in the computed Depends already.
if(OASIS_BUILD_PYTHON AND OASIS_BUILD_COMPILER)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
      "python3 (>= 3.11), python3 (<< 3.12), python3-numpy, python3-scipy")
endif()
# The CMake package's consumers compile against these headers (oasis_add_catalog's C++).
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "cmake (>= 3.25), g++ (>= 12)")
include(CPack)
