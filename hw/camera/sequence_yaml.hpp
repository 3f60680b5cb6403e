#pragma once
// sequence.yaml, the description of a recording folder (README.md here shows an example).
// Reading is strict: an unknown key, a missing key or a value of the wrong type or range throws
// CameraError as "FILE:LINE:COLUMN: message", so a hand-edited file is easy to repair.

#include <filesystem>
#include <string>

#include "camera/sequence_description.hpp"

namespace oasis::hw::camera {

SequenceDescription read_sequence_yaml(const std::filesystem::path& file);

// The text the writer stores. Numbers are written in their shortest exact form, so reading the
// text back gives the same doubles bit for bit.
std::string sequence_yaml_text(const SequenceDescription& description);

}  // namespace oasis::hw::camera
