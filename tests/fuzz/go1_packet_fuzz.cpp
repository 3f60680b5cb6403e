// The Go1 packet decoders (hw/go1): any datagram is decoded or refused with a reason, never
// read past its end. A HighState decoded without the CRC check and encoded again decodes to
// the same state (the fields the decoder keeps survive), and a decoded HighCmd likewise.

#include <cmath>
#include <span>

#include "fuzz_target.hpp"
#include "go1/high_cmd.hpp"
#include "go1/high_state.hpp"

namespace {

using namespace oasis::hw::go1;

// Equal fields, or equal encodings: a NaN field is unequal to itself but encodes the same.
bool same(const HighState& a, const HighState& b) {
  if (a == b) return true;
  const HighStateBytes left = encode_high_state(a, 0);
  const HighStateBytes right = encode_high_state(b, 0);
  return left == right;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> packet(data, size);
  const std::optional<std::uint8_t> level = size > 2 ? std::optional(data[2]) : std::nullopt;
  for (const bool check_crc : {true, false}) {
    const auto state = decode_high_state(packet, level, check_crc);
    if (!state.ok()) {
      FUZZ_REQUIRE(!refusal_name(state.refused().reason).empty());
      continue;
    }
    const HighStateBytes again = encode_high_state(state.packet(), *level);
    const auto decoded = decode_high_state(again, level, true);
    FUZZ_REQUIRE(decoded.ok());
    FUZZ_REQUIRE(same(decoded.packet(), state.packet()));
  }
  const auto command = decode_high_cmd(packet, std::nullopt);
  if (command.ok()) {
    const HighCmdBytes again = encode_high_cmd(command.packet(), level.value_or(0));
    FUZZ_REQUIRE(decode_high_cmd(again, std::nullopt).ok());
  }
  return 0;
}
