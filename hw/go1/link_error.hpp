#pragma once
// The one exception type of the Go1 link: a bad address, a socket that cannot be opened or bound.
// Its message names the address and the system's reason.

#include <stdexcept>

namespace oasis::hw::go1 {

class LinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace oasis::hw::go1
