#pragma once
// Why a received packet was refused, and the result type of the decoders: a decoded packet or
// the refusal with a human-readable detail ("length 128, expected 129").

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace oasis::hw::go1 {

enum class PacketRefusal : std::uint8_t { kWrongLength, kWrongHead, kWrongLevelFlag, kBadCrc };

std::string_view refusal_name(PacketRefusal refusal);

struct Refused {
  PacketRefusal reason;
  std::string detail;  // e.g. "crc 0x12345678 in packet, computed 0x9abcdef0"
};

template <typename Packet>
class DecodeResult {
 public:
  DecodeResult(Packet packet) : value_(std::move(packet)) {}     // NOLINT: implicit on purpose
  DecodeResult(Refused refused) : value_(std::move(refused)) {}  // NOLINT

  bool ok() const { return std::holds_alternative<Packet>(value_); }
  const Packet& packet() const { return std::get<Packet>(value_); }
  const Refused& refused() const { return std::get<Refused>(value_); }

 private:
  std::variant<Packet, Refused> value_;
};

}  // namespace oasis::hw::go1
