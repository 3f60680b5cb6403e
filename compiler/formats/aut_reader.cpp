#include "formats/aut_reader.hpp"

#include <algorithm>
#include <cstring>
#include <deque>
#include <filesystem>
#include <ostream>
#include <string>
#include <unordered_map>
#include <vector>

#include "formats/aut_label.hpp"
#include "formats/distribution_collector.hpp"
#include "formats/exact_sum.hpp"
#include "formats/model_size.hpp"
#include "formats/text_scanner.hpp"
#include "formats/value_cache.hpp"

namespace oasis::formats {
namespace {

using model::ActionIndex;
using model::StateIndex;

constexpr std::uint64_t kOutOfRange = UINT64_MAX;

struct LabelInfo {
  ActionIndex action = 0;
  ValueId reward = RationalPool::kZero;
};

// One target of a probabilistic state `t0 p1 t1 ... pn tn` as read, before range checks.
struct Target {
  std::uint64_t state = 0;
  ValueId probability = RationalPool::kOne;
  const char* position = nullptr;
  std::uint32_t length = 0;
};

std::string state_range_message(std::uint64_t state, std::string_view digits,
                                std::uint32_t num_states) {
  const std::string shown = state == kOutOfRange ? std::string(digits) : std::to_string(state);
  return "state " + shown + " is out of range: the header declares " + std::to_string(num_states) +
         (num_states == 1 ? " state" : " states");
}

// What a second, quiet reading of the body looks for: the offsets of the labels of some
// collected distributions (the first reading keeps no offsets: 8 bytes a line, needed only to
// point at a duplicate). The second reading checks every line as the first did, so it collects
// the same lines in the same order and can count them.
struct Locating {
  std::vector<std::uint32_t> wanted;  // distribution indices, ascending
  std::unordered_map<std::uint32_t, SourceOffset> found;
  std::uint32_t collected = 0;
};

// Which part of the body a distributed reader reads, and where its lines go.
struct PartReading {
  std::uint32_t index = 0;
  std::uint32_t count = 1;
  const AutLineSink* sink = nullptr;
};

class AutReader {
 public:
  AutReader(FileId file, DiagnosticEngine& diagnostics, const ReadOptions& options,
            std::optional<PartReading> part = std::nullopt)
      : part_(part),
        file_(file),
        source_(diagnostics.sources().file(file)),
        diagnostics_(diagnostics),
        options_(options),
        scan_(source_.text()),
        cache_(model_.values, options.max_number_bits),
        errors_before_(diagnostics.error_count()) {}

  std::optional<model::ExplicitModel> read() {
    if (!read_header()) return std::nullopt;
    read_transitions();
    source_.release_pages_before(scan_.offset());
    check_transition_count();
    if (diagnostics_.should_stop() || !assemble_model()) return std::nullopt;
    if (diagnostics_.error_count() != errors_before_) return std::nullopt;
    return std::move(model_);
  }

  // The second reading (Locating): `diagnostics_` is a quiet engine without an error limit.
  std::unordered_map<std::uint32_t, SourceOffset> locate(std::vector<std::uint32_t> wanted) {
    locating_.emplace();
    std::sort(wanted.begin(), wanted.end());
    locating_->wanted = std::move(wanted);
    if (read_header()) read_transitions();
    return std::move(locating_->found);
  }

  std::optional<AutPart> read_part(bool& header_read) {
    header_read = read_header();
    if (!header_read) return std::nullopt;
    seek_to_part();
    read_transitions();
    if (diagnostics_.error_count() != errors_before_) return std::nullopt;
    AutPart part;
    part.num_states = num_states_;
    part.initial = model_.states.initial;
    part.declared_transitions = declared_transitions_;
    part.declared_transitions_offset = scan_.offset_of(transitions_token_);
    part.lines = transitions_seen_;
    part.actions = std::move(model_.actions);
    part.action_offsets = std::move(action_offsets_);
    part.values = std::move(model_.values);
    return part;
  }

 private:
  // --- diagnostics ---------------------------------------------------------------------
  [[nodiscard]] SourceRange range_at(const char* position, std::size_t length) const {
    return SourceRange{{file_, scan_.offset_of(position)},
                       static_cast<std::uint32_t>(std::max<std::size_t>(length, 1))};
  }
  void error_at(const char* position, std::size_t length, const std::string& message) {
    diagnostics_.error(range_at(position, length), message);
  }
  void error_here(const std::string& message) { error_at(scan_.position(), 1, message); }

