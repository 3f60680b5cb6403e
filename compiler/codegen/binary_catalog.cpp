#include "codegen/binary_catalog.hpp"

#include <bit>
#include <cstring>

#include "oasis/rt/catalog_file.hpp"
#include "support/atomic_file.hpp"

namespace oasis::codegen {
namespace {

static_assert(std::endian::native == std::endian::little, "catalog files are little-endian");

class Builder {
 public:
  explicit Builder(std::uint32_t num_arrays) : num_arrays_(num_arrays) {
    bytes_.assign(rt::kCatalogHeaderBytes + std::size_t{num_arrays} * 16, '\0');
  }

  template <typename T>
  void put_at(std::size_t offset, T value) {
    std::memcpy(bytes_.data() + offset, &value, sizeof value);
  }

  // Appends the next array of the table of contents, 8-byte aligned.
  template <typename T>
  void array(const T* data, std::size_t count) {
    bytes_.resize((bytes_.size() + 7) / 8 * 8, '\0');
    const std::size_t entry = rt::kCatalogHeaderBytes + std::size_t{next_++} * 16;
    put_at<std::uint64_t>(entry, bytes_.size());
    put_at<std::uint64_t>(entry + 8, count);
    if (count > 0) bytes_.append(reinterpret_cast<const char*>(data), count * sizeof(T));
  }
  template <typename T>
  void array(const std::vector<T>& data) {
    array(data.data(), data.size());
  }

  std::string finish() {
    bytes_.resize((bytes_.size() + 7) / 8 * 8, '\0');
    put_at<std::uint32_t>(12, num_arrays_);
    put_at<std::uint64_t>(16, bytes_.size());
    const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data());
    put_at<std::uint64_t>(24, rt::fnv1a64(data + 32, bytes_.size() - 32));
    return std::move(bytes_);
  }

 private:
  std::uint32_t num_arrays_;
  std::uint32_t next_ = 0;
  std::string bytes_;
};

// All strings in one NUL-separated text, in the order the loader expects.
void add_strings(const CatalogData& catalog, Builder& out) {
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
  for (const AbstractionData& abstraction : catalog.abstractions)
    add(abstraction.context);
  out.array(text.data(), text.size());
  out.array(offsets);
}

void add_csr(const CsrData& csr, Builder& out) {
  out.array(csr.choice_begin);
  out.array(csr.target);
  out.array(csr.probability);
}

}  // namespace

std::string binary_catalog(const CatalogData& catalog) {
  const auto n = static_cast<std::uint32_t>(catalog.abstractions.size());
  Builder out(rt::kCatalogGlobalArrays + n * rt::kCatalogArraysPerAbstraction);
  out.put_at<std::uint64_t>(0, rt::kCatalogMagic);
  out.put_at<std::uint32_t>(8, rt::kCatalogFormat);
  out.put_at<std::uint64_t>(32, catalog.spec_hash);
  out.put_at<std::uint32_t>(40, catalog.num_states);
  out.put_at<std::uint32_t>(44, catalog.num_actions);
  out.put_at<std::uint32_t>(48, n);
  out.put_at<std::uint32_t>(52, static_cast<std::uint32_t>(catalog.observation));
  out.put_at<double>(56, catalog.p_correct);
  add_strings(catalog, out);
  out.array(catalog.switching);
  out.array(catalog.prior);
  std::vector<std::uint32_t> blocks;
  for (const AbstractionData& abstraction : catalog.abstractions)
    blocks.push_back(abstraction.num_blocks);
  out.array(blocks);
  for (const AbstractionData& abstraction : catalog.abstractions) {
    out.array(abstraction.block_of);
    out.array(abstraction.block_reward);
    add_csr(abstraction.quotient, out);
    out.array(abstraction.reward);
    out.array(abstraction.policy);
    out.array(abstraction.value);
    add_csr(abstraction.state_transitions, out);
  }
  return out.finish();
}

bool write_binary_catalog(const CatalogData& catalog, const std::string& path, std::string& error) {
  AtomicFile file;
  if (!file.open(path, error)) return false;
  file.append(binary_catalog(catalog));
  return file.commit(error);
}

}  // namespace oasis::codegen
