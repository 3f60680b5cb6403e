#pragma once
// Running out of memory, whoever says so: std::bad_alloc (operator new; --memory-budget's limit
// makes malloc fail); OpenCV, which throws a cv::Exception with code StsNoMem ("Failed to
// allocate N bytes") instead; a thread that cannot get its stack. oasis-go1 and oasis-ros
// report them all with the out-of-memory message of every program
// (common/command_line/memory_option.hpp), never with OpenCV's or TBB's own text. C++17-clean: the
// ROS edge includes it.
#include <exception>
#include <new>
#include <string_view>
#include <system_error>

#include <opencv2/core.hpp>

namespace oasis::hw {

inline bool is_out_of_memory(const std::exception& error) {
  if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr) return true;
  if (const auto* opencv = dynamic_cast<const cv::Exception*>(&error))
    return opencv->code == cv::Error::StsNoMem;
  // A thread whose stack does not fit in the budget (RLIMIT_DATA counts thread stacks): EAGAIN
  // from std::thread, or from TBB, OpenCV's thread pool, as a std::runtime_error of this text.
  if (const auto* system = dynamic_cast<const std::system_error*>(&error))
    return system->code() == std::errc::resource_unavailable_try_again;
  return std::string_view(error.what()).rfind("pthread_create has failed", 0) == 0;
}

}  // namespace oasis::hw
