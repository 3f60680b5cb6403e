#pragma once
/// @file
/// The binary catalog file: its layout, and a loader that turns untrusted bytes into a
/// CatalogView or refuses them with a reason. C++17, standard library only.
///
/// Layout (all integers little-endian, every array 8-byte aligned):
///
///     offset  size  field
///          0     8  magic "OASISCAT"
///          8     4  format version (kCatalogFormat)
///         12     4  number of arrays in the table of contents (kCatalogArrayCount)
///         16     8  file size in bytes
///         24     8  checksum: FNV-1a 64 of every byte from offset 32 to the end
///         32     8  spec hash
///         40     4  num_states     44  4  num_actions
///         48     4  num_abstractions   52  4  observation kind
///         56     8  p_correct (IEEE-754 double)
///         64        table of contents: per array, u64 offset and u64 element count
///
/// The arrays, in table-of-contents order: the name text (all strings, each ending in NUL)
/// and the string offsets into it (catalog name, compiler version, actions, states,
/// contexts); switching; prior; then per abstraction its num_blocks and the arrays of
/// AbstractionView in declaration order. Element counts are checked against the sizes the
/// header and the earlier arrays imply, so a file cannot make the loader read out of bounds.

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace oasis {
namespace rt {

/// "OASISCAT" read as a little-endian 64-bit integer.
inline constexpr std::uint64_t kCatalogMagic = 0x5441435349534153ULL;
inline constexpr std::size_t kCatalogHeaderBytes = 64;
/// Catalog-wide arrays: name text, string offsets, switching, prior, block counts.
inline constexpr std::uint32_t kCatalogGlobalArrays = 5;
/// Per abstraction: block_of, block_reward, quotient (3), reward, policy, value, state
/// transitions (3).
inline constexpr std::uint32_t kCatalogArraysPerAbstraction = 11;
/// Refuse files larger than this (1 GiB): a catalog is tables for a robot, not a dataset.
inline constexpr std::uint64_t kMaxCatalogFileBytes = std::uint64_t{1} << 30;

/// A catalog loaded from bytes: owns them (8-byte aligned) and exposes a CatalogView into
/// them. Move-only, so the view's pointers stay valid.
class LoadedCatalog {
 public:
  LoadedCatalog() = default;
  LoadedCatalog(const LoadedCatalog&) = delete;
  LoadedCatalog& operator=(const LoadedCatalog&) = delete;
  LoadedCatalog(LoadedCatalog&&) = default;
  LoadedCatalog& operator=(LoadedCatalog&&) = default;

  /// True when the bytes passed every check; otherwise error() says which failed.
  bool ok() const noexcept { return ok_; }
  const std::string& error() const noexcept { return error_; }
  /// Valid only when ok(). Points into this object.
  const CatalogView& view() const noexcept { return view_; }

  /// Parses and checks `size` bytes (copied). Never reads outside them, whatever they hold.
  static LoadedCatalog from_bytes(const void* bytes, std::size_t size) {
    LoadedCatalog catalog;
    // A new[]-allocated unsigned char array is aligned for every fundamental type and may
    // hold objects of any implicit-lifetime type, so the arrays can be read in place.
    catalog.storage_.reset(new unsigned char[size == 0 ? 1 : size]);
    if (size > 0) std::memcpy(catalog.storage_.get(), bytes, size);
    catalog.size_ = size;
    catalog.parse();
    return catalog;
  }

  /// Reads and checks a file; a file that cannot be read is an error, not an exception.
  static LoadedCatalog from_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return failed("cannot open " + path);
    const std::streamoff length = in.tellg();
    if (length < 0 || static_cast<std::uint64_t>(length) > kMaxCatalogFileBytes) {
      return failed(path + ": file too large for a catalog");
    }
    std::vector<char> bytes(static_cast<std::size_t>(length));
    in.seekg(0);
    if (length > 0 && !in.read(bytes.data(), length)) return failed("cannot read " + path);
    LoadedCatalog catalog = from_bytes(bytes.data(), bytes.size());
    if (!catalog.ok_) catalog.error_ = path + ": " + catalog.error_;
    return catalog;
  }

 private:
  struct Array {
    std::uint64_t offset;
    std::uint64_t count;
  };

  static LoadedCatalog failed(std::string why) {
    LoadedCatalog catalog;
    catalog.error_ = std::move(why);
    return catalog;
  }

  const unsigned char* bytes() const noexcept { return storage_.get(); }

  template <typename T>
  T read_at(std::size_t offset) const noexcept {
    T value;
    std::memcpy(&value, bytes() + offset, sizeof value);
    return value;
  }

  bool fail(std::string why) {
    error_ = std::move(why);
    ok_ = false;
    return false;
  }

  // The table-of-contents entry `index`, checked to lie inside the file, aligned, and to
  // hold exactly `expected` elements of `element_size` bytes. Returns its address or null.
  template <typename T>
  const T* array(std::uint32_t index, std::uint64_t expected, const char* what) {
    const std::size_t entry = kCatalogHeaderBytes + std::size_t{index} * 16;
    const Array a{read_at<std::uint64_t>(entry), read_at<std::uint64_t>(entry + 8)};
    if (a.count != expected) {
      fail(std::string("array '") + what + "' has " + std::to_string(a.count) +
           " elements, expected " + std::to_string(expected));
      return nullptr;
    }
    if (a.offset % 8 != 0 || a.offset > size_ || a.count > (size_ - a.offset) / sizeof(T)) {
      fail(std::string("array '") + what + "' lies outside the file or is misaligned");
      return nullptr;
    }
    if (a.count == 0) return nullptr;
    return reinterpret_cast<const T*>(bytes() + a.offset);
  }

  bool parse_header() {
    if (size_ < kCatalogHeaderBytes) return fail("file too short for a catalog header");
    if (read_at<std::uint64_t>(0) != kCatalogMagic) return fail("not an oasis catalog (bad magic)");
    const auto version = read_at<std::uint32_t>(8);
    if (version != kCatalogFormat) {
      return fail("catalog format " + std::to_string(version) + ", this runtime reads format " +
                  std::to_string(kCatalogFormat) + " (recompile the catalog with oasisc)");
    }
    if (read_at<std::uint64_t>(16) != size_)
      return fail("file size does not match its header (truncated?)");
    if (read_at<std::uint64_t>(24) != fnv1a64(bytes() + 32, size_ - 32))
      return fail("checksum mismatch (corrupt file)");
    view_.spec_hash = read_at<std::uint64_t>(32);
    view_.num_states = read_at<std::uint32_t>(40);
    view_.num_actions = read_at<std::uint32_t>(44);
    view_.num_abstractions = read_at<std::uint32_t>(48);
    const auto kind = read_at<std::uint32_t>(52);
    if (kind == static_cast<std::uint32_t>(ObservationKind::kMatrix)) {
      return fail("confusion-matrix observation models are not stored in catalog files");
    }
    if (kind > static_cast<std::uint32_t>(ObservationKind::kMatrix)) {
      return fail("unknown observation kind " + std::to_string(kind));
    }
    view_.observation.kind = static_cast<ObservationKind>(kind);
    view_.observation.p_correct = read_at<double>(56);
    const std::uint64_t arrays =
        kCatalogGlobalArrays + std::uint64_t{view_.num_abstractions} * kCatalogArraysPerAbstraction;
    if (read_at<std::uint32_t>(12) != arrays || arrays > (size_ - kCatalogHeaderBytes) / 16) {
      return fail("table of contents does not match the number of abstractions");
    }
    return true;
  }

  // Strings: offsets into the NUL-terminated text; each must start inside it and end at a
  // NUL inside it.
  bool parse_strings() {
    const std::uint64_t num_strings =
        2 + std::uint64_t{view_.num_actions} + view_.num_states + view_.num_abstractions;
    const std::uint64_t text_size = read_at<std::uint64_t>(kCatalogHeaderBytes + 8);
    const char* text = array<char>(0, text_size, "name text");
    const std::uint32_t* offsets = array<std::uint32_t>(1, num_strings, "string offsets");
    if (!ok_ || text == nullptr || text[text_size - 1] != '\0') return fail("malformed name text");
    names_.resize(num_strings);
    for (std::uint64_t i = 0; i < num_strings; ++i) {
      if (offsets[i] >= text_size) return fail("string offset out of range");
      names_[i] = text + offsets[i];
    }
    view_.name = names_[0];
    view_.compiler_version = names_[1];
    view_.action_names = names_.data() + 2;
    view_.state_names = names_.data() + 2 + view_.num_actions;
    return true;
  }

  bool parse_transitions(std::uint32_t first, std::uint64_t rows, TransitionsCsr& csr,
                         bool optional) {
    const std::size_t entry = kCatalogHeaderBytes + std::size_t{first + 1} * 16 + 8;
    const std::uint64_t edges = read_at<std::uint64_t>(entry);
    if (optional && edges == 0) {
      array<std::uint32_t>(first, 0, "state transition rows");
      array<std::uint32_t>(first + 1, 0, "state transition targets");
      array<double>(first + 2, 0, "state transition probabilities");
      return ok_;
    }
    if (edges > UINT32_MAX) return fail("too many edges");
    csr.choice_begin = array<std::uint32_t>(first, rows + 1, "transition rows");
    csr.target = array<std::uint32_t>(first + 1, edges, "transition targets");
    csr.probability = array<double>(first + 2, edges, "transition probabilities");
    csr.num_edges = static_cast<std::uint32_t>(edges);
    return ok_;
  }

  void parse() {
    ok_ = true;
    if (!parse_header() || !parse_strings()) return;
    const std::uint32_t n = view_.num_abstractions;
    const std::uint64_t states = view_.num_states;
    const std::uint64_t actions = view_.num_actions;
    view_.switching = array<double>(2, std::uint64_t{n} * n, "switching");
    view_.prior = array<double>(3, n, "prior");
    const std::uint32_t* blocks = array<std::uint32_t>(4, n, "block counts");
    if (!ok_) return;
    abstractions_.assign(n, AbstractionView{});
    for (std::uint32_t i = 0; i < n && ok_; ++i) {
      AbstractionView& a = abstractions_[i];
      const std::uint32_t base = kCatalogGlobalArrays + i * kCatalogArraysPerAbstraction;
      a.context = names_[2 + actions + states + i];
      a.num_blocks = blocks[i];
      a.block_of = array<std::uint32_t>(base, states, "block_of");
      a.block_reward = array<double>(base + 1, a.num_blocks, "block_reward");
      if (!parse_transitions(base + 2, std::uint64_t{a.num_blocks} * actions, a.quotient, false))
        return;
      a.reward = array<double>(base + 5, std::uint64_t{a.num_blocks} * actions, "reward");
      a.policy = array<std::uint32_t>(base + 6, a.num_blocks, "policy");
      a.value = array<double>(base + 7, a.num_blocks, "value");
      parse_transitions(base + 8, states * actions, a.state_transitions, true);
    }
    if (!ok_) return;
    view_.abstractions = abstractions_.data();
    std::string why;
    if (!validate(view_, &why)) fail("invalid catalog: " + why);
  }

  std::unique_ptr<unsigned char[]> storage_;  // the file's bytes
  std::size_t size_ = 0;
  std::vector<const char*> names_;
  std::vector<AbstractionView> abstractions_;
  CatalogView view_;
  bool ok_ = false;
  std::string error_ = "not loaded";
};

}  // namespace rt
}  // namespace oasis
