#pragma once
/// @file
/// The binary catalog file loader: turns untrusted bytes into a CatalogView or refuses them
/// with a reason. The layout (a header, a table of tagged sections, the arrays) is in
/// catalog_sections.hpp; files of format 1 and 2 load. C++17, standard library only.
///
/// Every array's element count is checked against the sizes the header and the earlier
/// arrays imply, and its place against the file's bounds and alignment, so a file cannot
/// make the loader read out of bounds; validate() then checks the catalog's meaning.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "oasis/rt/catalog_sections.hpp"
#include "oasis/rt/catalog_validation.hpp"
#include "oasis/rt/catalog_view.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace oasis {
namespace rt {

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
    // Only a regular file: a directory is no catalog, and opening a FIFO nobody writes to
    // would wait forever.
    std::error_code ignored;
    const std::filesystem::file_status status = std::filesystem::status(path, ignored);
    if (std::filesystem::is_directory(status))
      return failed(path + ": is a directory, not a catalog file");
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
      return failed(path +
                    ": is not a regular file (a FIFO, socket or device), not a catalog file");
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

  /// As from_file(path), and refused unless compiled from the spec whose bytes hash to
  /// `expected_spec_hash` (rt::spec_hash of the spec's text): a catalog left behind by an
  /// edited spec is an error naming both hashes, not a robot running an old policy.
  static LoadedCatalog from_file(const std::string& path, std::uint64_t expected_spec_hash) {
    LoadedCatalog catalog = from_file(path);
    if (catalog.ok_ && catalog.view_.spec_hash != expected_spec_hash) {
      catalog.fail(path + ": compiled from another spec (spec hash " +
                   spec_hash_text(catalog.view_.spec_hash) + ", expected " +
                   spec_hash_text(expected_spec_hash) + ")");
    }
    return catalog;
  }

 private:
  struct Entry {
    std::uint32_t tag;
    std::uint32_t abstraction;
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

  static bool before(const Entry& a, const Entry& b) noexcept {
    return a.tag != b.tag ? a.tag < b.tag : a.abstraction < b.abstraction;
  }

  // entries_ is sorted by (tag, abstraction) once read: a lookup is a binary search, so a
  // hostile table of millions of entries costs O(n log n), not O(n^2).
  const Entry* find(Section tag, std::uint32_t abstraction) const noexcept {
    const Entry key{static_cast<std::uint32_t>(tag), abstraction, 0, 0};
    const auto found = std::lower_bound(entries_.begin(), entries_.end(), key, before);
    if (found == entries_.end() || found->tag != key.tag || found->abstraction != abstraction)
      return nullptr;
    return &*found;
  }

  bool sort_entries() {
    std::sort(entries_.begin(), entries_.end(), before);
    for (std::size_t k = 1; k < entries_.size(); ++k) {
      if (!before(entries_[k - 1], entries_[k]))
        return fail("a section appears twice (tag " + std::to_string(entries_[k].tag) + ")");
    }
    return true;
  }

  // The catalog-wide section `tag` as an array of its element type (kSectionTable), checked
  // by section_array().
  template <Section tag>
  const SectionElementOf<tag>* wide(std::uint64_t expected, bool optional = false) {
    static_assert(section_info(tag).scope == SectionScope::kCatalog, "a per-abstraction tag");
    return section_array<SectionElementOf<tag>>(tag, kCatalogWide, expected, optional);
  }

  // The section `tag` of abstraction i, as wide() reads a catalog-wide one.
  template <Section tag>
  const SectionElementOf<tag>* of_abstraction(std::uint32_t i, std::uint64_t expected,
                                              bool optional = false) {
    static_assert(section_info(tag).scope == SectionScope::kAbstraction, "a catalog-wide tag");
    return section_array<SectionElementOf<tag>>(tag, i, expected, optional);
  }

