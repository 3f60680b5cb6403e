#include "distributed/distributed_reader.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>

#include "distributed/grouping.hpp"
#include "formats/aut_reader.hpp"
#include "support/diagnostics.hpp"
#include "support/error_report.hpp"
#include "support/mapped_file.hpp"
#include "support/source_manager.hpp"

namespace oasis::distributed {
namespace {

using model::StateIndex;

// A rank sends what it has read once this much is waiting: the reading's memory beyond the
// rank's share of the model is two such batches (one leaving, one arriving) per rank.
constexpr std::size_t kBatchBytes = std::size_t{16} << 20;

// The lines that reached their owner, in arrival order: a choice's edges follow the previous
// choice's. Action and value ids are the sender's until the tables are known; which sender a
// choice came from is kept per message, not per choice.
struct Arrivals {
  struct Message {
    std::uint32_t sender;
    std::uint32_t first_choice;
  };
  std::vector<Message> messages;
  std::vector<std::uint32_t> state;  // local
  std::vector<std::uint32_t> action;
  std::vector<ValueId> reward;
  std::vector<std::uint32_t> edge_begin;  // one more than choices once finished
  std::vector<StateIndex> edge_target;
  std::vector<ValueId> edge_probability;
  bool too_many_edges = false;

  void reserve(std::size_t choices, std::size_t edges) {
    state.reserve(choices);
    action.reserve(choices);
    reward.reserve(choices);
    edge_begin.reserve(choices + 1);
    edge_target.reserve(edges);
    edge_probability.reserve(edges);
  }

  void take(std::uint32_t from, const Bytes& bytes, const Ownership& ownership) {
    if (bytes.empty()) return;
    messages.push_back({from, static_cast<std::uint32_t>(state.size())});
    ByteReader reader(bytes);
    while (!reader.at_end()) {
      state.push_back(ownership.local(reader.get<StateIndex>()));
      action.push_back(reader.get<std::uint32_t>());
      reward.push_back(reader.get<ValueId>());
      const auto count = reader.get<std::uint32_t>();
      if (edge_target.size() + count >= UINT32_MAX) too_many_edges = true;
      edge_begin.push_back(static_cast<std::uint32_t>(edge_target.size()));
      for (std::uint32_t i = 0; i < count; ++i) {
        edge_target.push_back(reader.get<StateIndex>());
        edge_probability.push_back(reader.get<ValueId>());
      }
    }
  }

  void finish() { edge_begin.push_back(static_cast<std::uint32_t>(edge_target.size())); }
};

// Sends lines to their owners in batches. Every flush is collective: a rank whose part is
// read keeps flushing (with nothing to send) until every rank's part is read.
class LineSender {
 public:
  LineSender(const Communicator& communicator, Arrivals& arrivals, const Ownership& ownership)
      : communicator_(communicator),
        arrivals_(arrivals),
        ownership_(ownership),
        outgoing_(communicator.size()) {}

  // The file's size, for reserve_arrivals() and the progress.
  void set_file_bytes(std::size_t bytes) { file_bytes_ = bytes; }
  void set_progress(const ReadProgress& progress) { progress_ = progress; }

  void send(const formats::AutLine& line) {
    if (lines_ == 0) first_offset_ = line.offset;
    edges_ += line.row.size();
    if (++lines_ == kSampleLines) reserve_arrivals(line.offset);
    if (progress_ && lines_ % kProgressLines == 0) {
      const std::uint64_t part = file_bytes_ / communicator_.size();
      progress_(std::min<std::uint64_t>(line.offset - first_offset_, part), part);
    }
    Bytes& bytes = outgoing_[ownership_.owner(line.source)];
    const std::size_t before = bytes.size();
    ByteWriter writer(bytes);
    writer.put(line.source);
    writer.put(line.action);
    writer.put(line.reward);
    writer.put(static_cast<std::uint32_t>(line.row.size()));
    for (const auto& [target, probability] : line.row) {
      writer.put(target);
      writer.put(probability);
    }
    waiting_ += bytes.size() - before;
    if (waiting_ >= kBatchBytes) flush(false);
  }