  // --- header: des (INIT, NUM_TRANSITIONS, NUM_STATES) ---------------------------------
  bool read_header() {
    scan_.skip_blank_lines();
    scan_.skip_blanks();
    header_ = scan_.position();
    if (scan_.rest_of_line().substr(0, 3) != "des") {
      error_here("expected the header 'des (initial, transitions, states)'");
      return false;
    }
    scan_.seek(scan_.position() + 3);
    scan_.skip_blanks();
    if (!expect('(', "expected '(' after 'des'")) return false;
    scan_.skip_blanks();
    if (!read_targets()) return false;
    std::vector<Target> initial = targets_;
    scan_.skip_blanks();
    if (!expect(',', "expected ',' after the initial state")) return false;
    scan_.skip_blanks();
    transitions_token_ = scan_.position();
    const Natural transitions = scan_.read_natural();
    if (transitions.empty() || transitions.overflow) {
      error_here("expected the number of transitions");
      return false;
    }
    declared_transitions_ = transitions.value;
    scan_.skip_blanks();
    if (!expect(',', "expected ',' after the number of transitions")) return false;
    scan_.skip_blanks();
    if (!read_state_count()) return false;
    if (!fits_memory_budget()) return false;
    scan_.skip_blanks();
    if (!expect(')', "expected ')' to close the header")) return false;
    scan_.skip_blanks();
    if (!scan_.at_line_end()) {
      error_here("unexpected text after the header");
      return false;
    }
    scan_.skip_line();
    return set_initial_states(initial);
  }

  bool read_state_count() {
    const char* token = scan_.position();
    const Natural states = scan_.read_natural();
    if (states.empty()) {
      error_here("expected the number of states");
      return false;
    }
    const std::optional<std::string> refusal =
        state_count_refusal(states.text, states.overflow ? UINT64_MAX : states.value, options_);
    if (refusal) {
      error_at(token, states.text.size(), "the header declares " + *refusal);
      return false;
    }
    if (states.value == 0) {
      error_at(token, states.text.size(),
               "the header declares no states; at least the initial state is needed");
      return false;
    }
    num_states_ = static_cast<std::uint32_t>(states.value);
    return true;
  }

  // A header declaring more than reading it could fit is refused here, before any line of
  // the body is read or anything is reserved for it (on each rank: its share).
  bool fits_memory_budget() {
    const DeclaredSize size{.states = num_states_, .choices = declared_transitions_};
    const std::optional<std::uint32_t> ranks =
        part_ ? std::optional<std::uint32_t>(part_->count) : std::nullopt;
    const std::optional<std::string> refusal = memory_refusal(size, options_, ranks);
    if (!refusal) return true;
    const std::string transitions = std::to_string(declared_transitions_);
    error_at(transitions_token_, transitions.size(),
             "the header declares " + transitions + " transitions and " +
                 std::to_string(num_states_) + " states: " + *refusal);
    return false;
  }

  // The initial state may be a distribution; our models have a set of initial states, so
  // its support becomes that set (with a warning, since the probabilities are dropped).
  bool set_initial_states(const std::vector<Target>& initial) {
    bool ok = true;
    for (const Target& target : initial) {
      if (target.state >= num_states_) {
        error_at(target.position, target.length,
                 state_range_message(target.state, {target.position, target.length}, num_states_));
        ok = false;
        continue;
      }
      model_.states.initial.push_back(static_cast<StateIndex>(target.state));
    }
    std::vector<StateIndex>& states = model_.states.initial;
    std::sort(states.begin(), states.end());
    states.erase(std::unique(states.begin(), states.end()), states.end());
    if (ok && initial.size() > 1) {
      diagnostics_.warning(SourceRange{{file_, scan_.offset_of(initial.front().position)}, 1},
                           "the initial state is a distribution; only its support is kept, as " +
                               std::to_string(states.size()) + " initial states");
    }
    return ok;
  }

  // --- parts of the body, for a distributed reader --------------------------------------
  // Byte `part * size / count` of the body, computed without overflowing 64 bits.
  [[nodiscard]] static std::uint64_t part_boundary(std::uint64_t size, std::uint32_t part,
                                                   std::uint32_t count) {
    return size / count * part + size % count * part / count;
  }