  // The section (tag, abstraction), checked to lie inside the file, aligned, and to hold
  // exactly `expected` elements of T. A missing optional section reads as empty (null).
  // Messages name it by its kSectionTable name.
  template <typename T>
  const T* section_array(Section tag, std::uint32_t abstraction, std::uint64_t expected,
                         bool optional) {
    const char* what = section_info(tag).name;
    const Entry* entry = find(tag, abstraction);
    if (entry == nullptr) {
      if (!optional) fail(std::string("section '") + what + "' is missing");
      return nullptr;
    }
    if (entry->count != expected) {
      fail(std::string("array '") + what + "' has " + std::to_string(entry->count) +
           " elements, expected " + std::to_string(expected));
      return nullptr;
    }
    if (entry->offset % 8 != 0 || entry->offset > size_ ||
        entry->count > (size_ - entry->offset) / sizeof(T)) {
      fail(std::string("array '") + what + "' lies outside the file or is misaligned");
      return nullptr;
    }
    if (entry->count == 0) return nullptr;
    return reinterpret_cast<const T*>(bytes() + entry->offset);
  }

  // The element count of a section, or 0 when absent (its size is checked by section_array()).
  std::uint64_t count_of(Section tag, std::uint32_t abstraction) const noexcept {
    const Entry* entry = find(tag, abstraction);
    return entry == nullptr ? 0 : entry->count;
  }