  // Returns whether every rank has finished reading.
  bool flush(bool finished) {
    waiting_ = 0;
    const std::vector<Bytes> incoming = communicator_.exchange(outgoing_);
    outgoing_.assign(communicator_.size(), Bytes());
    for (std::uint32_t q = 0; q < incoming.size(); ++q)
      arrivals_.take(q, incoming[q], ownership_);
    return !communicator_.any(!finished);
  }

 private:
  // Growing the arrival arrays by doubling would make their last doubling the reading's peak
  // (old and new array at once, and up to twice the room needed). Once the part's first
  // lines show the bytes per line and edges per line, every rank expects about
  // (file bytes / bytes per line) / P lines, the states being spread evenly over the ranks.
  void reserve_arrivals(SourceOffset offset) {
    if (offset <= first_offset_) return;
    const double bytes_per_line =
        static_cast<double>(offset - first_offset_) / static_cast<double>(lines_ - 1);
    const double lines =
        static_cast<double>(file_bytes_) / bytes_per_line / communicator_.size() * 1.05 + 1024;
    const double edges = lines * static_cast<double>(edges_) / static_cast<double>(lines_);
    if (edges >= UINT32_MAX) return;
    arrivals_.reserve(static_cast<std::size_t>(lines), static_cast<std::size_t>(edges));
  }

