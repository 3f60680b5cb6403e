#pragma once
// Name tables of a spec. Values (constants, variables, states, regions) share one namespace;
// actions and contexts each have their own, so a state and an action may share a name.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

#include "model/expression.hpp"
#include "support/diagnostics.hpp"

namespace oasis::frontend {

enum class SymbolKind { Constant, Variable, ContinuousVariable, State, Region, Input };

struct Symbol {
  SymbolKind kind = SymbolKind::Constant;
  std::uint32_t index = 0;
  model::Type type = model::Type::Int;
  Rational value;  // constants only
  SourceRange declared;
  // A constant whose definition had an error (reported there): its uses are refused without
  // a message, so that one bad constant is one error, not one more per use.
  bool failed = false;
};

std::string_view describe(SymbolKind kind);

// Maps names to T, reporting a second declaration of a name as an error with a note that
// points at the first.
template <typename T>
class NameTable {
 public:
  struct Entry {
    T value;
    SourceRange declared;
  };

  // `what` names the kind of thing in the message: "state", "action", "context".
  bool declare(std::string_view name, SourceRange where, T value, std::string_view what,
               DiagnosticEngine& diagnostics) {
    auto [it, inserted] = entries_.try_emplace(std::string(name), Entry{std::move(value), where});
    if (!inserted) {
      diagnostics.error(where, "duplicate " + std::string(what) + " '" + std::string(name) + "'");
      diagnostics.note(it->second.declared, "'" + std::string(name) + "' was first declared here");
    }
    return inserted;
  }

  [[nodiscard]] const Entry* find(std::string_view name) const {
    auto it = entries_.find(std::string(name));
    return it == entries_.end() ? nullptr : &it->second;
  }
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

 private:
  std::unordered_map<std::string, Entry> entries_;
};

using Scope = NameTable<Symbol>;

}  // namespace oasis::frontend
