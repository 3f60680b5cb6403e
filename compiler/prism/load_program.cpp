#include "prism/load_program.hpp"

#include <algorithm>
#include <filesystem>

#include "prism/checker.hpp"
#include "prism/lexer.hpp"
#include "prism/parser.hpp"
#include "support/input_validation.hpp"

namespace oasis::prism {

bool is_program_path(const std::string& path) {
  return path.ends_with(".pm") || path.ends_with(".nm") || path.ends_with(".prism");
}

std::optional<model::ExplicitModel> load_program_text(FileId file, const std::string& name,
                                                      DiagnosticEngine& diagnostics,
                                                      const LoadOptions& options) {
  const std::size_t errors_before = diagnostics.error_count();
  if (!validate_input(file, diagnostics)) return std::nullopt;
  const std::vector<Token> tokens = lex(file, diagnostics);
  const ast::Program tree = parse(tokens, diagnostics);
  // Semantic errors on a tree with syntax errors are mostly echoes of them: stop here.
  if (diagnostics.error_count() != errors_before) return std::nullopt;
  const CheckOptions check_options{
      options.constants,       options.spec_constants, options.imported_at.has_value(),
      options.max_number_bits, options.rewards,        options.reward_ranges};
  const auto program = check(tree, name, diagnostics, check_options);
  if (!program) return std::nullopt;
  if (options.names != nullptr) *options.names = program->names;
  return explore(*program, diagnostics, options.explore);
}

std::optional<model::ExplicitModel> load_program(const std::string& path, SourceManager& sources,
                                                 DiagnosticEngine& diagnostics,
                                                 const LoadOptions& options) {
  MappedFile contents;
  std::string reason;
  // Source positions are 32-bit offsets, whatever the option says.
  if (!contents.open(path, options.max_bytes, reason)) {
    if (options.imported_at)
      diagnostics.error(*options.imported_at, "cannot read the imported program: " + reason);
    else
      diagnostics.file_error(path, "cannot read PRISM program: " + reason);
    return std::nullopt;
  }
  const FileId file = sources.add(path, std::move(contents));
  return load_program_text(file, std::filesystem::path(path).stem().string(), diagnostics, options);
}

}  // namespace oasis::prism