  bool parse_header() {
    if (size_ < kCatalogHeaderBytes) return fail("file too short for a catalog header");
    if (read_at<std::uint64_t>(0) != kCatalogMagic) return fail("not an oasis catalog (bad magic)");
    format_ = read_at<std::uint32_t>(8);
    if (format_ < kOldestCatalogFileFormat || format_ > kCatalogFileFormat) {
      return fail("catalog format " + std::to_string(format_) + ", this runtime reads formats " +
                  std::to_string(kOldestCatalogFileFormat) + " to " +
                  std::to_string(kCatalogFileFormat) + " (recompile the catalog with oasisc)");
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
    if (kind > static_cast<std::uint32_t>(ObservationKind::kMatrix)) {
      return fail("unknown observation kind " + std::to_string(kind));
    }
    view_.observation.kind = static_cast<ObservationKind>(kind);
    view_.observation.p_correct = read_at<double>(56);
    return format_ == 1 ? read_format1_table() : read_format2_table();
  }

  // Format 1: a fixed order of (offset, count) pairs, given their tags here.
  bool read_format1_table() {
    constexpr std::uint64_t kCatalogWideCount = kFormat1CatalogOrder.size();
    constexpr std::uint64_t kPerAbstractionCount = kFormat1AbstractionOrder.size();
    const std::uint64_t count =
        kCatalogWideCount + std::uint64_t{view_.num_abstractions} * kPerAbstractionCount;
    if (read_at<std::uint32_t>(12) != count ||
        count > (size_ - kCatalogHeaderBytes) / kFormat1EntryBytes) {
      return fail("table of contents does not match the number of abstractions");
    }
    entries_.reserve(count);
    for (std::uint64_t k = 0; k < count; ++k) {
      const std::size_t at = kCatalogHeaderBytes + k * kFormat1EntryBytes;
      const bool wide = k < kCatalogWideCount;
      const Section tag =
          wide ? kFormat1CatalogOrder[k]
               : kFormat1AbstractionOrder[(k - kCatalogWideCount) % kPerAbstractionCount];
      const std::uint32_t abstraction =
          wide ? kCatalogWide
               : static_cast<std::uint32_t>((k - kCatalogWideCount) / kPerAbstractionCount);
      entries_.push_back({static_cast<std::uint32_t>(tag), abstraction, read_at<std::uint64_t>(at),
                          read_at<std::uint64_t>(at + 8)});
    }
    return sort_entries();
  }

  bool read_format2_table() {
    const std::uint64_t count = read_at<std::uint32_t>(12);
    if (count > (size_ - kCatalogHeaderBytes) / kFormat2EntryBytes)
      return fail("section table runs past the end of the file");
    entries_.reserve(count);
    for (std::uint64_t k = 0; k < count; ++k) {
      const std::size_t at = kCatalogHeaderBytes + k * kFormat2EntryBytes;
      const Entry entry{read_at<std::uint32_t>(at), read_at<std::uint32_t>(at + 4),
                        read_at<std::uint64_t>(at + 8), read_at<std::uint64_t>(at + 16)};
      if ((entry.tag & kRequiredSection) != 0 && find_section(entry.tag) == nullptr) {
        return fail("the catalog has a section this runtime does not know (tag " +
                    std::to_string(entry.tag & ~kRequiredSection) + "); it needs a newer runtime");
      }
      if (entry.abstraction != kCatalogWide && entry.abstraction >= view_.num_abstractions)
        return fail("a section belongs to abstraction " + std::to_string(entry.abstraction) +
                    " of " + std::to_string(view_.num_abstractions));
      entries_.push_back(entry);
    }
    return sort_entries();
  }

  // The observation model's sections: a kMatrix model's confusion matrix (present exactly
  // then) and the reward source (absent: the true state's).
  bool parse_observation() {
    ObservationModel& obs = view_.observation;
    const bool matrix = obs.kind == ObservationKind::kMatrix;
    const std::uint64_t states = view_.num_states;
    const std::uint64_t cells =
        count_of(Section::kConfusion, kCatalogWide) == 0 && !matrix ? 0 : states * states;
    obs.confusion = wide<Section::kConfusion>(cells, !matrix);
    const std::uint32_t* source = wide<Section::kRewardSource>(1, true);
    if (!ok_) return false;
    if (source != nullptr) {
      if (*source > static_cast<std::uint32_t>(RewardSource::kObservedState))
        return fail("unknown reward source " + std::to_string(*source));
      obs.reward_source = static_cast<RewardSource>(*source);
    }
    return parse_position_noise();
  }

  // A continuous catalog's position noise: all three sections or none (validate() checks
  // the numbers).
  bool parse_position_noise() {
    PositionNoise& noise = view_.observation.position;
    const std::uint64_t sigmas = count_of(Section::kObjectSigma, kCatalogWide);
    if (sigmas == 0) return true;
    if (sigmas % 3 != 0 || sigmas / 3 >= kExactVariable)
      return fail("position noise: " + std::to_string(sigmas) + " sigma coefficients");
    const std::uint64_t objects = sigmas / 3;
    noise.sigma = wide<Section::kObjectSigma>(sigmas);
    noise.detection = wide<Section::kObjectDetection>(objects);
    noise.object_of = wide<Section::kObjectOf>(view_.state_dimension);
    noise.num_objects = static_cast<std::uint32_t>(objects);
    return ok_;
  }

  // Strings: offsets into the NUL-terminated text; each must start inside it and end at a
  // NUL inside it.
  bool parse_strings() {
    const std::uint32_t* dimension = wide<Section::kStateDimension>(
        count_of(Section::kStateDimension, kCatalogWide) == 0 ? 0 : 1, true);
    if (!ok_) return false;
    view_.state_dimension = dimension == nullptr ? 0 : *dimension;
    const std::uint64_t num_strings = 2 + std::uint64_t{view_.num_actions} + view_.num_states +
                                      view_.num_abstractions + view_.state_dimension;
    const std::uint64_t text_size = count_of(Section::kNameText, kCatalogWide);
    const char* text = wide<Section::kNameText>(text_size);
    const std::uint32_t* offsets = wide<Section::kStringOffsets>(num_strings);
    if (!ok_ || text == nullptr || text[text_size - 1] != '\0') return fail("malformed name text");
    names_.resize(num_strings);
    for (std::uint64_t i = 0; i < num_strings; ++i) {
      if (offsets[i] >= text_size) return fail("string offset out of range");
      names_[i] = text + offsets[i];
    }
    view_.name = names_[0];
    view_.compiler_version = names_[1];
    view_.action_names = names_.data() + 2;
    view_.state_names = view_.num_states == 0 ? nullptr : names_.data() + 2 + view_.num_actions;
    if (view_.state_dimension > 0) {
      view_.variable_names =
          names_.data() + 2 + view_.num_actions + view_.num_states + view_.num_abstractions;
    }
    return true;
  }

  // The stated properties: pairs of NUL-terminated strings (name, text), none when the
  // section is absent. Each abstraction's guarantees are then required (parse_abstraction).
  bool parse_properties() {
    const std::uint64_t size = count_of(Section::kPropertyText, kCatalogWide);
    const char* text = wide<Section::kPropertyText>(size, true);
    if (!ok_) return false;
    if (size == 0) return true;
    if (text[size - 1] != '\0') return fail("malformed property text");
    std::vector<const char*> strings;
    for (std::uint64_t at = 0; at < size; at += std::strlen(text + at) + 1)
      strings.push_back(text + at);
    if (strings.size() % 2 != 0) return fail("property text: a name without its property");
    if (strings.size() / 2 >= UINT32_MAX / kGuaranteeFields)
      return fail("property text: too many properties");
    for (std::size_t k = 0; k < strings.size(); k += 2) {
      property_names_.push_back(strings[k]);
      property_texts_.push_back(strings[k + 1]);
    }
    view_.properties.count = static_cast<std::uint32_t>(property_names_.size());
    view_.properties.names = property_names_.data();
    view_.properties.texts = property_texts_.data();
    return true;
  }

  // A continuous abstraction's grid and cell map, each count checked before it is used.
  void parse_grid(std::uint32_t i, AbstractionView& a) {
    const std::uint64_t d = count_of(Section::kGridAxes, i);
    a.grid.axes = of_abstraction<Section::kGridAxes>(i, d);
    a.grid.break_begin = of_abstraction<Section::kGridBreakBegin>(i, d + 1);
    if (!ok_ || d == 0 || d > UINT32_MAX - 1) {
      if (ok_) fail("a continuous abstraction without a grid");
      return;
    }
    a.grid.dimension = static_cast<std::uint32_t>(d);
    for (std::uint64_t k = 0; k < d; ++k) {
      if (a.grid.break_begin[k + 1] < a.grid.break_begin[k])
        return static_cast<void>(fail("grid break offsets decrease"));
    }
    a.grid.breaks = of_abstraction<Section::kGridBreaks>(i, a.grid.break_begin[d]);
    if (!ok_) return;
    if (!validate_grid(a.grid, view_.state_dimension))
      return static_cast<void>(fail("malformed grid in abstraction " + std::to_string(i)));
    if (count_of(Section::kBspCounts, i) != 0 && !parse_bsp(i, a)) return;
    a.cell_block = of_abstraction<Section::kCellBlock>(i, partition_cells(a));
    const std::uint32_t* outside = of_abstraction<Section::kOutsideBlock>(i, 1);
    const double* epsilon = of_abstraction<Section::kEpsilon>(i, 1, true);
    if (!ok_) return;
    a.outside_block = *outside;
    a.epsilon = epsilon == nullptr ? 0.0 : *epsilon;
  }

  // A polytope abstraction's BSP (its counts first, then arrays of those sizes); its shape is
  // checked by validate() with the rest of the view.
  bool parse_bsp(std::uint32_t i, AbstractionView& a) {
    const std::uint32_t* counts = of_abstraction<Section::kBspCounts>(i, 2);
    if (!ok_) return false;
    const std::uint64_t nodes = counts[0];
    if (nodes == 0 || counts[1] == 0)
      return fail("an empty BSP in abstraction " + std::to_string(i));
    a.bsp.num_nodes = counts[0];
    a.bsp.num_cells = counts[1];
    a.bsp.normal = of_abstraction<Section::kBspNormal>(i, nodes * a.grid.dimension);
    a.bsp.bound = of_abstraction<Section::kBspBound>(i, nodes);
    a.bsp.below = of_abstraction<Section::kBspBelow>(i, nodes);
    a.bsp.above = of_abstraction<Section::kBspAbove>(i, nodes);
    a.bsp.cell = of_abstraction<Section::kBspCell>(i, nodes);
    return ok_;
  }

  // A CSR relation: its rows, targets and probabilities. Absent (all three sections missing
  // or empty) when `optional`; then the view's pointers stay null.
  template <Section rows_tag, Section targets_tag, Section probabilities_tag>
  bool parse_transitions(std::uint32_t abstraction, std::uint64_t rows, TransitionsCsr& csr,
                         bool optional) {
    const std::uint64_t edges = count_of(targets_tag, abstraction);
    if (optional && count_of(rows_tag, abstraction) == 0 && edges == 0 &&
        count_of(probabilities_tag, abstraction) == 0)
      return ok_;
    if (edges > UINT32_MAX) return fail("too many edges");
    csr.choice_begin = of_abstraction<rows_tag>(abstraction, rows + 1);
    csr.target = of_abstraction<targets_tag>(abstraction, edges);
    csr.probability = of_abstraction<probabilities_tag>(abstraction, edges);
    csr.num_edges = static_cast<std::uint32_t>(edges);
    return ok_;
  }

  void parse_abstraction(std::uint32_t i, const std::uint32_t* blocks) {
    AbstractionView& a = abstractions_[i];
    const std::uint64_t states = view_.num_states;
    const std::uint64_t actions = view_.num_actions;
    a.context = names_[2 + actions + states + i];
    a.num_blocks = blocks[i];
    const std::uint64_t cells = std::uint64_t{a.num_blocks} * actions;
    if (view_.state_dimension > 0) {
      parse_grid(i, a);
    } else {
      a.block_of = of_abstraction<Section::kBlockOf>(i, states);
    }
    a.block_reward = of_abstraction<Section::kBlockReward>(i, a.num_blocks);
    if (!parse_transitions<Section::kQuotientRows, Section::kQuotientTargets,
                           Section::kQuotientProbabilities>(i, cells, a.quotient, true))
      return;
    a.reward = of_abstraction<Section::kReward>(i, cells);
    a.policy = of_abstraction<Section::kPolicy>(i, a.num_blocks);
    a.value = of_abstraction<Section::kValue>(i, a.num_blocks);
    parse_transitions<Section::kStateRows, Section::kStateTargets, Section::kStateProbabilities>(
        i, states * actions, a.state_transitions, true);
    const std::uint64_t properties = view_.properties.count;
    a.guarantee =
        of_abstraction<Section::kGuarantee>(i, properties * kGuaranteeFields, properties == 0);
  }

  void parse() {
    ok_ = true;
    if (!parse_header() || !parse_strings() || !parse_properties() || !parse_observation()) return;
    const std::uint32_t n = view_.num_abstractions;
    view_.switching = wide<Section::kSwitching>(std::uint64_t{n} * n);
    view_.prior = wide<Section::kPrior>(n);
    const std::uint32_t* blocks = wide<Section::kBlockCounts>(n);
    if (!ok_) return;
    abstractions_.assign(n, AbstractionView{});
    for (std::uint32_t i = 0; i < n && ok_; ++i)
      parse_abstraction(i, blocks);
    if (!ok_) return;
    view_.abstractions = abstractions_.data();
    std::string why;
    if (!validate(view_, &why)) fail("invalid catalog: " + why);
  }

  std::unique_ptr<unsigned char[]> storage_;  // the file's bytes
  std::size_t size_ = 0;
  std::vector<const char*> names_;
  std::vector<const char*> property_names_;  // the stated properties' (view_.properties)
  std::vector<const char*> property_texts_;
  std::vector<AbstractionView> abstractions_;
  std::vector<Entry> entries_;  // the section table, as read
  std::uint32_t format_ = 0;    // the file's format
  CatalogView view_;
  bool ok_ = false;
  std::string error_ = "not loaded";
};

}  // namespace rt
}  // namespace oasis
