#include "go1/packet_refusal.hpp"

namespace oasis::hw::go1 {

std::string_view refusal_name(PacketRefusal refusal) {
  switch (refusal) {
    case PacketRefusal::kWrongLength:
      return "wrong length";
    case PacketRefusal::kWrongHead:
      return "wrong head";
    case PacketRefusal::kWrongLevelFlag:
      return "wrong level flag";
    case PacketRefusal::kBadCrc:
      return "bad crc";
  }
  return "?";
}

}  // namespace oasis::hw::go1