  // The first line start at or after `position` (lines start after a newline).
  [[nodiscard]] const char* line_start_at_or_after(const char* position, const char* body) const {
    if (position == body || position[-1] == '\n') return position;
    const void* newline =
        std::memchr(position, '\n', static_cast<std::size_t>(scan_.end() - position));
    return newline ? static_cast<const char*>(newline) + 1 : scan_.end();
  }

  void seek_to_part() {
    const char* body = scan_.position();
    const auto size = static_cast<std::uint64_t>(scan_.end() - body);
    const auto at = [&](std::uint32_t part) {
      return line_start_at_or_after(body + part_boundary(size, part, part_->count), body);
    };
    part_end_ = at(part_->index + 1);
    scan_.seek(at(part_->index));
  }

  // --- transitions: (FROM, LABEL, TARGETS) ---------------------------------------------
  void read_transitions() {
    if (!part_ && !locating_) {
      const std::size_t expected =
          std::min<std::uint64_t>(declared_transitions_, source_.text().size() / 8);
      collector_.reserve(expected, std::min<std::size_t>(expected, kSampleTransitions * 16));
    }
    for (;;) {
      scan_.skip_blank_lines();
      if (part_ && scan_.position() >= part_end_) return;  // the next part's line
      scan_.skip_blanks();
      if (scan_.at_end() || scan_.peek() == '\x04') return;  // EOT ends the file, as in mCRL2
      ++transitions_seen_;
      read_transition();  // reports its own errors; the next line is read either way
      scan_.skip_line();
      if (!part_ && !locating_ && transitions_seen_ == kSampleTransitions)
        reserve_edges_for_the_rest();
      if (diagnostics_.should_stop()) return;
      release_read_pages();
      if (collector_.full()) {
        error_here("the file has more than 2^32 edges");
        return;
      }
    }
  }

  // The header gives the number of distributions but not of edges. Growing the edge arrays
  // by doubling would, at the last doubling, hold the old and the new array at once: the
  // reader's peak. So once the first lines have shown how many bytes an edge takes, the
  // arrays are reserved for the rest of the file at that rate, with a margin; capacity never
  // touched costs address space, not memory.
  void reserve_edges_for_the_rest() {
    const std::size_t edges = collector_.num_edges();
    if (edges == 0) return;
    const double bytes_per_edge =
        static_cast<double>(scan_.offset_of(scan_.position()) - scan_.offset_of(header_)) /
        static_cast<double>(edges);
    const auto rest = static_cast<double>(scan_.end() - scan_.position());
    const auto expected = static_cast<std::size_t>(rest / bytes_per_edge * 1.05) + edges;
    collector_.reserve_edges(std::min<std::size_t>(expected, UINT32_MAX));
  }

  // The file is read once, front to back: what is behind the scanner need not stay resident
  // (a 10^7-transition file is 470 MB, more than the model it describes). Diagnostics about
  // earlier lines still read it, from the page cache.
  void release_read_pages() {
    const std::size_t offset = scan_.offset();
    if (offset - released_ < kReleaseStep) return;
    source_.release_pages_before(offset);
    released_ = offset;
  }

  bool read_transition() {
    if (!expect('(', "expected '(' to start a transition")) return false;
    scan_.skip_blanks();
    const char* source_token = scan_.position();
    const Natural source = scan_.read_natural();
    if (source.empty()) {
      error_here("expected the source state");
      return false;
    }
    if (source.overflow || source.value >= num_states_) {
      error_at(source_token, source.text.size(),
               state_range_message(source.overflow ? kOutOfRange : source.value, source.text,
                                   num_states_));
      return false;
    }
    scan_.skip_blanks();
    if (!expect(',', "expected ',' after the source state")) return false;
    scan_.skip_blanks();
    const char* label_token = scan_.position();
    const std::optional<LabelInfo> label = read_label();
    if (!label) return false;
    scan_.skip_blanks();
    if (!read_targets()) return false;
    scan_.skip_blanks();
    if (!expect(')', "expected ')' to close the transition")) return false;
    scan_.skip_blanks();
    if (!scan_.at_line_end()) {
      error_here("unexpected text after the transition");
      return false;
    }
    for (const Target& target : targets_) {
      if (target.state >= num_states_) {
        error_at(target.position, target.length,
                 state_range_message(target.state, {target.position, target.length}, num_states_));
        return false;
      }
    }
    // Only a fully checked line reaches the collector, so errors never leave half a
    // distribution behind.
    if (part_) {
      hand_over(static_cast<StateIndex>(source.value), *label, scan_.offset_of(label_token));
      return true;
    }
    if (locating_) {
      note_location(scan_.offset_of(label_token));
      return true;
    }
    collector_.begin(static_cast<StateIndex>(source.value), label->action,
                     scan_.offset_of(label_token), label->reward);
    for (const Target& target : targets_) {
      collector_.add(static_cast<StateIndex>(target.state), target.probability);
    }
    return true;
  }

