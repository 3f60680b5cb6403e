#include "fit/spec_fragment.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace oasis::fit {
namespace {

// `units` / 10^decimals as text, trailing zeros dropped.
std::string fixed_point_text(long long units, int decimals) {
  const bool negative = units < 0;
  if (negative) units = -units;
  long long scale = 1;
  for (int k = 0; k < decimals; ++k)
    scale *= 10;
  std::string text = std::to_string(units / scale);
  std::string fraction = std::to_string(units % scale);
  fraction = std::string(static_cast<std::size_t>(decimals) - fraction.size(), '0') + fraction;
  while (!fraction.empty() && fraction.back() == '0')
    fraction.pop_back();
  if (!fraction.empty()) text += "." + fraction;
  return (negative && units != 0 ? "-" : "") + text;
}

long long scale_of(int decimals) {
  long long scale = 1;
  for (int k = 0; k < decimals; ++k)
    scale *= 10;
  return scale;
}

std::string distribution(const std::vector<std::string>& texts,
                         const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t j = 0; j < texts.size(); ++j) {
    if (texts[j] == "0") continue;
    out += (out.empty() ? "" : " + ") + texts[j] + ": " + names[j];
  }
  return out;
}

}  // namespace

std::string decimal_text(double value, int decimals) {
  const double scaled = value * static_cast<double>(scale_of(decimals));
  if (!std::isfinite(scaled) || std::fabs(scaled) > 9e18)
    throw std::domain_error("cannot write " + std::to_string(value) + " as a decimal number");
  return fixed_point_text(std::llround(scaled), decimals);
}

std::vector<std::string> exact_row(const std::vector<double>& row, int decimals) {
  const long long scale = scale_of(decimals);
  std::vector<long long> units(row.size());
  long long sum = 0;
  std::size_t largest = 0;
  for (std::size_t j = 0; j < row.size(); ++j) {
    units[j] = std::llround(row[j] * static_cast<double>(scale));
    sum += units[j];
    if (row[j] > row[largest]) largest = j;
  }
  if (!row.empty()) units[largest] += scale - sum;
  std::vector<std::string> texts;
  for (long long u : units)
    texts.push_back(fixed_point_text(u, decimals));
  return texts;
}

std::string switching_stay_fragment(double p_stay, int decimals) {
  return "switching stay " + decimal_text(p_stay, decimals) + ";\n";
}

std::string switching_matrix_fragment(const std::vector<double>& matrix,
                                      const std::vector<std::string>& contexts, int decimals) {
  const std::size_t n = contexts.size();
  std::string out = "switching {\n";
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<double> row(matrix.begin() + static_cast<std::ptrdiff_t>(i * n),
                                  matrix.begin() + static_cast<std::ptrdiff_t>((i + 1) * n));
    out += "  " + contexts[i] + " -> " + distribution(exact_row(row, decimals), contexts) + ";\n";
  }
  return out + "}\n";
}

std::string state_noise_fragment(double sigma, const std::string& reward_follows, int decimals) {
  const std::string noise = decimal_text(sigma, decimals);
  if (!(sigma >= 0.0) || noise == "1")
    throw std::domain_error(
        "the fitted state noise is " + noise +
        ": (nearly) every label is wrong, which no state noise in [0, 1) describes; "
        "are the columns true_state,observed_state swapped?");
  return "observation {\n  state noise " + noise + ";\n  reward follows " + reward_follows +
         ";\n}\n";
}

std::string confusion_fragment(const std::vector<double>& matrix,
                               const std::vector<std::string>& states,
                               const std::string& reward_follows, int decimals) {
  const std::size_t n = states.size();
  std::string out = "observation {\n  state confusion {\n";
  for (std::size_t s = 0; s < n; ++s) {
    const std::vector<double> row(matrix.begin() + static_cast<std::ptrdiff_t>(s * n),
                                  matrix.begin() + static_cast<std::ptrdiff_t>((s + 1) * n));
    out += "    " + states[s] + " -> " + distribution(exact_row(row, decimals), states) + ";\n";
  }
  return out + "  }\n  reward follows " + reward_follows + ";\n}\n";
}

std::string object_noise_fragment(const std::string& name,
                                  const std::vector<std::string>& variables,
                                  const std::vector<double>& sigma, int digits) {
  std::string out = "object " + name + " (";
  for (std::size_t v = 0; v < variables.size(); ++v)
    out += (v ? ", " : "") + variables[v];
  out += ") { noise " + significant_text(sigma.empty() ? 0.0 : sigma[0], digits);
  const char* powers[] = {"", " * d", " * d * d"};
  for (std::size_t k = 1; k < sigma.size() && k < 3; ++k) {
    out += sigma[k] < 0 ? " - " : " + ";
    out += significant_text(std::fabs(sigma[k]), digits) + powers[k];
  }
  return out + "; }\n";
}

std::string significant_text(double value, int digits) {
  std::ostringstream out;
  out << std::setprecision(digits) << value;
  return out.str();
}

}  // namespace oasis::fit
