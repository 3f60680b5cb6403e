#pragma once
// An IPv4 address and UDP port. The Go1 speaks IPv4 only (192.168.123.x, or 192.168.12.1 over
// its Wi-Fi hotspot), so names are not resolved: an address must be a dotted quad.

#include <cstdint>
#include <string>
#include <string_view>

#include <netinet/in.h>

namespace oasis::hw::go1 {

struct Endpoint {
  std::string address = "0.0.0.0";
  std::uint16_t port = 0;

  bool operator==(const Endpoint&) const = default;
};

std::string to_string(const Endpoint& endpoint);

// "192.168.123.161:8082" -> Endpoint; throws LinkError naming the text and what is wrong.
Endpoint parse_endpoint(std::string_view text);

// Throws LinkError if the address is not a dotted-quad IPv4 address.
sockaddr_in to_sockaddr(const Endpoint& endpoint);
Endpoint from_sockaddr(const sockaddr_in& address);

}  // namespace oasis::hw::go1
