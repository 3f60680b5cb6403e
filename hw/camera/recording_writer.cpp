#include "camera/recording_writer.hpp"

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include "camera/camera_error.hpp"
#include "camera/recording_layout.hpp"
#include "camera/sequence_yaml.hpp"

namespace oasis::hw::camera {

namespace {

namespace fs = std::filesystem;

// A POSIX descriptor closed on every path out, so errors can carry errno's reason.
class OpenFile {
 public:
  OpenFile(const fs::path& path, int flags) : descriptor_(::open(path.c_str(), flags, 0644)) {}
  ~OpenFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  int descriptor() const { return descriptor_; }

 private:
  int descriptor_;
};

[[noreturn]] void fail_on(const fs::path& path, const std::string& action) {
  throw CameraError("cannot " + action + " " + path.string() + ": " + std::strerror(errno));
}

void write_file(const fs::path& path, const std::vector<unsigned char>& bytes, bool sync) {
  const OpenFile file(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC);
  if (file.descriptor() < 0) fail_on(path, "create");
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t written = ::write(file.descriptor(), bytes.data() + done, bytes.size() - done);
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) fail_on(path, "write");
    done += static_cast<std::size_t>(written);
  }
  if (sync && ::fsync(file.descriptor()) != 0) fail_on(path, "flush to disk");
}

void write_png(const fs::path& path, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!cv::imencode(".png", image, bytes))
    throw CameraError("cannot encode " + path.string() + " as PNG");
  write_file(path, bytes, false);  // finish() flushes all frames at once: cheaper than one by one
}

// Flushes every file written into the folder (one syncfs instead of an fsync per frame), or,
// with a rename just done, the folder entry itself.
void sync_folder(const fs::path& folder, bool whole_file_system) {
  const OpenFile directory(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (directory.descriptor() < 0) fail_on(folder, "open");
  const int result =
      whole_file_system ? ::syncfs(directory.descriptor()) : ::fsync(directory.descriptor());
  if (result != 0) fail_on(folder, "flush to disk");
}

void remove_earlier_recording(const fs::path& folder) {
  std::error_code error;
  fs::remove(folder / kSequenceFileName, error);  // first: the folder stops being a recording
  const std::string temporary = std::string(kSequenceFileName) + ".tmp";
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if ((is_recording_file_name(name) || name == temporary) && !fs::remove(entry.path(), error))
      throw CameraError("cannot delete " + entry.path().string() + ": " + error.message());
  }
}

void prepare_folder(const fs::path& folder, ExistingFolder existing) {
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error))
    throw CameraError("cannot record into " + folder.string() + ": it is not a folder");
  fs::create_directories(folder, error);
  if (error) throw CameraError("cannot create " + folder.string() + ": " + error.message());
  if (fs::is_empty(folder, error)) return;
  if (existing == ExistingFolder::kRefuse)
    throw CameraError("recording folder " + folder.string() +
                      " is not empty; choose an empty folder or ask to replace the recording");
  remove_earlier_recording(folder);
}

void check_frame_format(const Frame& frame) {
  const cv::Size size(frame.intrinsics.width, frame.intrinsics.height);
  if (frame.colour.type() != CV_8UC3 || frame.colour.size() != size)
    throw CameraError("cannot record a frame whose colour image is not 8-bit BGR of " +
                      std::to_string(size.width) + "x" + std::to_string(size.height) +
                      " (the intrinsics' size)");
  if (frame.depth.type() != CV_16UC1 || frame.depth.size() != size)
    throw CameraError("cannot record a frame whose depth image is not 16-bit single-channel of " +
                      std::to_string(size.width) + "x" + std::to_string(size.height));
}

bool same_intrinsics(const CameraIntrinsics& a, const CameraIntrinsics& b) {
  return a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy && a.width == b.width &&
         a.height == b.height;
}

}  // namespace

RecordingWriter::RecordingWriter(std::filesystem::path folder, ExistingFolder existing)
    : folder_(std::move(folder)) {
  prepare_folder(folder_, existing);
}

void RecordingWriter::write(const Frame& frame, std::optional<TreatHolder> truth) {
  if (finished_) throw CameraError("recording " + folder_.string() + " is already finished");
  check_frame_format(frame);
  if (frames_written() == 0) {
    description_.intrinsics = frame.intrinsics;
    description_.depth_scale_m_per_unit = frame.depth_scale_m_per_unit;
  }
  check_matches_first(frame);
  check_truth_given_consistently(truth.has_value());
  const std::size_t index = frames_written();
  write_png(folder_ / colour_file_name(index), frame.colour);
  write_png(folder_ / depth_file_name(index), frame.depth);
  description_.timestamps_s.push_back(frame.timestamp_s);
  if (truth) description_.truth.push_back(*truth);
}

void RecordingWriter::check_matches_first(const Frame& frame) const {
  if (!same_intrinsics(frame.intrinsics, description_.intrinsics) ||
      frame.depth_scale_m_per_unit != description_.depth_scale_m_per_unit)
    throw CameraError("frame " + std::to_string(frames_written()) +
                      " has other intrinsics or depth scale than frame 0; a recording has one "
                      "camera setting");
  if (frames_written() > 0 && !(frame.timestamp_s > description_.timestamps_s.back()))
    throw CameraError("frame " + std::to_string(frames_written()) + " is stamped " +
                      std::to_string(frame.timestamp_s) + " s, not after the previous frame");
}

void RecordingWriter::check_truth_given_consistently(bool given) const {
  if (frames_written() > 0 && given != description_.has_truth())
    throw CameraError("frame " + std::to_string(frames_written()) +
                      (given ? " has a treat holder but earlier frames have none"
                             : " has no treat holder but earlier frames have one") +
                      "; give it for every frame or for none");
}

void RecordingWriter::finish() {
  if (finished_) return;
  sync_folder(folder_, true);
  const std::string text = sequence_yaml_text(description_);
  const fs::path final_path = folder_ / kSequenceFileName;
  const fs::path temporary = folder_ / (std::string(kSequenceFileName) + ".tmp");
  write_file(temporary, std::vector<unsigned char>(text.begin(), text.end()), true);
  if (::rename(temporary.c_str(), final_path.c_str()) != 0) fail_on(final_path, "create");
  sync_folder(folder_, false);
  finished_ = true;
}

}  // namespace oasis::hw::camera
