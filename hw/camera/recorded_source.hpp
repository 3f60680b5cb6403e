#pragma once
// Plays a recording folder (sequence.yaml plus a colour and a depth PNG per frame, README.md
// here) as a FrameSource, so perception can be run and tested on real footage.
//
// A folder that is not a recording is refused at construction: sequence.yaml is read and checked
// in full and every frame file it promises must exist. The pixels are only read frame by frame,
// so a frame that cannot be decoded, or has the wrong size or pixel type, is found when it is
// reached: next() then returns SourceStop::kFailure naming the file (on every later call too).

#include <cstddef>
#include <filesystem>
#include <optional>

#include "camera/sequence_description.hpp"
#include "perception/frame.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw::camera {

class RecordedSource final : public FrameSource {
 public:
  // Throws CameraError naming the folder or file (for sequence.yaml also the line and key).
  explicit RecordedSource(std::filesystem::path folder);

  // The frames in order with their recorded timestamps, then SourceStop::kEnd.
  NextFrame next() override;

  // Who held the treat in the frame the last next() returned; nothing when that call returned a
  // stop (or none was made) or when the recording has no ground truth.
  std::optional<TreatHolder> truth_of_last_frame() const { return truth_of_last_frame_; }

  const SequenceDescription& description() const { return description_; }

 private:
  std::filesystem::path folder_;
  SequenceDescription description_;
  std::size_t next_index_ = 0;
  std::optional<TreatHolder> truth_of_last_frame_;
};

}  // namespace oasis::hw::camera
