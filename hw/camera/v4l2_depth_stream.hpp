#pragma once
// The depth node of a RealSense-class camera read through raw V4L2: 16-bit Z16 frames in
// memory-mapped buffers, every wait bounded by poll(). OpenCV cannot open this node (its V4L2
// backend has no Z16 format, hw/FACTS.md §2), hence this reader.

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "camera/v4l2_device.hpp"

namespace oasis::hw::camera {

class V4l2DepthStream {
 public:
  // Opens `device`, asks for Z16 at width x height and `fps`, maps the buffers and starts
  // streaming. Throws CameraError naming the device: missing, not a capture device, no Z16 at
  // that size (then the formats it offers are listed).
  V4l2DepthStream(const std::string& device, int width, int height, int fps);
  ~V4l2DepthStream();
  V4l2DepthStream(const V4l2DepthStream&) = delete;
  V4l2DepthStream& operator=(const V4l2DepthStream&) = delete;

  // Takes every frame the driver has finished and returns the newest (CV_16UC1, our own copy),
  // waiting up to `timeout` when none is ready yet. Nothing: no frame within the timeout.
  // Throws CameraError when the device fails (unplugged, driver error).
  std::optional<cv::Mat> newest(std::chrono::milliseconds timeout);

  const std::string& description() const { return device_.description(); }

 private:
  // One driver buffer mapped into our memory; unmapped on destruction.
  class MappedBuffer {
   public:
    MappedBuffer(void* start, std::size_t length) : start_(start), length_(length) {}
    ~MappedBuffer();
    MappedBuffer(MappedBuffer&& other) noexcept;
    MappedBuffer(const MappedBuffer&) = delete;
    MappedBuffer& operator=(const MappedBuffer&) = delete;
    MappedBuffer& operator=(MappedBuffer&&) = delete;
    const void* start() const { return start_; }

   private:
    void* start_;
    std::size_t length_;
  };

  void set_format(int fps);
  void map_buffers();
  void start_streaming();
  // One finished buffer: its pixels if the frame is whole, after handing the buffer back.
  std::optional<cv::Mat> dequeue();
  [[noreturn]] void fail(const std::string& what) const;

  V4l2Device device_;
  int width_;
  int height_;
  std::size_t bytes_per_line_ = 0;
  std::vector<MappedBuffer> buffers_;
  bool streaming_ = false;
};

}  // namespace oasis::hw::camera
