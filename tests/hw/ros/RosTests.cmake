# The tests of oasis-ros (included from hw/ros/CMakeLists.txt).
#   ros_edge_test      the ROS edge's conversions and messages, no master needed (C++17, as the
#                      edge is: it includes ROS's message headers)
#   ros_settings_test  the node's settings schema (C++20)
#   ros.*              oasis-ros against a real roscore that each test starts on a free port
#                      with its own ROS home (roscore_fixture.py): label "ros"
if(NOT OASIS_BUILD_TESTS)
  return()
endif()
find_package(GTest REQUIRED)
include(GoogleTest)
set(ros_tests "${PROJECT_SOURCE_DIR}/tests/hw/ros")

file(GLOB edge_test_sources CONFIGURE_DEPENDS "${ros_tests}/edge/*_test.cpp")
if(edge_test_sources)
  add_executable(ros_edge_test ${edge_test_sources})
  set_target_properties(ros_edge_test PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON)
  target_include_directories(ros_edge_test PRIVATE "${PROJECT_SOURCE_DIR}/hw"
                             "${PROJECT_SOURCE_DIR}/runtime/include" "${PROJECT_SOURCE_DIR}/common"
                             "${PROJECT_SOURCE_DIR}/generated/go1_treat")
  target_include_directories(ros_edge_test SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(ros_edge_test PRIVATE oasis_hw_ros_edge oasis_go1_catalog GTest::gtest
                                              GTest::gtest_main)
  oasis_set_warnings(ros_edge_test)
  gtest_discover_tests(ros_edge_test DISCOVERY_MODE PRE_TEST TEST_PREFIX "ros_edge_test."
                       PROPERTIES LABELS "unit;hw")
endif()

add_executable(ros_settings_test "${ros_tests}/node_settings_test.cpp")
target_link_libraries(ros_settings_test PRIVATE oasis_hw_ros_settings GTest::gtest
                                                GTest::gtest_main)
oasis_set_warnings(ros_settings_test)
gtest_discover_tests(ros_settings_test DISCOVERY_MODE PRE_TEST TEST_PREFIX "ros_settings_test."
                     PROPERTIES LABELS "unit;hw")

# Debian's python3 has rospy; a virtualenv's or pyenv's may not.
find_program(OASIS_DEBIAN_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
foreach(case IN ITEMS bad_parameter fail_safe sigint closed_loop launch replay sighup last_resort
                      last_resort_abort crafted_frames crafted_bag bad_topic_name)
  add_test(NAME ros.${case}
           COMMAND "${OASIS_DEBIAN_PYTHON}" "${ros_tests}/ros_node_test.py" ${case}
                   --oasis-ros $<TARGET_FILE:oasis-ros>
                   --sim $<TARGET_FILE:oasis-ros-hallway-sim>
                   --oasis-go1 $<TARGET_FILE:oasis-go1>
                   --package-path "${CMAKE_CURRENT_BINARY_DIR}/package")
  set_tests_properties(ros.${case} PROPERTIES LABELS "ros;hw" TIMEOUT 300 RESOURCE_LOCK roscore_cpu)
endforeach()
# The closed loop runs in real time (at twice the trial's pace): alone, so that no other test
# takes the cores it needs to keep up with the frames.
set_tests_properties(ros.closed_loop PROPERTIES RUN_SERIAL TRUE)
