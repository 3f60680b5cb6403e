#include "codegen/binary_catalog.hpp"

#include <bit>
#include <cstring>
#include <type_traits>

#include "oasis/rt/catalog_sections.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "support/atomic_file.hpp"

namespace oasis::codegen {
namespace {

static_assert(std::endian::native == std::endian::little, "catalog files are little-endian");

// A section as kSectionTable describes it, checked when this file compiles: the array's
// element type and the section's scope must be the table's, and the format this writer
// writes must have the section.
template <rt::Section tag, rt::SectionScope scope, typename T>
constexpr void check_section() {
  constexpr rt::SectionInfo kInfo = rt::section_info(tag);
  static_assert(std::is_same_v<T, rt::SectionElementOf<tag>>, "not the table's element type");
  static_assert(kInfo.scope == scope, "not the table's scope");
  static_assert(kInfo.first_format <= rt::kCatalogFileFormat, "a section of a later format");
}

// Collects tagged sections, then lays out the header, the section table and the arrays
// (catalog_sections.hpp). Sections are written in the order they are added.
class Builder {
 public:
  template <typename T>
  void put_at(std::size_t offset, T value) {
    std::memcpy(header_.data() + offset, &value, sizeof value);
  }

  // A catalog-wide section.
  template <rt::Section tag, typename T>
  void wide(const T* data, std::size_t count) {
    check_section<tag, rt::SectionScope::kCatalog, T>();
    add(tag, rt::kCatalogWide, data, count);
  }
  template <rt::Section tag, typename T>
  void wide(const std::vector<T>& data) {
    wide<tag>(data.data(), data.size());
  }

  // A section of abstraction i.
  template <rt::Section tag, typename T>
  void of_abstraction(std::uint32_t i, const T* data, std::size_t count) {
    check_section<tag, rt::SectionScope::kAbstraction, T>();
    add(tag, i, data, count);
  }
  template <rt::Section tag, typename T>
  void of_abstraction(std::uint32_t i, const std::vector<T>& data) {
    of_abstraction<tag>(i, data.data(), data.size());
  }

  std::string finish() {
    std::string out = header_;
    const std::size_t table = out.size();
    out.resize(table + sections_.size() * rt::kFormat2EntryBytes, '\0');
    for (std::size_t k = 0; k < sections_.size(); ++k) {
      out.resize((out.size() + 7) / 8 * 8, '\0');
      const Pending& pending = sections_[k];
      const std::size_t entry = table + k * rt::kFormat2EntryBytes;
      write(out, entry, static_cast<std::uint32_t>(pending.tag));
      write(out, entry + 4, pending.abstraction);
      write<std::uint64_t>(out, entry + 8, out.size());
      write<std::uint64_t>(out, entry + 16, pending.count);
      out += pending.bytes;
    }
    out.resize((out.size() + 7) / 8 * 8, '\0');
    write<std::uint32_t>(out, 8, rt::kCatalogFileFormat);
    write<std::uint32_t>(out, 12, static_cast<std::uint32_t>(sections_.size()));
    write<std::uint64_t>(out, 16, out.size());
    const auto* data = reinterpret_cast<const unsigned char*>(out.data());
    write<std::uint64_t>(out, 24, rt::fnv1a64(data + 32, out.size() - 32));
    return out;
  }

 private:
  struct Pending {
    rt::Section tag;
    std::uint32_t abstraction;
    std::size_t count;
    std::string bytes;
  };

  template <typename T>
  void add(rt::Section tag, std::uint32_t abstraction, const T* data, std::size_t count) {
    std::string bytes(count * sizeof(T), '\0');
    if (count > 0) std::memcpy(bytes.data(), data, bytes.size());
    sections_.push_back({tag, abstraction, count, std::move(bytes)});
  }

  template <typename T>
  static void write(std::string& out, std::size_t offset, T value) {
    std::memcpy(out.data() + offset, &value, sizeof value);
  }

