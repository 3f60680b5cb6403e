#pragma once
// A bound IPv4 UDP socket (POSIX). Opening and binding throw LinkError; sending and receiving
// report failures as values, because the sender thread must keep commanding, never throw.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "go1/endpoint.hpp"

namespace oasis::hw::go1 {

struct Datagram {
  std::vector<std::uint8_t> bytes;
  Endpoint from;
};

class UdpSocket {
 public:
  // Binds to `local` (port 0: any free port). Throws LinkError with the system's reason.
  explicit UdpSocket(const Endpoint& local);
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  Endpoint local_endpoint() const;

  // The error text (e.g. "sendto 192.168.123.161:8082: Network is unreachable"), or nullopt.
  std::optional<std::string> send_to(std::span<const std::uint8_t> bytes, const sockaddr_in& to);

  // Waits up to `timeout` (zero: do not wait) for one datagram.
  std::optional<Datagram> receive(std::chrono::milliseconds timeout);

 private:
  int descriptor_ = -1;
};

}  // namespace oasis::hw::go1
