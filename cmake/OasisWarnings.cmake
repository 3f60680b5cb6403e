# oasis_set_warnings(TARGET): the warning policy for every target we own.
# Third-party headers come in as SYSTEM includes, so the warnings apply to our code only.
# Warnings are errors in the developer presets and CI (OASIS_WERROR=ON), never in a user's
# or a packager's build: another compiler or optimisation level may warn where ours does not
# (g++ 12 at -O3 reports a false -Wrestrict inside std::string's operator+, GCC bug 105651:
# silenced there, since it points at the standard library, never at our code).
option(OASIS_WERROR "Treat compiler warnings as errors (on in the presets and CI)" OFF)

function(oasis_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wnon-virtual-dtor
                                           -Wold-style-cast -Wcast-align -Woverloaded-virtual)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(OASIS_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
