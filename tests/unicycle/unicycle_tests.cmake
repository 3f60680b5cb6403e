# The Go1 as a unicycle (specs/go1_unicycle.oasis): its catalog compiles with its epsilon and
# Table II holds on it in the simulated hallway (go1_unicycle_table2.py). Needs oasis-go1 (OASIS_BUILD_HW).
if(OASIS_BUILD_HW)
  add_test(NAME spec.go1_unicycle_table2
    COMMAND Python3::Interpreter "${CMAKE_CURRENT_LIST_DIR}/go1_unicycle_table2.py"
            --oasisc $<TARGET_FILE:oasisc> --oasis-go1 $<TARGET_FILE:oasis-go1>
            --spec "${PROJECT_SOURCE_DIR}/specs/go1_unicycle.oasis")
  set_tests_properties(spec.go1_unicycle_table2 PROPERTIES LABELS "hw;sim" TIMEOUT 300)
endif()