  void note_location(SourceOffset offset) {
    const std::uint32_t d = locating_->collected++;
    if (std::binary_search(locating_->wanted.begin(), locating_->wanted.end(), d))
      locating_->found.emplace(d, offset);
  }

  void hand_over(StateIndex source, const LabelInfo& label, SourceOffset offset) {
    row_.clear();
    for (const Target& target : targets_)
      row_.emplace_back(static_cast<StateIndex>(target.state), target.probability);
    model::normalize_distribution(row_, model_.values);
    (*part_->sink)(AutLine{offset, source, label.action, label.reward, row_});
  }

  bool expect(char c, const char* message) {
    if (scan_.consume(c)) return true;
    error_here(message);
    return false;
  }

  // A quoted label keeps its spaces; an unquoted one runs to the next ',' with blanks
  // removed (both as mCRL2 reads them). The label is followed by its ','.
  std::optional<LabelInfo> read_label() {
    const char* start = scan_.position();
    std::string_view text;
    if (scan_.consume('"')) {
      const char* p = scan_.position();
      while (p < scan_.end() && *p != '"' && *p != '\n')
        ++p;
      if (p == scan_.end() || *p != '"') {
        error_at(start, 1, "unterminated label: expected '\"' before the end of the line");
        return std::nullopt;
      }
      text = std::string_view(scan_.position(), static_cast<std::size_t>(p - scan_.position()));
      scan_.seek(p + 1);
      scan_.skip_blanks();
    } else {
      const char* p = scan_.position();
      while (p < scan_.end() && *p != ',' && *p != '\n')
        ++p;
      text = std::string_view(start, static_cast<std::size_t>(p - start));
      scan_.seek(p);
      if (text.find_first_of(" \t\r") != std::string_view::npos) text = without_blanks(text);
    }
    if (!expect(',', "expected ',' after the label")) return std::nullopt;
    if (text.empty()) {
      error_at(start, 2, "empty label; mCRL2 does not accept it as an action");
      return std::nullopt;
    }
    return lookup_label(text, start);
  }

  std::string_view without_blanks(std::string_view text) {
    std::string& kept = owned_labels_.emplace_back();
    for (char c : text) {
      if (!TextScanner::is_blank(c) && c != '\r') kept += c;
    }
    return kept;
  }

  // Labels repeat on almost every line: the last one is checked first, then a table; only
  // a label never seen before is split into action and reward.
  std::optional<LabelInfo> lookup_label(std::string_view text, const char* position) {
    if (text == last_label_) return last_info_;
    auto found = labels_.find(text);
    if (found == labels_.end()) {
      std::string problem;
      const std::optional<AutLabel> parsed = parse_aut_label(text, problem);
      if (!parsed) {
        error_at(position, text.size() + 2, problem);
        return std::nullopt;
      }
      LabelInfo info{action_index(parsed->action, scan_.offset_of(position)),
                     cache_.intern(parsed->reward)};
      if (!cache_.check_carried(info.reward, "reward", range_at(position, text.size() + 2),
                                diagnostics_)) {
        return std::nullopt;
      }
      if (info.reward != RationalPool::kZero) any_reward_ = true;
      found = labels_.emplace(text, info).first;
    }
    last_label_ = text;
    last_info_ = found->second;
    return last_info_;
  }

  ActionIndex action_index(const std::string& name, SourceOffset offset) {
    const auto [it, inserted] =
        action_indices_.try_emplace(name, static_cast<ActionIndex>(model_.actions.size()));
    if (inserted) {
      model_.actions.push_back(name);
      action_offsets_.push_back(offset);
    }
    return it->second;
  }

