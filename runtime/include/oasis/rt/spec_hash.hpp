// oasis/rt/spec_hash.hpp: the one hash of oasis, FNV-1a 64-bit.
//
// It fingerprints the spec a catalog was compiled from (CatalogView::spec_hash: the hash of
// the spec file's bytes) and checksums binary catalog files. FNV-1a is tiny, has no
// dependencies and gives the same value on every platform, so a robot program can check its
// catalog against its configuration without the compiler. It is not cryptographic: it
// detects accidents (a stale catalog, a damaged file), not an adversary.
//
// Published test values (Fowler/Noll/Vo): "" -> 0xcbf29ce484222325 (the offset basis),
// "a" -> 0xaf63dc4c8601ec8c, "foobar" -> 0x85944171f73967e8.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace oasis {
namespace rt {

/// FNV-1a 64 offset basis: the hash of no bytes.
inline constexpr std::uint64_t kFnv1a64Basis = 0xcbf29ce484222325ULL;

/// FNV-1a 64-bit over `size` bytes, continuing from `hash` (the basis for a fresh hash).
inline constexpr std::uint64_t fnv1a64(const unsigned char* data, std::size_t size,
                                       std::uint64_t hash = kFnv1a64Basis) noexcept {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

/// The spec hash of a spec's text: FNV-1a 64 over its bytes.
inline constexpr std::uint64_t spec_hash(std::string_view text) noexcept {
  std::uint64_t hash = kFnv1a64Basis;
  for (char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

/// A hash as every tool prints it: 16 lower-case hex digits ("8b73c5aabd717338").
inline std::string spec_hash_text(std::uint64_t hash) {
  std::string text(16, '0');
  for (std::size_t digit = 16; digit-- > 0; hash >>= 4)
    text[digit] = "0123456789abcdef"[hash & 0xF];
  return text;
}

static_assert(spec_hash("a") == 0xaf63dc4c8601ec8cULL, "FNV-1a 64 published test value");
static_assert(spec_hash("foobar") == 0x85944171f73967e8ULL, "FNV-1a 64 published test value");

}  // namespace rt
}  // namespace oasis
