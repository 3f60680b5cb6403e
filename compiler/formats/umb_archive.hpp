#pragma once
// The container of a UMB file (docs/formats.md, "UMB"): a tar archive, read plain or
// compressed with gzip or xz, and written as a gzip-compressed tar. This is the only file that
// includes libarchive; the UMB reader and writer see named byte strings.
//
// Reading is bounded: the decompressed entries together may hold at most `max_bytes`, so a
// small file that inflates without end (a "zip bomb") stops with an error instead of taking
// the machine's memory. Writing is deterministic: entries in the order given, every
// timestamp, owner and gzip header field fixed, so the same model gives the same bytes.

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace oasis::formats {

struct UmbEntry {
  std::string name;   // the path inside the archive, without a leading "./"
  std::string bytes;  // its contents, decompressed
};

// Reads the regular files of the archive in `bytes` in their order (directories and other
// kinds of entries are skipped). Returns false and sets `error` for what is not a readable
// tar (or gzip/xz of one), an entry named twice, or contents past `max_bytes`.
bool read_umb_archive(std::string_view bytes, std::size_t max_bytes, std::vector<UmbEntry>& entries,
                      std::string& error);

// Writes `entries`, in order, as a gzip-compressed tar archive into `out`. Returns false and
// sets `error` when libarchive fails.
bool write_umb_archive(const std::vector<UmbEntry>& entries, std::string& out, std::string& error);

}  // namespace oasis::formats