  // `t0 n1/d1 t1 ... nk/dk tk`: each fraction is the probability of the target before it;
  // the last target gets what remains. Leaves the targets in targets_.
  bool read_targets() {
    targets_.clear();
    sum_.reset();
    if (!read_target()) return false;
    for (;;) {
      scan_.skip_blanks();
      if (!TextScanner::is_digit(scan_.peek())) break;
      const char* fraction = scan_.position();
      const std::optional<ValueId> probability = read_probability();
      if (!probability) return false;
      targets_.back().probability = *probability;
      sum_.add(*probability, cache_);
      if (sum_.compare_to_one() >= 0) {
        error_at(fraction, static_cast<std::size_t>(scan_.position() - fraction),
                 sum_.compare_to_one() == 0
                     ? std::string(
                           "probabilities reach 1 before the last target, which would get nothing")
                     : "probabilities before the last target sum to " + describe(sum_.value()) +
                           ", more than 1");
        return false;
      }
      scan_.skip_blanks();
      if (!read_target()) return false;
    }
    targets_.back().probability =
        targets_.size() == 1 ? RationalPool::kOne : sum_.interned_remainder(cache_);
    return true;
  }

  bool read_target() {
    const char* token = scan_.position();
    const Natural state = scan_.read_natural();
    if (state.empty()) {
      error_here("expected a state number");
      return false;
    }
    targets_.push_back(Target{state.overflow ? kOutOfRange : state.value, RationalPool::kOne, token,
                              static_cast<std::uint32_t>(state.text.size())});
    return true;
  }

  std::optional<ValueId> read_probability() {
    const char* start = scan_.position();
    const Natural numerator = scan_.read_natural();
    scan_.skip_blanks();
    if (!scan_.consume('/')) {
      error_here("expected '/' in the probability: .aut probabilities are fractions like 1/2");
      return std::nullopt;
    }
    scan_.skip_blanks();
    const Natural denominator = scan_.read_natural();
    if (denominator.empty()) {
      error_here("expected the denominator of the probability");
      return std::nullopt;
    }
    const std::size_t length = static_cast<std::size_t>(scan_.position() - start);
    std::optional<ValueId> id;
    if (!numerator.overflow && !denominator.overflow) {
      if (denominator.value != 0) id = cache_.intern_fraction(numerator.value, denominator.value);
    } else {
      id = cache_.intern_text(std::string(numerator.text) + "/" + std::string(denominator.text));
    }
    if (!id) {
      error_at(start, length, "probability has a zero denominator");
      return std::nullopt;
    }
    if (*id == RationalPool::kZero) {
      error_at(start, length, "probability must be positive");
      return std::nullopt;
    }
    if (!cache_.check_carried(*id, "probability", range_at(start, length), diagnostics_))
      return std::nullopt;
    return id;
  }

  // --- the whole file ------------------------------------------------------------------
  void check_transition_count() {
    if (diagnostics_.should_stop() || transitions_seen_ == declared_transitions_) return;
    error_at(transitions_token_, std::to_string(declared_transitions_).size(),
             "the header declares " + std::to_string(declared_transitions_) +
                 " transitions but the file has " + std::to_string(transitions_seen_));
  }

  bool assemble_model() {
    const std::uint32_t k = static_cast<std::uint32_t>(model_.actions.size());
    if (std::uint64_t{num_states_} * k >= UINT32_MAX) {
      error_at(header_, 3,
               std::to_string(num_states_) + " states and " + std::to_string(k) +
                   " actions make more than 2^32 state-action pairs");
      return false;
    }
    std::vector<DistributionCollector::Duplicate> duplicates;
    std::optional<model::TransitionMatrix> matrix =
        collector_.finish(num_states_, k, model_.values, duplicates);
    report_duplicates(duplicates);
    if (!matrix) return false;
    model_.name = std::filesystem::path(source_.path()).stem().string();
    model_.states.size = num_states_;
    model::Context context;
    context.name = "default";
    context.rewards.state.assign(num_states_, RationalPool::kZero);
    if (any_reward_) {
      context.rewards.choice.assign(std::size_t{num_states_} * k, RationalPool::kZero);
      for (std::uint32_t d = 0; d < collector_.size(); ++d) {
        context.rewards.choice[std::size_t{collector_.source(d)} * k + collector_.action(d)] =
            collector_.payload(d);
      }
    }
    collector_.release();
    context.transitions = std::make_shared<const model::TransitionMatrix>(std::move(*matrix));
    model_.contexts.push_back(std::move(context));
    return true;
  }

