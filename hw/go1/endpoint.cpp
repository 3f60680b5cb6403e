#include "go1/endpoint.hpp"

#include <charconv>

#include <arpa/inet.h>

#include "go1/link_error.hpp"

namespace oasis::hw::go1 {

std::string to_string(const Endpoint& endpoint) {
  return endpoint.address + ":" + std::to_string(endpoint.port);
}

Endpoint parse_endpoint(std::string_view text) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos)
    throw LinkError("endpoint '" + std::string(text) + "' has no ':PORT'");
  const std::string_view port_text = text.substr(colon + 1);
  unsigned port = 0;
  const auto [end, error] =
      std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (error != std::errc{} || end != port_text.data() + port_text.size() || port > 65535)
    throw LinkError("endpoint '" + std::string(text) + "' has an invalid port");
  Endpoint endpoint{std::string(text.substr(0, colon)), static_cast<std::uint16_t>(port)};
  (void)to_sockaddr(endpoint);  // validates the address
  return endpoint;
}

sockaddr_in to_sockaddr(const Endpoint& endpoint) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(endpoint.port);
  if (inet_pton(AF_INET, endpoint.address.c_str(), &address.sin_addr) != 1)
    throw LinkError("'" + endpoint.address + "' is not an IPv4 address (dotted quad, e.g. " +
                    "192.168.123.161)");
  return address;
}

Endpoint from_sockaddr(const sockaddr_in& address) {
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &address.sin_addr, text, sizeof text);
  return Endpoint{text, ntohs(address.sin_port)};
}

}  // namespace oasis::hw::go1
