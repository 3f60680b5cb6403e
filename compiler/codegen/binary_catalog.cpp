#include "codegen/binary_catalog.hpp"

#include <bit>
#include <cstring>

#include "oasis/rt/catalog_sections.hpp"
#include "oasis/rt/spec_hash.hpp"
#include "support/atomic_file.hpp"

namespace oasis::codegen {
namespace {

static_assert(std::endian::native == std::endian::little, "catalog files are little-endian");

// Collects tagged sections, then lays out the header, the section table and the arrays
// (catalog_sections.hpp). Sections are written in the order they are added.
class Builder {
 public:
  template <typename T>
  void put_at(std::size_t offset, T value) {
    std::memcpy(header_.data() + offset, &value, sizeof value);
  }

  template <typename T>
  void section(rt::Section tag, std::uint32_t abstraction, const T* data, std::size_t count) {
    std::string bytes(count * sizeof(T), '\0');
    if (count > 0) std::memcpy(bytes.data(), data, bytes.size());
    sections_.push_back({tag, abstraction, count, std::move(bytes)});
  }
  template <typename T>
  void section(rt::Section tag, std::uint32_t abstraction, const std::vector<T>& data) {
    section(tag, abstraction, data.data(), data.size());
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
  out.section(rt::Section::kNameText, rt::kCatalogWide, text.data(), text.size());
  out.section(rt::Section::kStringOffsets, rt::kCatalogWide, offsets);
}

void add_csr(const model::CsrData& csr, std::uint32_t abstraction, rt::Section rows,
             rt::Section targets, rt::Section probabilities, Builder& out) {
  if (csr.choice_begin.empty()) return;  // absent: an optional section, or no robust section
  out.section(rows, abstraction, csr.choice_begin);
  out.section(targets, abstraction, csr.target);
  out.section(probabilities, abstraction, csr.probability);
}

void add_grid(const model::AbstractionData& abstraction, std::uint32_t i, Builder& out) {
  out.section(rt::Section::kGridAxes, i, abstraction.grid_axes);
  out.section(rt::Section::kGridBreakBegin, i, abstraction.grid_break_begin);
  out.section(rt::Section::kGridBreaks, i, abstraction.grid_breaks);
  out.section(rt::Section::kCellBlock, i, abstraction.cell_block);
  out.section(rt::Section::kOutsideBlock, i, &abstraction.outside_block, 1);
  out.section(rt::Section::kEpsilon, i, &abstraction.epsilon, 1);
  if (abstraction.bsp_cell.empty()) return;
  const std::uint32_t counts[2] = {static_cast<std::uint32_t>(abstraction.bsp_cell.size()),
                                   abstraction.bsp_cells};
  out.section(rt::Section::kBspCounts, i, counts, 2);
  out.section(rt::Section::kBspNormal, i, abstraction.bsp_normal);
  out.section(rt::Section::kBspBound, i, abstraction.bsp_bound);
  out.section(rt::Section::kBspBelow, i, abstraction.bsp_below);
  out.section(rt::Section::kBspAbove, i, abstraction.bsp_above);
  out.section(rt::Section::kBspCell, i, abstraction.bsp_cell);
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
    out.section(rt::Section::kStateDimension, rt::kCatalogWide, &dimension, 1);
  }
  if (catalog.observation == rt::ObservationKind::kMatrix)
    out.section(rt::Section::kConfusion, rt::kCatalogWide, catalog.confusion);
  if (catalog.observation != rt::ObservationKind::kNone ||
      catalog.reward_source != rt::RewardSource::kTrueState) {
    const auto source = static_cast<std::uint32_t>(catalog.reward_source);
    out.section(rt::Section::kRewardSource, rt::kCatalogWide, &source, 1);
  }
  if (!catalog.position.empty()) {
    out.section(rt::Section::kObjectOf, rt::kCatalogWide, catalog.position.object_of);
    out.section(rt::Section::kObjectSigma, rt::kCatalogWide, catalog.position.sigma);
    out.section(rt::Section::kObjectDetection, rt::kCatalogWide, catalog.position.detection);
  }
  out.section(rt::Section::kSwitching, rt::kCatalogWide, catalog.switching);
  out.section(rt::Section::kPrior, rt::kCatalogWide, catalog.prior);
  std::vector<std::uint32_t> blocks;
  for (const model::AbstractionData& abstraction : catalog.abstractions)
    blocks.push_back(abstraction.num_blocks);
  out.section(rt::Section::kBlockCounts, rt::kCatalogWide, blocks);
  for (std::uint32_t i = 0; i < n; ++i) {
    const model::AbstractionData& abstraction = catalog.abstractions[i];
    if (catalog.variable_names.empty()) {
      out.section(rt::Section::kBlockOf, i, abstraction.block_of);
    } else {
      add_grid(abstraction, i, out);
    }
    out.section(rt::Section::kBlockReward, i, abstraction.block_reward);
    add_csr(abstraction.quotient, i, rt::Section::kQuotientRows, rt::Section::kQuotientTargets,
            rt::Section::kQuotientProbabilities, out);
    out.section(rt::Section::kReward, i, abstraction.reward);
    out.section(rt::Section::kPolicy, i, abstraction.policy);
    out.section(rt::Section::kValue, i, abstraction.value);
    add_csr(abstraction.state_transitions, i, rt::Section::kStateRows, rt::Section::kStateTargets,
            rt::Section::kStateProbabilities, out);
  }
  return out.finish();
}

bool write_binary_catalog(const model::CatalogData& catalog, const std::string& path,
                          std::string& error) {
  AtomicFile file;
  if (!file.open(path, error)) return false;
  file.append(binary_catalog(catalog));
  return file.commit(error);
}

}  // namespace oasis::codegen
