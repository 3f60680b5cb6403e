#include "formats/aut_label.hpp"

#include <vector>

#include "support/text.hpp"

namespace oasis::formats {
namespace {

constexpr std::string_view kRewardOpen = "reward(";

// The parts of a multi-action: split at '|' outside parentheses, as mCRL2 does.
std::vector<std::string_view> split_parts(std::string_view label) {
  std::vector<std::string_view> parts;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < label.size(); ++i) {
    if (label[i] == '(') ++depth;
    if (label[i] == ')') --depth;
    if (label[i] == '|' && depth == 0) {
      parts.push_back(label.substr(start, i - start));
      start = i + 1;
    }
  }
  parts.push_back(label.substr(start));
  return parts;
}

bool is_reward_part(std::string_view part) {
  part = trim_blanks(part);
  return part.size() > kRewardOpen.size() && part.substr(0, kRewardOpen.size()) == kRewardOpen &&
         part.back() == ')';
}

std::string join(const std::vector<std::string_view>& parts) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) text += '|';
    text += parts[i];
  }
  return text;
}

}  // namespace

std::string format_aut_label(std::string_view action, const Rational& reward) {
  if (sgn(reward) == 0) return std::string(action);
  const std::string reward_part = std::string(kRewardOpen) + to_string(reward) + ")";
  // Insert where mCRL2's sort would put it, leaving the action's own parts in their order,
  // so that reading the label back gives exactly `action`.
  std::vector<std::string_view> parts = split_parts(action);
  std::size_t position = 0;
  while (position < parts.size() && parts[position] < reward_part)
    ++position;
  parts.insert(parts.begin() + static_cast<std::ptrdiff_t>(position), reward_part);
  return join(parts);
}

std::optional<std::string> aut_action_problem(std::string_view action) {
  const std::string quoted = "action name '" + std::string(action) + "'";
  if (action.empty()) return std::string("an action name is empty");
  if (action.find_first_of("\"\n\r") != std::string_view::npos) {
    return quoted + " contains a quote or a line break";
  }
  int depth = 0;
  for (char c : action) {
    depth += c == '(' ? 1 : (c == ')' ? -1 : 0);
    if (depth < 0) break;
  }
  if (depth != 0) return quoted + " has unbalanced parentheses";
  for (std::string_view part : split_parts(action)) {
    if (trim_blanks(part).empty()) return quoted + " has an empty multi-action part";
    if (is_reward_part(part))
      return quoted + " has a part 'reward(...)' that would read as a reward";
  }
  return std::nullopt;
}

std::optional<AutLabel> parse_aut_label(std::string_view label, std::string& error) {
  if (label.find(kRewardOpen) == std::string_view::npos) {
    return AutLabel{std::string(label), Rational(0)};  // the common case: no reward
  }
  std::vector<std::string_view> parts = split_parts(label);
  std::vector<std::string_view> action_parts;
  std::optional<std::string_view> reward_text;
  for (std::string_view part : parts) {
    if (!is_reward_part(part)) {
      action_parts.push_back(trim_blanks(part));
      continue;
    }
    if (reward_text) {
      error = "label '" + std::string(label) + "' has two reward parts";
      return std::nullopt;
    }
    part = trim_blanks(part);
    reward_text = part.substr(kRewardOpen.size(), part.size() - kRewardOpen.size() - 1);
  }
  if (!reward_text) return AutLabel{std::string(label), Rational(0)};  // e.g. "myreward(1)"
  const std::optional<Rational> reward = parse_rational(trim_blanks(*reward_text));
  if (!reward) {
    error = "reward '" + std::string(*reward_text) + "' in label '" + std::string(label) +
            "' is not a number";
    return std::nullopt;
  }
  if (action_parts.size() == 1 && action_parts[0].empty()) action_parts.clear();
  if (action_parts.empty()) {
    error = "label '" + std::string(label) + "' has a reward but no action";
    return std::nullopt;
  }
  return AutLabel{join(action_parts), *reward};
}

}  // namespace oasis::formats
