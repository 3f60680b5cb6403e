// The UMB container (umb_archive.hpp) on libarchive.

#include "formats/umb_archive.hpp"

#include <memory>
#include <set>

#include <archive.h>
#include <archive_entry.h>

namespace oasis::formats {
namespace {

struct ReadCloser {
  void operator()(archive* a) const { archive_read_free(a); }
};
struct WriteCloser {
  void operator()(archive* a) const { archive_write_free(a); }
};
struct EntryCloser {
  void operator()(archive_entry* e) const { archive_entry_free(e); }
};

std::string reason(archive* a, const char* fallback) {
  const char* text = archive_error_string(a);
  return text != nullptr && *text != '\0' ? std::string(text) : std::string(fallback);
}

std::string entry_name(const char* raw) {
  std::string name = raw != nullptr ? raw : "";
  while (name.starts_with("./"))
    name.erase(0, 2);
  return name;
}

// Appends the data of the current entry to `bytes`; false past `room` bytes or on an error.
bool read_data(archive* a, const std::string& name, std::size_t& room, std::string& bytes,
               std::string& error) {
  char block[65536];
  for (;;) {
    const la_ssize_t got = archive_read_data(a, block, sizeof block);
    if (got == 0) return true;
    if (got < 0) {
      error = "entry '" + name + "': " + reason(a, "cannot be read");
      return false;
    }
    const auto size = static_cast<std::size_t>(got);
    if (size > room) {
      error =
          "the archive's contents are larger than the input limit (--max-input-size) when "
          "decompressed";
      return false;
    }
    room -= size;
    bytes.append(block, size);
  }
}

la_ssize_t write_to_string(archive* /*a*/, void* client, const void* buffer, std::size_t length) {
  static_cast<std::string*>(client)->append(static_cast<const char*>(buffer), length);
  return static_cast<la_ssize_t>(length);
}

}  // namespace

bool read_umb_archive(std::string_view bytes, std::size_t max_bytes, std::vector<UmbEntry>& entries,
                      std::string& error) {
  const std::unique_ptr<archive, ReadCloser> owner(archive_read_new());
  archive* a = owner.get();
  if (a == nullptr) {
    error = "cannot start reading the archive";
    return false;
  }
  // The format allows tar, plain or compressed with gzip or xz: nothing else is tried.
  archive_read_support_filter_gzip(a);
  archive_read_support_filter_xz(a);
  archive_read_support_format_tar(a);
  if (archive_read_open_memory(a, bytes.data(), bytes.size()) != ARCHIVE_OK) {
    error = "not a UMB file (a tar archive, plain or compressed with gzip or xz): " +
            reason(a, "unknown format");
    return false;
  }
  std::set<std::string, std::less<>> seen;
  std::size_t room = max_bytes;
  for (;;) {
    archive_entry* entry = nullptr;
    const int status = archive_read_next_header(a, &entry);
    if (status == ARCHIVE_EOF) return true;
    if (status != ARCHIVE_OK && status != ARCHIVE_WARN) {
      error = (entries.empty() && seen.empty()
                   ? "not a UMB file (a tar archive, plain or compressed with gzip or xz): "
                   : "the archive is damaged after entry '" +
                         (entries.empty() ? std::string() : entries.back().name) + "': ") +
              reason(a, "unreadable header");
      return false;
    }
    if (archive_entry_filetype(entry) != AE_IFREG) continue;
    std::string name = entry_name(archive_entry_pathname(entry));
    if (!seen.insert(name).second) {
      error = "entry '" + name + "' appears twice in the archive";
      return false;
    }
    UmbEntry read{std::move(name), {}};
    if (!read_data(a, read.name, room, read.bytes, error)) return false;
    entries.push_back(std::move(read));
  }
}

bool write_umb_archive(const std::vector<UmbEntry>& entries, std::string& out, std::string& error) {
  const std::unique_ptr<archive, WriteCloser> owner(archive_write_new());
  archive* a = owner.get();
  const auto fail = [&](const char* what) {
    error = std::string(what) + ": " + reason(a, "libarchive failed");
    return false;
  };
  if (a == nullptr) return fail("cannot start the archive");
  // POSIX tar (pax extensions only for a name longer than ustar holds), gzip without the
  // timestamp in its header, and no padding of the last block beyond what tar needs.
  if (archive_write_set_format_pax_restricted(a) != ARCHIVE_OK ||
      archive_write_add_filter_gzip(a) != ARCHIVE_OK ||
      archive_write_set_filter_option(a, "gzip", "timestamp", nullptr) != ARCHIVE_OK ||
      archive_write_set_bytes_in_last_block(a, 1) != ARCHIVE_OK) {
    return fail("cannot set up the archive");
  }
  if (archive_write_open(a, &out, nullptr, write_to_string, nullptr) != ARCHIVE_OK)
    return fail("cannot start the archive");
  for (const UmbEntry& item : entries) {
    const std::unique_ptr<archive_entry, EntryCloser> entry(archive_entry_new());
    if (!entry) return fail("cannot make an archive entry");
    archive_entry_set_pathname(entry.get(), item.name.c_str());
    archive_entry_set_filetype(entry.get(), AE_IFREG);
    archive_entry_set_perm(entry.get(), 0644);
    archive_entry_set_size(entry.get(), static_cast<la_int64_t>(item.bytes.size()));
    archive_entry_set_mtime(entry.get(), 0, 0);
    if (archive_write_header(a, entry.get()) != ARCHIVE_OK) return fail("cannot write an entry");
    std::size_t done = 0;
    while (done < item.bytes.size()) {
      const la_ssize_t wrote =
          archive_write_data(a, item.bytes.data() + done, item.bytes.size() - done);
      if (wrote <= 0) return fail("cannot write an entry");
      done += static_cast<std::size_t>(wrote);
    }
  }
  if (archive_write_close(a) != ARCHIVE_OK) return fail("cannot finish the archive");
  return true;
}

}  // namespace oasis::formats
