# FindGMP: GMP and its C++ interface (gmpxx) from the Debian package libgmp-dev.
# Debian ships pkg-config files (gmp.pc, gmpxx.pc) but no CMake package, so we wrap them.
# Defines GMP::gmp and GMP::gmpxx.
find_package(PkgConfig REQUIRED QUIET)
# GLOBAL: the compiler finds GMP and the tests and tools link it too.
pkg_check_modules(PC_GMP QUIET IMPORTED_TARGET GLOBAL gmp)
pkg_check_modules(PC_GMPXX QUIET IMPORTED_TARGET GLOBAL gmpxx)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(GMP
  REQUIRED_VARS PC_GMP_FOUND PC_GMPXX_FOUND
  VERSION_VAR PC_GMP_VERSION)

if(GMP_FOUND AND NOT TARGET GMP::gmp)
  add_library(GMP::gmp INTERFACE IMPORTED GLOBAL)
  target_link_libraries(GMP::gmp INTERFACE PkgConfig::PC_GMP)
  add_library(GMP::gmpxx INTERFACE IMPORTED GLOBAL)
  target_link_libraries(GMP::gmpxx INTERFACE PkgConfig::PC_GMPXX PkgConfig::PC_GMP)
endif()
