#pragma once
// How the paper's tables are printed, shared by Table I (oasis-sim) and Table II (oasis-go1
// score) so that both read alike: "0.91 ± 0.07" cells in columns padded by display width.

#include <cstddef>
#include <string>

#include "metrics/mean_std.hpp"

namespace oasis::metrics {

// "mean ± std" with two decimals.
std::string mean_std_text(const MeanStd& value);

// `text` followed by spaces up to `width` display columns (UTF-8 aware: "±" is one column).
std::string pad_columns(const std::string& text, std::size_t width);

}  // namespace oasis::metrics