  static constexpr std::uint64_t kSampleLines = 4096;
  static constexpr std::uint64_t kProgressLines = std::uint64_t{1} << 20;
  ReadProgress progress_;
  const Communicator& communicator_;
  Arrivals& arrivals_;
  const Ownership& ownership_;
  std::vector<Bytes> outgoing_;
  std::size_t waiting_ = 0;
  std::size_t file_bytes_ = 0;
  std::uint64_t lines_ = 0;
  std::uint64_t edges_ = 0;
  SourceOffset first_offset_ = 0;
};

std::string serialize_tables(const formats::AutPart& part) {
  Bytes bytes;
  ByteWriter writer(bytes);
  writer.put(static_cast<std::uint32_t>(part.actions.size()));
  for (std::size_t a = 0; a < part.actions.size(); ++a) {
    writer.put_text(part.actions[a]);
    writer.put(part.action_offsets[a]);
  }
  writer.put(static_cast<std::uint32_t>(part.values.size()));
  for (std::size_t id = 0; id < part.values.size(); ++id)
    writer.put_text(to_string(part.values[static_cast<ValueId>(id)]));
  return {bytes.begin(), bytes.end()};
}

// The global action list and value pool from every rank's tables, and per rank the map
// from its ids to the global ones; identical on every rank. Actions are numbered in order of
// first appearance in the file, as read_aut numbers them, so that a quotient written from
// them lists a state's lines in the sequential engine's order.
struct GlobalTables {
  std::vector<std::string> actions;
  RationalPool values;
  std::vector<std::vector<std::uint32_t>> action_of;  // [rank][rank's action id]
  std::vector<std::vector<ValueId>> value_of;         // [rank][rank's value id]
};

GlobalTables merge_tables(const std::vector<std::string>& tables) {
  GlobalTables global;
  global.action_of.resize(tables.size());
  global.value_of.resize(tables.size());
  std::vector<std::vector<std::string>> names(tables.size());
  std::map<std::string, SourceOffset> first_offset;
  for (std::size_t q = 0; q < tables.size(); ++q) {
    ByteReader reader(std::span<const char>(tables[q].data(), tables[q].size()));
    const auto num_actions = reader.get<std::uint32_t>();
    for (std::uint32_t a = 0; a < num_actions; ++a) {
      const std::string& name = names[q].emplace_back(reader.get_text());
      const auto offset = reader.get<SourceOffset>();
      const auto [it, inserted] = first_offset.try_emplace(name, offset);
      if (!inserted) it->second = std::min(it->second, offset);
    }
    const auto num_values = reader.get<std::uint32_t>();
    for (std::uint32_t v = 0; v < num_values; ++v) {
      // Written by to_string on a rank of this job: always parses.
      const std::optional<Rational> value = parse_rational(reader.get_text());
      global.value_of[q].push_back(global.values.intern(value.value_or(0)));
    }
  }
  std::map<SourceOffset, std::string> by_offset;
  for (const auto& [name, offset] : first_offset)
    by_offset.emplace(offset, name);
  std::map<std::string, std::uint32_t> index;
  for (const auto& [offset, name] : by_offset) {
    index.emplace(name, static_cast<std::uint32_t>(global.actions.size()));
    global.actions.push_back(name);
  }
  for (std::size_t q = 0; q < names.size(); ++q)
    for (const std::string& name : names[q])
      global.action_of[q].push_back(index.at(name));
  return global;
}

template <typename T>
void permute(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
  std::vector<T> permuted(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    permuted[i] = values[order[i]];
  values = std::move(permuted);
}

// Translates the arrivals' ids to the global tables and groups them by owned state, sorted
// by action. Returns the first (state, action) given twice, if any.
std::optional<std::pair<StateIndex, std::uint32_t>> assemble(Arrivals& arrivals,
                                                             const GlobalTables& tables,
                                                             OwnedModel& owned) {
  const auto num_choices = static_cast<std::uint32_t>(arrivals.state.size());
  for (std::size_t m = 0; m < arrivals.messages.size(); ++m) {
    const std::uint32_t q = arrivals.messages[m].sender;
    const std::uint32_t end =
        m + 1 < arrivals.messages.size() ? arrivals.messages[m + 1].first_choice : num_choices;
    for (std::uint32_t c = arrivals.messages[m].first_choice; c < end; ++c) {
      arrivals.action[c] = tables.action_of[q][arrivals.action[c]];
      arrivals.reward[c] = tables.value_of[q][arrivals.reward[c]];
      for (std::uint32_t e = arrivals.edge_begin[c]; e < arrivals.edge_begin[c + 1]; ++e)
        arrivals.edge_probability[e] = tables.value_of[q][arrivals.edge_probability[e]];
    }
  }
  arrivals.messages = {};
  // Grouped by state, then each state's few choices sorted by action.
  const std::uint32_t num_owned = owned.ownership.share(owned.num_states, owned.ownership.rank);
  Grouping by_state = group_by_key(arrivals.state, num_owned);
  arrivals.state = {};
  owned.state_choice_begin = std::move(by_state.begin);
  const std::vector<std::uint32_t>& begin = owned.state_choice_begin;
  std::vector<std::uint32_t>& order = by_state.order;
  std::optional<std::pair<StateIndex, std::uint32_t>> repeated;
  for (std::uint32_t i = 0; i < num_owned; ++i) {
    const auto first = order.begin() + begin[i];
    const auto last = order.begin() + begin[i + 1];
    std::sort(first, last, [&](std::uint32_t x, std::uint32_t y) {
      return arrivals.action[x] < arrivals.action[y];
    });
    const auto same = std::adjacent_find(first, last, [&](std::uint32_t x, std::uint32_t y) {
      return arrivals.action[x] == arrivals.action[y];
    });
    if (same != last && !repeated)
      repeated.emplace(owned.ownership.global(i, owned.ownership.rank), arrivals.action[*same]);
  }
  owned.edge_count.resize(num_choices);
  for (std::uint32_t i = 0; i < num_choices; ++i)
    owned.edge_count[i] = arrivals.edge_begin[order[i] + 1] - arrivals.edge_begin[order[i]];
  arrivals.edge_begin.pop_back();
  permute(arrivals.action, order);
  permute(arrivals.reward, order);
  permute(arrivals.edge_begin, order);
  owned.choice_action = std::move(arrivals.action);
  owned.choice_reward = std::move(arrivals.reward);
  owned.edge_begin = std::move(arrivals.edge_begin);
  owned.edge_target = std::move(arrivals.edge_target);
  owned.edge_probability = std::move(arrivals.edge_probability);
  return repeated;
}

// Reads this rank's part and sends its lines on. Returns the part, or nullopt after
// reporting errors (rank 0 reports the header's; the others only their part's).
std::optional<formats::AutPart> read_own_part(const std::string& path,
                                              const formats::ReadOptions& options,
                                              const Communicator& communicator, LineSender& sender,
                                              SourceManager& sources) {
  std::ostringstream buffered;
  DiagnosticEngine diagnostics(sources, communicator.is_root() ? std::cerr : buffered);
  MappedFile file;
  std::string error;
  const bool opened = file.open(path, options.max_bytes, error);
  // Usually every rank fails alike (no such file) and rank 0 says so once; a file that only
  // some ranks cannot open (not on their machine) is reported by each of them. 0: not opened,
  // else the size the rank sees plus one.
  const std::vector<std::uint64_t> opened_by =
      communicator.all_gather(opened ? file.text().size() + 1 : 0);
  if (!opened && (communicator.is_root() || opened_by[0] != 0)) {
    const std::string where = communicator.is_root()
                                  ? std::string()
                                  : " (rank " + std::to_string(communicator.rank()) + ")";
    diagnostics.file_error(path, error + where);
    std::cerr << buffered.str() << std::flush;
  }
  if (std::find(opened_by.begin(), opened_by.end(), 0) != opened_by.end()) return std::nullopt;
  // The parts are cut by the size each rank sees: they fit together only if all saw one size.
  if (std::adjacent_find(opened_by.begin(), opened_by.end(), std::not_equal_to<>()) !=
      opened_by.end()) {
    if (communicator.is_root())
      diagnostics.file_error(path, "the file changed size while being read");
    return std::nullopt;
  }
  sender.set_file_bytes(file.text().size());
  const FileId id = sources.add(path, std::move(file));
  bool header_read = false;
  std::optional<formats::AutPart> part = formats::read_aut_part(
      id, diagnostics, options, communicator.rank(), communicator.size(),
      [&](const formats::AutLine& line) { sender.send(line); }, header_read);
  if (header_read && !communicator.is_root()) std::cerr << buffered.str() << std::flush;
  return part;
}

}  // namespace

std::optional<OwnedModel> read_aut_distributed(const std::string& path,
                                               const formats::ReadOptions& options,
                                               const Communicator& communicator,
                                               const ReadProgress& progress) {
  OwnedModel owned;
  owned.ownership = Ownership{communicator.rank(), communicator.size()};
  owned.name = std::filesystem::path(path).stem().string();
  Arrivals arrivals;
  LineSender sender(communicator, arrivals, owned.ownership);
  sender.set_progress(progress);
  SourceManager sources;
  std::optional<formats::AutPart> part =
      read_own_part(path, options, communicator, sender, sources);
  while (!sender.flush(true)) {
  }
  arrivals.finish();
  if (communicator.any(!part.has_value() || arrivals.too_many_edges)) {
    if (arrivals.too_many_edges)
      report_error(path, "more than 2^32 edges start at the states of rank " +
                             std::to_string(communicator.rank()) + "; run with more ranks");
    return std::nullopt;
  }
  owned.num_states = part->num_states;
  owned.initial = part->initial;
  const std::uint64_t lines = communicator.sum(part->lines);
  if (lines != part->declared_transitions) {
    if (communicator.is_root()) {
      DiagnosticEngine diagnostics(sources, std::cerr);
      diagnostics.error(SourceRange{{FileId{0}, part->declared_transitions_offset},
                                    static_cast<std::uint32_t>(
                                        std::to_string(part->declared_transitions).size())},
                        "the header declares " + std::to_string(part->declared_transitions) +
                            " transitions but the file has " + std::to_string(lines));
    }
    return std::nullopt;
  }
  GlobalTables tables = merge_tables(communicator.all_gather(serialize_tables(*part)));
  part.reset();
  sources = SourceManager();
  const auto repeated = assemble(arrivals, tables, owned);
  if (repeated) {
    report_error(path, "state " + std::to_string(repeated->first) +
                           " has more than one distribution for action '" +
                           tables.actions[repeated->second] +
                           "'; an MDP allows one per action "
                           "('oasisc check " +
                           path + "' shows the lines)");
  }
  if (communicator.any(repeated.has_value())) return std::nullopt;
  owned.actions = std::move(tables.actions);
  owned.values = std::move(tables.values);
  owned.num_edges = communicator.sum(owned.edge_target.size());
  return owned;
}

}  // namespace oasis::distributed
