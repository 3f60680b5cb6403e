#pragma once
// Test helper: a binary catalog's bytes edited in place, as a careful attacker would, so that
// the file still loads and only the verifier can tell (catalog_sections.hpp, format 2).

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "oasis/rt/catalog_sections.hpp"
#include "oasis/rt/spec_hash.hpp"

namespace oasis::test {

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Writes the checksum a catalog file must carry (FNV-1a of bytes 32..end, at offset 24).
inline void fix_checksum(std::string& bytes) {
  const std::uint64_t checksum =
      rt::fnv1a64(reinterpret_cast<const unsigned char*>(bytes.data()) + 32, bytes.size() - 32);
  std::memcpy(bytes.data() + 24, &checksum, sizeof checksum);
}

// Where a section of a catalog file starts; 0 if absent.
inline std::uint64_t section_offset(const std::string& bytes, rt::Section tag,
                                    std::uint32_t abstraction) {
  std::uint32_t entries = 0;
  std::memcpy(&entries, bytes.data() + 12, sizeof entries);
  for (std::uint32_t k = 0; k < entries; ++k) {
    const char* entry =
        bytes.data() + rt::kCatalogHeaderBytes + std::size_t{k} * rt::kFormat2EntryBytes;
    std::uint32_t entry_tag = 0;
    std::uint32_t entry_abstraction = 0;
    std::uint64_t offset = 0;
    std::memcpy(&entry_tag, entry, sizeof entry_tag);
    std::memcpy(&entry_abstraction, entry + 4, sizeof entry_abstraction);
    std::memcpy(&offset, entry + 8, sizeof offset);
    if (entry_tag == static_cast<std::uint32_t>(tag) && entry_abstraction == abstraction)
      return offset;
  }
  return 0;
}

}  // namespace oasis::test
