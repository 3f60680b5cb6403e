#pragma once
// Writes frames into a recording folder that RecordedSource can play (README.md here).
//
// sequence.yaml is what makes a folder a recording, so it is written last, by finish(): the
// frames are flushed to disk, then the description goes to a temporary file that is renamed
// into place. A recording cut short (a crash, an exception, no finish()) has frames but no
// sequence.yaml, and the reader refuses it instead of taking it for a whole one.

#include <cstddef>
#include <filesystem>
#include <optional>

#include "camera/sequence_description.hpp"
#include "perception/frame.hpp"
#include "perception/treat_holder.hpp"

namespace oasis::hw::camera {

// What to do when the folder already holds files.
enum class ExistingFolder {
  kRefuse,   // throw CameraError: never overwrite a recording by accident
  kReplace,  // delete the earlier recording's files (sequence.yaml first); leave any others
};

class RecordingWriter {
 public:
  // Creates the folder (and its parents) if needed. Throws CameraError naming the folder.
  explicit RecordingWriter(std::filesystem::path folder,
                           ExistingFolder existing = ExistingFolder::kRefuse);

  // Writes the frame's colour and depth PNGs. The first frame fixes the intrinsics and depth
  // scale; later frames must agree and be later in time. Give `truth` for every frame or for
  // none. Throws CameraError (bad frame, disk full, after finish()).
  void write(const Frame& frame, std::optional<TreatHolder> truth = std::nullopt);

  // Writes sequence.yaml; the folder is a recording from then on. Throws CameraError.
  void finish();

  std::size_t frames_written() const { return description_.frame_count(); }
  const std::filesystem::path& folder() const { return folder_; }

 private:
  void check_matches_first(const Frame& frame) const;
  void check_truth_given_consistently(bool given) const;

  std::filesystem::path folder_;
  SequenceDescription description_;
  bool finished_ = false;
};

}  // namespace oasis::hw::camera
