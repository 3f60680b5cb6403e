#pragma once
// The few collective operations the distributed engine needs, over MPI_COMM_WORLD. Every
// call is collective: all ranks make the same calls in the same order. Messages of any size
// are sent in pieces below MPI's 2^31-element limit. An MPI error aborts the whole job
// (MPI's default handler), which mpirun reports.

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace oasis::distributed {

using Bytes = std::vector<char>;

class Communicator {
 public:
  // Initialises MPI; the destructor finalises it. One per process.
  Communicator(int& argc, char**& argv);
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;
  ~Communicator();

  [[nodiscard]] std::uint32_t rank() const { return rank_; }
  [[nodiscard]] std::uint32_t size() const { return size_; }
  [[nodiscard]] bool is_root() const { return rank_ == 0; }

  // Rank r receives outgoing[r] of every rank; the result is indexed by sender. `outgoing`
  // is emptied as it is sent, so a caller's buffers do not outlive the exchange.
  [[nodiscard]] std::vector<Bytes> exchange(std::vector<Bytes>& outgoing) const;

  // Every rank's `mine`, indexed by rank.
  [[nodiscard]] std::vector<std::string> all_gather(std::string_view mine) const;
  [[nodiscard]] std::vector<std::uint64_t> all_gather(std::uint64_t mine) const;

  [[nodiscard]] std::uint64_t sum(std::uint64_t mine) const;
  [[nodiscard]] std::uint64_t max(std::uint64_t mine) const;
  [[nodiscard]] bool any(bool mine) const { return max(mine ? 1 : 0) != 0; }

  void barrier() const;

  // Ends every rank of the job with `status` (MPI_Abort): for a failure on one rank that the
  // others, waiting in a collective, cannot learn of (an exception such as out of memory).
  [[noreturn]] void abort(int status) const;

 private:
  std::uint32_t rank_ = 0;
  std::uint32_t size_ = 1;
};

// Appends values to a byte buffer, and reads them back in the same order.
class ByteWriter {
 public:
  explicit ByteWriter(Bytes& bytes) : bytes_(bytes) {}
  template <typename T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& value) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  void put_text(std::string_view text) {
    put(static_cast<std::uint32_t>(text.size()));
    bytes_.insert(bytes_.end(), text.begin(), text.end());
  }

 private:
  Bytes& bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(std::span<const char> bytes) : bytes_(bytes) {}
  [[nodiscard]] bool at_end() const { return at_ == bytes_.size(); }
  template <typename T>
  requires std::is_trivially_copyable_v<T> T get() {
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string_view get_text() {
    const auto length = get<std::uint32_t>();
    const std::string_view text(bytes_.data() + at_, length);
    at_ += length;
    return text;
  }

 private:
  std::span<const char> bytes_;
  std::size_t at_ = 0;
};

}  // namespace oasis::distributed
