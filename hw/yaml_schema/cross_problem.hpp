// A problem between two keys of a file, found after every key was read (a speed beyond a
// limit set elsewhere, a range whose low end is above its high end). A schema's cross-key
// check returns these; the reader reports each at `key` if the file wrote it, else at
// `other_key`, else at the file.
#pragma once

#include <string>

namespace oasis::hw::yaml_schema {

struct CrossProblem {
  std::string key;
  std::string other_key;
  std::string message;
};

}  // namespace oasis::hw::yaml_schema
