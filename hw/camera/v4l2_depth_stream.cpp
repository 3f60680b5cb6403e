#include "camera/v4l2_depth_stream.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include <linux/videodev2.h>
#include <poll.h>
#include <sys/mman.h>

#include "camera/camera_error.hpp"

namespace oasis::hw::camera {

namespace {

using Clock = std::chrono::steady_clock;

// Enough buffers that a loop slower than the camera (5 Hz against 30 frames/s) still finds the
// latest frame queued: the driver drops new frames, not old ones, once every buffer is full.
constexpr unsigned kBufferCount = 8;

std::string fourcc_text(std::uint32_t code) {
  std::string text;
  for (int shift = 0; shift < 32; shift += 8)
    text += static_cast<char>((code >> shift) & 0xFF);
  while (!text.empty() && text.back() == ' ')
    text.pop_back();
  return text;
}

// "YUYV, Z16", or "none" when the node lists nothing.
std::string offered_formats(const V4l2Device& device) {
  std::string list;
  v4l2_fmtdesc format{};
  format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  for (format.index = 0; device.io_control(VIDIOC_ENUM_FMT, &format) == 0; ++format.index)
    list += (list.empty() ? "" : ", ") + fourcc_text(format.pixelformat);
  return list.empty() ? "none" : list;
}

v4l2_buffer mmap_buffer(unsigned index = 0) {
  v4l2_buffer buffer{};
  buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  buffer.memory = V4L2_MEMORY_MMAP;
  buffer.index = index;
  return buffer;
}

}  // namespace

V4l2DepthStream::MappedBuffer::~MappedBuffer() {
  if (start_ != nullptr) ::munmap(start_, length_);
}

V4l2DepthStream::MappedBuffer::MappedBuffer(MappedBuffer&& other) noexcept
    : start_(std::exchange(other.start_, nullptr)), length_(other.length_) {}

V4l2DepthStream::V4l2DepthStream(const std::string& device, int width, int height, int fps)
    : device_(device, "depth"), width_(width), height_(height) {
  set_format(fps);
  map_buffers();
  start_streaming();
}

V4l2DepthStream::~V4l2DepthStream() {
  if (!streaming_) return;
  v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  device_.io_control(VIDIOC_STREAMOFF, &type);  // before the buffers are unmapped
}

void V4l2DepthStream::fail(const std::string& what) const {
  throw CameraError(description() + ": " + what);
}

void V4l2DepthStream::set_format(int fps) {
  v4l2_format format{};
  format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  format.fmt.pix.width = static_cast<std::uint32_t>(width_);
  format.fmt.pix.height = static_cast<std::uint32_t>(height_);
  format.fmt.pix.pixelformat = V4L2_PIX_FMT_Z16;
  format.fmt.pix.field = V4L2_FIELD_NONE;
  if (device_.io_control(VIDIOC_S_FMT, &format) != 0)
    fail(std::string("refuses the Z16 format (VIDIOC_S_FMT: ") + std::strerror(errno) +
         "); is another program using the camera?");
  // The driver answers with the nearest format it has instead of failing.
  if (format.fmt.pix.pixelformat != V4L2_PIX_FMT_Z16)
    fail("offers no Z16 depth (it offers " + offered_formats(device_) +
         "); is depth_device the depth node? `v4l2-ctl -d <node> --list-formats-ext` shows each "
         "node's formats");
  if (static_cast<int>(format.fmt.pix.width) != width_ ||
      static_cast<int>(format.fmt.pix.height) != height_)
    fail("has no Z16 mode of " + std::to_string(width_) + "x" + std::to_string(height_) +
         " (nearest: " + std::to_string(format.fmt.pix.width) + "x" +
         std::to_string(format.fmt.pix.height) + "); `v4l2-ctl -d <node> --list-formats-ext`");
  bytes_per_line_ =
      std::max<std::size_t>(format.fmt.pix.bytesperline, static_cast<std::size_t>(width_) * 2);
  // The rate is a request: a camera without that rate keeps its own, which is no error.
  v4l2_streamparm rate{};
  rate.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  rate.parm.capture.timeperframe = {1, static_cast<std::uint32_t>(fps)};
  device_.io_control(VIDIOC_S_PARM, &rate);
}

void V4l2DepthStream::map_buffers() {
  v4l2_requestbuffers request{};
  request.count = kBufferCount;
  request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  request.memory = V4L2_MEMORY_MMAP;
  if (device_.io_control(VIDIOC_REQBUFS, &request) != 0 || request.count == 0)
    fail(std::string("gives no memory-mapped buffers (VIDIOC_REQBUFS: ") + std::strerror(errno) +
         ")");
  for (unsigned index = 0; index < request.count; ++index) {
    v4l2_buffer buffer = mmap_buffer(index);
    if (device_.io_control(VIDIOC_QUERYBUF, &buffer) != 0)
      fail(std::string("VIDIOC_QUERYBUF: ") + std::strerror(errno));
    void* start = ::mmap(nullptr, buffer.length, PROT_READ | PROT_WRITE, MAP_SHARED,
                         device_.descriptor(), buffer.m.offset);
    if (start == MAP_FAILED) fail(std::string("cannot map a buffer: ") + std::strerror(errno));
    buffers_.emplace_back(start, buffer.length);
  }
}

void V4l2DepthStream::start_streaming() {
  for (unsigned index = 0; index < buffers_.size(); ++index) {
    v4l2_buffer buffer = mmap_buffer(index);
    if (device_.io_control(VIDIOC_QBUF, &buffer) != 0)
      fail(std::string("VIDIOC_QBUF: ") + std::strerror(errno));
  }
  v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (device_.io_control(VIDIOC_STREAMON, &type) != 0)
    fail(std::string("will not start streaming (VIDIOC_STREAMON: ") + std::strerror(errno) +
         "); is another program using the camera? Is it on a USB 3 port?");
  streaming_ = true;
}

std::optional<cv::Mat> V4l2DepthStream::dequeue() {
  v4l2_buffer buffer = mmap_buffer();
  if (device_.io_control(VIDIOC_DQBUF, &buffer) != 0) {
    if (errno == EAGAIN) return std::nullopt;  // poll woke us, but the frame is not done
    fail(std::string("stopped delivering depth (VIDIOC_DQBUF: ") + std::strerror(errno) +
         "); is the camera still plugged in?");
  }
  std::optional<cv::Mat> pixels;
  const std::size_t needed = bytes_per_line_ * static_cast<std::size_t>(height_);
  // A frame the driver flags as damaged, or cut short on the bus, is dropped.
  if (!(buffer.flags & V4L2_BUF_FLAG_ERROR) && buffer.bytesused >= needed &&
      buffer.index < buffers_.size()) {
    const cv::Mat view(height_, width_, CV_16UC1, const_cast<void*>(buffers_[buffer.index].start()),
                       bytes_per_line_);
    pixels = view.clone();  // the buffer goes back to the driver below
  }
  if (device_.io_control(VIDIOC_QBUF, &buffer) != 0)
    fail(std::string("VIDIOC_QBUF: ") + std::strerror(errno));
  return pixels;
}

std::optional<cv::Mat> V4l2DepthStream::newest(std::chrono::milliseconds timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  std::optional<cv::Mat> latest;
  while (true) {
    // Once a frame is in hand, only take what is already waiting.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
    const int wait_ms = latest ? 0 : static_cast<int>(std::max<long long>(left.count(), 0));
    pollfd waiting{device_.descriptor(), POLLIN, 0};
    const int ready = ::poll(&waiting, 1, wait_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) fail(std::string("poll: ") + std::strerror(errno));
    if (ready == 0) return latest;
    if (!(waiting.revents & POLLIN))
      fail("stopped delivering depth (device error); is the camera still plugged in?");
    if (auto pixels = dequeue()) latest = std::move(pixels);
    if (!latest && Clock::now() >= deadline) return latest;  // only damaged frames came
  }
}

}  // namespace oasis::hw::camera
