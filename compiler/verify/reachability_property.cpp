#include "verify/reachability_property.hpp"

#include <algorithm>
#include <cctype>

#include "support/limits.hpp"
#include "support/text.hpp"

namespace oasis::verify {
namespace {

constexpr std::string_view kWhatVerifyReads =
    "verify checks schedulers of Pmax=? [F T], Pmin=? [F T], Pmax=? [phi U T] and Pmin=? [phi "
    "U T], T and phi made of quoted labels, true, false, !, &, | and parentheses; 'oasisc query' "
    "answers other properties";

// A state formula in postfix: evaluated per state with a small stack.
struct Op {
  enum class Kind { kLabel, kTrue, kFalse, kNot, kAnd, kOr } kind;
  std::uint32_t label = 0;
};

struct Token {
  enum class Kind { kWord, kLabel, kSymbol, kEnd } kind;
  std::string_view text;  // a label without its quotes
  std::size_t at = 0;     // byte offset in the property
};

struct ReadError {
  std::string message;
};

class Reader {
 public:
  Reader(std::string_view text, const model::ExplicitModel& model) : text_(text), model_(model) {
    next();
  }

  ReachabilityProperty read() {
    ReachabilityProperty property;
    if (!is_word("Pmax") && !is_word("Pmin")) fail("expected Pmax or Pmin");
    property.maximise = token_.text == "Pmax";
    next();
    expect_symbol("=?");
    expect_symbol("[");
    std::vector<Op> until{{Op::Kind::kTrue}};
    std::vector<Op> target;
    if (is_word("F")) {
      next();
      target = formula();
    } else {
      until = formula();
      if (!is_word("U")) fail("expected F at the start or U after the first formula");
      next();
      target = formula();
    }
    expect_symbol("]");
    if (token_.kind != Token::Kind::kEnd) fail("expected the end of the property");
    property.until = evaluate(until);
    property.target = evaluate(target);
    return property;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError{what + " at character " + std::to_string(token_.at + 1) + " of the property"};
  }

  bool is_word(std::string_view word) const {
    return token_.kind == Token::Kind::kWord && token_.text == word;
  }
  bool is_symbol(std::string_view symbol) const {
    return token_.kind == Token::Kind::kSymbol && token_.text == symbol;
  }
  void expect_symbol(std::string_view symbol) {
    if (!is_symbol(symbol)) fail("expected '" + std::string(symbol) + "'");
    next();
  }

  void next() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n'))
      ++at_;
    token_ = {Token::Kind::kEnd, {}, at_};
    if (at_ == text_.size()) return;
    const char c = text_[at_];
    const auto word_char = [](char x) {
      return std::isalnum(static_cast<unsigned char>(x)) != 0 || x == '_';
    };
    if (word_char(c)) {
      std::size_t end = at_;
      while (end < text_.size() && word_char(text_[end]))
        ++end;
      token_ = {Token::Kind::kWord, text_.substr(at_, end - at_), at_};
      at_ = end;
    } else if (c == '"') {
      const std::size_t close = text_.find('"', at_ + 1);
      if (close == std::string_view::npos) fail("a label's closing quote is missing");
      token_ = {Token::Kind::kLabel, text_.substr(at_ + 1, close - at_ - 1), at_};
      at_ = close + 1;
    } else if (text_.substr(at_, 2) == "=?") {
      token_ = {Token::Kind::kSymbol, text_.substr(at_, 2), at_};
      at_ += 2;
    } else if (std::string_view("[]()!&|").find(c) != std::string_view::npos) {
      token_ = {Token::Kind::kSymbol, text_.substr(at_, 1), at_};
      ++at_;
    } else {
      fail("unexpected " + quoted(text_.substr(at_, 1)));
    }
  }

  // formula := conjunction ('|' conjunction)*; conjunction := unary ('&' unary)*;
  // unary := '!'* atom; atom := "label" | true | false | '(' formula ')'.
  std::vector<Op> formula() {
    std::vector<Op> ops;
    disjunction(ops, 0);
    return ops;
  }
  void disjunction(std::vector<Op>& ops, int depth) {
    conjunction(ops, depth);
    while (is_symbol("|")) {
      next();
      conjunction(ops, depth);
      ops.push_back({Op::Kind::kOr});
    }
  }
  void conjunction(std::vector<Op>& ops, int depth) {
    unary(ops, depth);
    while (is_symbol("&")) {
      next();
      unary(ops, depth);
      ops.push_back({Op::Kind::kAnd});
    }
  }
  void unary(std::vector<Op>& ops, int depth) {
    bool negated = false;
    for (; is_symbol("!"); next())
      negated = !negated;
    atom(ops, depth);
    if (negated) ops.push_back({Op::Kind::kNot});
  }
  void atom(std::vector<Op>& ops, int depth) {
    if (token_.kind == Token::Kind::kLabel) {
      const auto label = model_.labels.find(token_.text);
      if (!label) fail("the model has no label \"" + text::printable_excerpt(token_.text) + "\"");
      ops.push_back({Op::Kind::kLabel, *label});
    } else if (is_word("true") || is_word("false")) {
      ops.push_back({is_word("true") ? Op::Kind::kTrue : Op::Kind::kFalse});
    } else if (is_symbol("(")) {
      if (depth >= limits::kMaxNesting)
        fail("parentheses nested deeper than " + std::to_string(limits::kMaxNesting));
      next();
      disjunction(ops, depth + 1);
      if (!is_symbol(")")) fail("expected ')'");
    } else {
      fail("expected a quoted label, true, false, '!' or '('");
    }
    next();
  }

  std::vector<bool> evaluate(const std::vector<Op>& ops) const {
    const model::StateLabels& labels = model_.labels;
    std::vector<bool> result(model_.num_states());
    std::vector<bool> stack;
    for (model::StateIndex s = 0; s < model_.num_states(); ++s) {
      stack.clear();
      for (const Op& op : ops) {
        if (op.kind == Op::Kind::kLabel) {
          const auto held = labels.of(s);
          stack.push_back(std::binary_search(held.begin(), held.end(), op.label));
        } else if (op.kind == Op::Kind::kTrue || op.kind == Op::Kind::kFalse) {
          stack.push_back(op.kind == Op::Kind::kTrue);
        } else if (op.kind == Op::Kind::kNot) {
          stack.back() = !stack.back();
        } else {
          const bool right = stack.back();
          stack.pop_back();
          stack.back() =
              op.kind == Op::Kind::kAnd ? (stack.back() && right) : (stack.back() || right);
        }
      }
      result[s] = stack.back();
    }
    return result;
  }

  std::string_view text_;
  const model::ExplicitModel& model_;
  std::size_t at_ = 0;
  Token token_{Token::Kind::kEnd, {}, 0};
};

}  // namespace

std::optional<ReachabilityProperty> read_reachability_property(std::string_view text,
                                                               const model::ExplicitModel& model,
                                                               std::string& error) {
  if (text.size() > kMaxPropertyBytes) {
    error = "a property of " + std::to_string(text.size()) + " bytes, longer than the " +
            std::to_string(kMaxPropertyBytes) + " verify reads; " + std::string(kWhatVerifyReads);
    return std::nullopt;
  }
  try {
    return Reader(text, model).read();
  } catch (const ReadError& e) {
    error = e.message + "; " + std::string(kWhatVerifyReads);
    return std::nullopt;
  }
}

}  // namespace oasis::verify
