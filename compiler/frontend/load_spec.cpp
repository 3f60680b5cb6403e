#include "frontend/load_spec.hpp"

#include <algorithm>

#include "frontend/checker.hpp"
#include "frontend/lexer.hpp"
#include "frontend/parser.hpp"
#include "support/input_validation.hpp"

namespace oasis::frontend {

std::optional<model::ModelIR> check_spec_text(FileId file, DiagnosticEngine& diagnostics,
                                              const FrontendOptions& options) {
  const std::size_t errors_before = diagnostics.error_count();
  if (!validate_input(file, diagnostics)) return std::nullopt;
  const std::vector<Token> tokens = lex(file, diagnostics);
  const ast::SpecFile tree = parse(file, tokens, diagnostics);
  // Semantic errors on a tree with syntax errors are mostly echoes of them: stop here.
  if (diagnostics.error_count() != errors_before) return std::nullopt;
  return check(tree, diagnostics, options.max_number_bits);
}

std::optional<model::ModelIR> load_spec(const std::string& path, SourceManager& sources,
                                        DiagnosticEngine& diagnostics,
                                        const FrontendOptions& options) {
  MappedFile contents;
  std::string reason;
  // Source positions are 32-bit offsets, whatever the option says.
  if (!contents.open(path, options.max_bytes, reason)) {
    diagnostics.file_error(path, "cannot read spec: " + reason);
    return std::nullopt;
  }
  const FileId file = sources.add(path, std::move(contents));
  return check_spec_text(file, diagnostics, options);
}

}  // namespace oasis::frontend
