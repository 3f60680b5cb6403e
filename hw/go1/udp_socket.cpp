#include "go1/udp_socket.hpp"

#include <cerrno>
#include <cstring>

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "go1/link_error.hpp"

namespace oasis::hw::go1 {

namespace {

// Datagrams larger than a HighState are never ours, but must still be read whole to be refused.
constexpr std::size_t kReceiveBufferSize = 2048;

std::string system_reason() {
  return std::strerror(errno);
}

}  // namespace

UdpSocket::UdpSocket(const Endpoint& local) {
  const sockaddr_in address = to_sockaddr(local);
  descriptor_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (descriptor_ < 0) throw LinkError("cannot open a UDP socket: " + system_reason());
  if (::bind(descriptor_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const std::string reason = system_reason();
    ::close(descriptor_);
    throw LinkError("cannot bind UDP socket to " + to_string(local) + ": " + reason);
  }
}

UdpSocket::~UdpSocket() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

Endpoint UdpSocket::local_endpoint() const {
  sockaddr_in address{};
  socklen_t length = sizeof address;
  ::getsockname(descriptor_, reinterpret_cast<sockaddr*>(&address), &length);
  return from_sockaddr(address);
}

std::optional<std::string> UdpSocket::send_to(std::span<const std::uint8_t> bytes,
                                              const sockaddr_in& to) {
  const ssize_t sent = ::sendto(descriptor_, bytes.data(), bytes.size(), MSG_NOSIGNAL,
                                reinterpret_cast<const sockaddr*>(&to), sizeof to);
  if (sent < 0) return "sendto " + to_string(from_sockaddr(to)) + ": " + system_reason();
  if (static_cast<std::size_t>(sent) != bytes.size())
    return "sendto " + to_string(from_sockaddr(to)) + ": short write";
  return std::nullopt;
}

std::optional<Datagram> UdpSocket::receive(std::chrono::milliseconds timeout) {
  pollfd waiting{descriptor_, POLLIN, 0};
  if (::poll(&waiting, 1, static_cast<int>(timeout.count())) <= 0) return std::nullopt;
  Datagram datagram;
  datagram.bytes.resize(kReceiveBufferSize);
  sockaddr_in from{};
  socklen_t from_length = sizeof from;
  const ssize_t received =
      ::recvfrom(descriptor_, datagram.bytes.data(), datagram.bytes.size(), MSG_DONTWAIT,
                 reinterpret_cast<sockaddr*>(&from), &from_length);
  if (received < 0) return std::nullopt;  // e.g. a queued ICMP error; nothing to read
  datagram.bytes.resize(static_cast<std::size_t>(received));
  datagram.from = from_sockaddr(from);
  return datagram;
}

}  // namespace oasis::hw::go1