  std::string header_ = std::string(rt::kCatalogHeaderBytes, '\0');
  std::vector<Pending> sections_;
};

// All strings in one NUL-separated text, in the order the loader expects.
void add_strings(const model::CatalogData& catalog, Builder& out) {
  std::string text;
  std::vector<std::uint32_t> offsets;
  auto add = [&](const std::string& s) {
    offsets.push_back(static_cast<std::uint32_t>(text.size()));
    text += s;
    text += '\0';
  };
  add(catalog.name);
  add(catalog.compiler_version);
  for (const std::string& action : catalog.action_names)
    add(action);
  for (const std::string& state : catalog.state_names)
    add(state);
  for (const model::AbstractionData& abstraction : catalog.abstractions)
    add(abstraction.context);
  for (const std::string& variable : catalog.variable_names)
    add(variable);
  out.wide<rt::Section::kNameText>(text.data(), text.size());
  out.wide<rt::Section::kStringOffsets>(offsets);
}

template <rt::Section rows, rt::Section targets, rt::Section probabilities>
void add_csr(const model::CsrData& csr, std::uint32_t abstraction, Builder& out) {
  if (csr.choice_begin.empty()) return;  // absent: an optional section, or no robust section
  out.of_abstraction<rows>(abstraction, csr.choice_begin);
  out.of_abstraction<targets>(abstraction, csr.target);
  out.of_abstraction<probabilities>(abstraction, csr.probability);
}

void add_grid(const model::AbstractionData& abstraction, std::uint32_t i, Builder& out) {
  out.of_abstraction<rt::Section::kGridAxes>(i, abstraction.grid_axes);
  out.of_abstraction<rt::Section::kGridBreakBegin>(i, abstraction.grid_break_begin);
  out.of_abstraction<rt::Section::kGridBreaks>(i, abstraction.grid_breaks);
  out.of_abstraction<rt::Section::kCellBlock>(i, abstraction.cell_block);
  out.of_abstraction<rt::Section::kOutsideBlock>(i, &abstraction.outside_block, 1);
  out.of_abstraction<rt::Section::kEpsilon>(i, &abstraction.epsilon, 1);
  if (abstraction.bsp_cell.empty()) return;
  const std::uint32_t counts[2] = {static_cast<std::uint32_t>(abstraction.bsp_cell.size()),
                                   abstraction.bsp_cells};
  out.of_abstraction<rt::Section::kBspCounts>(i, counts, 2);
  out.of_abstraction<rt::Section::kBspNormal>(i, abstraction.bsp_normal);
  out.of_abstraction<rt::Section::kBspBound>(i, abstraction.bsp_bound);
  out.of_abstraction<rt::Section::kBspBelow>(i, abstraction.bsp_below);
  out.of_abstraction<rt::Section::kBspAbove>(i, abstraction.bsp_above);
  out.of_abstraction<rt::Section::kBspCell>(i, abstraction.bsp_cell);
}

// The stated properties: their names and texts, "name\0text\0" each, and per abstraction its
// guarantees (absent, as the loader expects, when the catalog states none).
void add_properties(const model::CatalogData& catalog, Builder& out) {
  if (catalog.properties.empty()) return;
  std::string text;
  for (const model::StatedProperty& property : catalog.properties) {
    text += property.name;
    text += '\0';
    text += property.text;
    text += '\0';
  }
  out.wide<rt::Section::kPropertyText>(text.data(), text.size());
  for (std::uint32_t i = 0; i < catalog.abstractions.size(); ++i)
    out.of_abstraction<rt::Section::kGuarantee>(i, catalog.abstractions[i].guarantee);
}

}  // namespace

std::string binary_catalog(const model::CatalogData& catalog) {
  const auto n = static_cast<std::uint32_t>(catalog.abstractions.size());
  Builder out;
  out.put_at<std::uint64_t>(0, rt::kCatalogMagic);
  out.put_at<std::uint64_t>(32, catalog.spec_hash);
  out.put_at<std::uint32_t>(40, catalog.num_states);
  out.put_at<std::uint32_t>(44, catalog.num_actions);
  out.put_at<std::uint32_t>(48, n);
  out.put_at<std::uint32_t>(52, static_cast<std::uint32_t>(catalog.observation));
  out.put_at<double>(56, catalog.p_correct);
  add_strings(catalog, out);
  if (!catalog.variable_names.empty()) {
    const auto dimension = static_cast<std::uint32_t>(catalog.variable_names.size());
    out.wide<rt::Section::kStateDimension>(&dimension, 1);
  }
  if (catalog.observation == rt::ObservationKind::kMatrix)
    out.wide<rt::Section::kConfusion>(catalog.confusion);
  if (catalog.observation != rt::ObservationKind::kNone ||
      catalog.reward_source != rt::RewardSource::kTrueState) {
    const auto source = static_cast<std::uint32_t>(catalog.reward_source);
    out.wide<rt::Section::kRewardSource>(&source, 1);
  }
  if (!catalog.position.empty()) {
    out.wide<rt::Section::kObjectOf>(catalog.position.object_of);
    out.wide<rt::Section::kObjectSigma>(catalog.position.sigma);
    out.wide<rt::Section::kObjectDetection>(catalog.position.detection);
  }
  out.wide<rt::Section::kSwitching>(catalog.switching);
  out.wide<rt::Section::kPrior>(catalog.prior);
  std::vector<std::uint32_t> blocks;
  for (const model::AbstractionData& abstraction : catalog.abstractions)
    blocks.push_back(abstraction.num_blocks);
  out.wide<rt::Section::kBlockCounts>(blocks);
  for (std::uint32_t i = 0; i < n; ++i) {
    const model::AbstractionData& abstraction = catalog.abstractions[i];
    if (catalog.variable_names.empty()) {
      out.of_abstraction<rt::Section::kBlockOf>(i, abstraction.block_of);
    } else {
      add_grid(abstraction, i, out);
    }
    out.of_abstraction<rt::Section::kBlockReward>(i, abstraction.block_reward);
    add_csr<rt::Section::kQuotientRows, rt::Section::kQuotientTargets,
            rt::Section::kQuotientProbabilities>(abstraction.quotient, i, out);
    out.of_abstraction<rt::Section::kReward>(i, abstraction.reward);
    out.of_abstraction<rt::Section::kPolicy>(i, abstraction.policy);
    out.of_abstraction<rt::Section::kValue>(i, abstraction.value);
    add_csr<rt::Section::kStateRows, rt::Section::kStateTargets, rt::Section::kStateProbabilities>(
        abstraction.state_transitions, i, out);
  }
  add_properties(catalog, out);
  return out.finish();
}

bool write_binary_catalog(const model::CatalogData& catalog, const std::string& path,
                          std::string& error) {
  return write_atomically(path, binary_catalog(catalog), error);
}

}  // namespace oasis::codegen
