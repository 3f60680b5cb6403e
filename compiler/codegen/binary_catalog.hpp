#pragma once
// The binary catalog file (layout: runtime/include/oasis/rt/catalog_file.hpp, which also
// holds the loader): little-endian, 8-byte aligned arrays, magic, format version, sizes and
// a checksum. Output is byte-deterministic for a given catalog.

#include <string>

#include "model/catalog_data.hpp"

namespace oasis::codegen {

std::string binary_catalog(const model::CatalogData& catalog);

// Writes atomically (temporary file, then rename): the file appears whole or not at all.
bool write_binary_catalog(const model::CatalogData& catalog, const std::string& path,
                          std::string& error);

}  // namespace oasis::codegen