  // Reported up to the error limit. Where they are is found by reading the file again, a
  // chunk of duplicates per reading: one reading under the default limit.
  void report_duplicates(const std::vector<DistributionCollector::Duplicate>& duplicates) {
    constexpr std::size_t kChunk = 256;
    for (std::size_t begin = 0; begin < duplicates.size(); begin += kChunk) {
      if (diagnostics_.should_stop()) return;
      const std::size_t end = std::min(duplicates.size(), begin + kChunk);
      std::vector<std::uint32_t> wanted;
      for (std::size_t i = begin; i < end; ++i) {
        wanted.push_back(duplicates[i].first);
        wanted.push_back(duplicates[i].second);
      }
      std::ostream discarded(nullptr);
      DiagnosticEngine quiet(diagnostics_.sources(), discarded, SIZE_MAX);
      const std::unordered_map<std::uint32_t, SourceOffset> offsets =
          AutReader(file_, quiet, options_).locate(std::move(wanted));
      for (std::size_t i = begin; i < end; ++i) {
        if (diagnostics_.should_stop()) return;
        report_duplicate(duplicates[i], offsets);
      }
    }
  }

  void report_duplicate(const DistributionCollector::Duplicate& duplicate,
                        const std::unordered_map<std::uint32_t, SourceOffset>& offsets) {
    const StateIndex state = collector_.source(duplicate.first);
    const std::string& action = model_.actions[collector_.action(duplicate.first)];
    const SourceLocation first{file_, offsets.at(duplicate.first)};
    const SourceLocation second{file_, offsets.at(duplicate.second)};
    diagnostics_.error(
        second, "state " + std::to_string(state) + " already has a distribution for action '" +
                    action + "' (line " + std::to_string(source_.line_column(first.offset).line) +
                    "); an MDP allows one per action");
    diagnostics_.note(first, "the first distribution of state " + std::to_string(state) +
                                 " for action '" + action + "' is here");
  }

  std::optional<PartReading> part_;
  std::optional<Locating> locating_;
  const char* part_end_ = nullptr;
  std::vector<std::pair<StateIndex, ValueId>> row_;  // the line handed to a part's sink
  FileId file_;
  const SourceFile& source_;
  DiagnosticEngine& diagnostics_;
  const ReadOptions& options_;
  TextScanner scan_;
  model::ExplicitModel model_;
  ValueCache cache_;
  ExactSum sum_;
  DistributionCollector collector_{DistributionCollector::Kept::Payloads};
  std::vector<Target> targets_;
  std::size_t errors_before_;

  const char* header_ = nullptr;
  const char* transitions_token_ = nullptr;
  std::uint64_t declared_transitions_ = 0;
  std::uint32_t num_states_ = 0;
  std::uint64_t transitions_seen_ = 0;
  static constexpr std::uint64_t kSampleTransitions = 4096;
  static constexpr std::size_t kReleaseStep = std::size_t{16} << 20;
  std::size_t released_ = 0;  // bytes of the file handed back by release_read_pages()

  std::unordered_map<std::string_view, LabelInfo> labels_;  // keys view the file or owned_labels_
  std::deque<std::string> owned_labels_;
  std::unordered_map<std::string, ActionIndex> action_indices_;
  std::vector<SourceOffset> action_offsets_;  // where each action first appears
  std::string_view last_label_;
  LabelInfo last_info_;
  bool any_reward_ = false;
};

}  // namespace

std::optional<model::ExplicitModel> read_aut(FileId file, DiagnosticEngine& diagnostics,
                                             const ReadOptions& options) {
  return AutReader(file, diagnostics, options).read();
}

std::optional<AutPart> read_aut_part(FileId file, DiagnosticEngine& diagnostics,
                                     const ReadOptions& options, std::uint32_t index,
                                     std::uint32_t count, const AutLineSink& sink,
                                     bool& header_read) {
  return AutReader(file, diagnostics, options, PartReading{index, count, &sink})
      .read_part(header_read);
}

}  // namespace oasis::formats
