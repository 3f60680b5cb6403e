# FindROS1: ROS 1 (Noetic, as Debian 12 packages it) for hw/ros/ only: roscpp, message_filters,
# cv_bridge and rosbag, with the message headers under /usr/include. Debian ships pkg-config
# files for roscpp and message_filters but no CMake packages usable outside catkin, so we wrap
# them. Defines ROS1::roscpp (with message_filters), ROS1::cv_bridge and ROS1::rosbag.
#
# rosbag's headers include pluginlib, which Debian 12 packages in its ROS 2 form (headers one
# folder deeper, on class_loader, rcpputils, rcutils and ament_index_cpp): those folders join
# the include path and those libraries the link, or rosbag/bag.h does not compile or link.
find_package(PkgConfig REQUIRED QUIET)
pkg_check_modules(PC_ROSCPP QUIET IMPORTED_TARGET GLOBAL roscpp message_filters)
find_library(ROS1_CV_BRIDGE_LIBRARY cv_bridge)
find_library(ROS1_ROSBAG_LIBRARY rosbag)
find_library(ROS1_ROSBAG_STORAGE_LIBRARY rosbag_storage)
find_path(ROS1_MESSAGES_INCLUDE_DIR geometry_msgs/Twist.h)
find_path(ROS1_PLUGINLIB_INCLUDE_DIR pluginlib/class_loader.hpp PATH_SUFFIXES pluginlib)
set(ROS1_ROSBAG_HELPERS console_bridge class_loader rcpputils rcutils ament_index_cpp)
set(ROS1_ROSBAG_HELPER_LIBRARIES "")
set(ROS1_ROSBAG_HELPER_INCLUDE_DIRS "")
foreach(helper IN LISTS ROS1_ROSBAG_HELPERS)
  find_library(ROS1_${helper}_LIBRARY ${helper})
  list(APPEND ROS1_ROSBAG_HELPER_LIBRARIES "${ROS1_${helper}_LIBRARY}")
  if(NOT helper STREQUAL "console_bridge")
    list(APPEND ROS1_ROSBAG_HELPER_INCLUDE_DIRS "/usr/include/${helper}")
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ROS1
  REQUIRED_VARS PC_ROSCPP_FOUND ROS1_CV_BRIDGE_LIBRARY ROS1_ROSBAG_LIBRARY
                ROS1_ROSBAG_STORAGE_LIBRARY ROS1_MESSAGES_INCLUDE_DIR ROS1_PLUGINLIB_INCLUDE_DIR
                ROS1_class_loader_LIBRARY ROS1_rcpputils_LIBRARY ROS1_rcutils_LIBRARY
                ROS1_ament_index_cpp_LIBRARY ROS1_console_bridge_LIBRARY
  VERSION_VAR PC_ROSCPP_VERSION)

if(ROS1_FOUND AND NOT TARGET ROS1::roscpp)
  add_library(ROS1::roscpp INTERFACE IMPORTED GLOBAL)
  target_link_libraries(ROS1::roscpp INTERFACE PkgConfig::PC_ROSCPP)
  add_library(ROS1::cv_bridge INTERFACE IMPORTED GLOBAL)
  target_link_libraries(ROS1::cv_bridge INTERFACE "${ROS1_CV_BRIDGE_LIBRARY}" ROS1::roscpp)
  add_library(ROS1::rosbag INTERFACE IMPORTED GLOBAL)
  # SYSTEM: these are other projects' headers, kept out of -Werror.
  target_include_directories(ROS1::rosbag SYSTEM INTERFACE "${ROS1_PLUGINLIB_INCLUDE_DIR}"
                                                           ${ROS1_ROSBAG_HELPER_INCLUDE_DIRS})
  target_link_libraries(ROS1::rosbag INTERFACE "${ROS1_ROSBAG_LIBRARY}"
                        "${ROS1_ROSBAG_STORAGE_LIBRARY}" ${ROS1_ROSBAG_HELPER_LIBRARIES}
                        ROS1::roscpp)
endif()
