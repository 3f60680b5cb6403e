#pragma once
// The catalog as C++ source, to link into a robot program: a header declaring
// `NAME::catalog()` and a few constexpr sizes, and a source file of plain `const` arrays
// (scalar initialisers, many per line, which compilers read quickly even for 10^6 states)
// and one rt::CatalogView over them. The output is byte-deterministic: no timestamps, no
// paths beyond the spec's file name.

#include <string>
#include <string_view>

#include "model/catalog_data.hpp"

namespace oasis::codegen {

struct CppSources {
  std::string header;  // BASENAME.hpp
  std::string source;  // BASENAME.cpp, includes "BASENAME.hpp"
};

// `basename` names the files; the namespace is the catalog's (the spec's model) name.
CppSources cpp_catalog(const model::CatalogData& catalog, std::string_view basename,
                       std::string_view spec_file_name);

}  // namespace oasis::codegen
