# The ARCH-COMP stochastic benchmarks (specs/arch/, its README), each shipped spec at a small
# grid (arch_specs.py), two ctest entries per spec, `ctest -L arch`:
#   arch.NAME         compile: a controller whose bounds are one per cell, 0 <= lower <= upper
#                     <= 1;
#   arch.verify.NAME  the same compile, then `oasisc verify` on the controller (its structure and
#                     a Monte-Carlo check of the bounds, 10 cells x 500 runs).
# Included from tests/CMakeLists.txt, so the tests run with the folder's TMPDIR and must leave
# nothing there. The full-size compiles are a benchmark, not a test:
# tests/bench/arch_benchmarks.py.
file(GLOB OASIS_ARCH_SPECS CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/specs/arch/*.oasis")
foreach(spec IN LISTS OASIS_ARCH_SPECS)
  get_filename_component(name "${spec}" NAME_WE)
  add_test(NAME arch.${name}
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_LIST_DIR}/arch_specs.py"
            --oasisc $<TARGET_FILE:oasisc> --spec "${spec}")
  add_test(NAME arch.verify.${name}
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_LIST_DIR}/arch_specs.py"
            --oasisc $<TARGET_FILE:oasisc> --spec "${spec}" --step verify)
  set_tests_properties(arch.${name} arch.verify.${name} PROPERTIES LABELS arch TIMEOUT 120)
endforeach()
