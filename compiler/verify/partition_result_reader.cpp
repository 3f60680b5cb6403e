#include "verify/partition_result_reader.hpp"

#include <limits>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "support/mapped_file.hpp"
#include "text/printable_text.hpp"

namespace oasis::verify {
namespace {

using nlohmann::json;

constexpr model::BlockIndex kUnassigned = std::numeric_limits<model::BlockIndex>::max();

// Thrown by the checks below and caught once in read_partition_result, so that each check
// is a line rather than a chain of early returns.
struct ResultError {
  std::string message;
};

class Reader {
 public:
  explicit Reader(const model::ExplicitModel& model) : model_(model) {
    for (model::StateIndex s = 0; s < model.num_states(); ++s)
      by_name_.emplace(model.states.name(s), s);
  }

  PartitionResult read(const json& document) {
    if (!document.is_object()) fail("the file is not a JSON object");
    if (!document.contains("contexts")) {
      fail(
          "no \"contexts\" key (expected the output of 'oasisc quotient --format json "
          "--partition')");
    }
    const json& contexts = document["contexts"];
    if (!contexts.is_array()) fail("\"contexts\" is not an array");
    if (contexts.empty()) fail("\"contexts\" is empty: nothing to verify");
    PartitionResult result;
    result.approximate = document.contains("exact") && document["exact"] == false;
    if (document.contains("respected_labels")) {
      if (!document["respected_labels"].is_string())
        fail("\"respected_labels\" is not a string (all, none, or label names)");
      result.respected_labels = document["respected_labels"].get<std::string>();
    }
    if (document.contains("choices")) {
      const json& choices = document["choices"];
      if (!choices.is_string() || (choices != "labelled" && choices != "unlabelled"))
        fail("\"choices\" is neither \"labelled\" nor \"unlabelled\"");
      result.unlabelled_choices = choices == "unlabelled";
    }
    std::vector<bool> seen(model_.contexts.size(), false);
    for (std::size_t i = 0; i < contexts.size(); ++i) {
      ContextPartition entry = read_context(contexts[i], i);
      if (seen[entry.context]) {
        fail("context '" + model_.contexts[entry.context].name + "' is listed twice");
      }
      seen[entry.context] = true;
      result.contexts.push_back(std::move(entry));
    }
    return result;
  }

 private:
  [[noreturn]] static void fail(std::string message) { throw ResultError{std::move(message)}; }

  ContextPartition read_context(const json& entry, std::size_t index) {
    const std::string where = "contexts[" + std::to_string(index) + "]";
    if (!entry.is_object()) fail(where + " is not an object");
    if (!entry.contains("name") || !entry["name"].is_string()) {
      fail(where + " has no \"name\" string");
    }
    const std::string name = entry["name"].get<std::string>();
    ContextPartition result;
    result.context = find_context(name);
    const std::string context = "context '" + text::printable_excerpt(name) + "'";
    if (!entry.contains("partition")) {
      fail(context + " has no \"partition\" (write it with 'oasisc quotient --partition')");
    }
    const json& blocks = entry["partition"];
    if (!blocks.is_array()) fail(context + ": \"partition\" is not an array of blocks");
    if (entry.contains("states") && entry["states"] != model_.num_states()) {
      fail(context + ": \"states\" is " + text::printable_excerpt(entry["states"].dump()) +
           " but the model has " + std::to_string(model_.num_states()) +
           " states (a different model?)");
    }
    if (entry.contains("blocks") && entry["blocks"] != blocks.size()) {
      fail(context + ": \"blocks\" is " + text::printable_excerpt(entry["blocks"].dump()) +
           " but \"partition\" lists " + std::to_string(blocks.size()) + " blocks");
    }

    model::Partition& partition = result.partition;
    partition.block_of.assign(model_.num_states(), kUnassigned);
    partition.num_blocks = static_cast<model::BlockIndex>(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const std::string block = context + ": block " + std::to_string(b);
      if (!blocks[b].is_array()) fail(block + " is not an array of states");
      if (blocks[b].empty()) fail(block + " is empty");
      for (const json& item : blocks[b]) {
        const model::StateIndex s = find_state(item, block);
        if (partition.block_of[s] != kUnassigned) {
          fail(context + ": state " + model_.states.name(s) + " is in block " +
               std::to_string(partition.block_of[s]) + " and in block " + std::to_string(b));
        }
        partition.block_of[s] = static_cast<model::BlockIndex>(b);
      }
    }
    for (model::StateIndex s = 0; s < model_.num_states(); ++s) {
      if (partition.block_of[s] == kUnassigned) {
        fail(context + ": state " + model_.states.name(s) + " is in no block");
      }
    }
    return result;
  }

  std::size_t find_context(const std::string& name) const {
    std::string names;
    for (std::size_t c = 0; c < model_.contexts.size(); ++c) {
      if (model_.contexts[c].name == name) return c;
      names += (c ? ", " : "") + model_.contexts[c].name;
    }
    fail("the model has no context '" + text::printable_excerpt(name) +
         "' (it has: " + text::printable_excerpt(names, text::kMaxMessageBytes / 2) + ")");
  }

  model::StateIndex find_state(const json& item, const std::string& block) const {
    if (item.is_string()) {
      const auto it = by_name_.find(item.get<std::string>());
      if (it == by_name_.end())
        fail(block + ": the model has no state " + text::printable_excerpt(item.dump()));
      return it->second;
    }
    if (item.is_number_unsigned()) {
      const auto index = item.get<std::uint64_t>();
      if (index >= model_.num_states()) {
        fail(block + ": state index " + std::to_string(index) + " is out of range (the model has " +
             std::to_string(model_.num_states()) + " states)");
      }
      return static_cast<model::StateIndex>(index);
    }
    fail(block + ": " + text::printable_excerpt(item.dump()) +
         " is neither a state name nor a state index");
  }

  const model::ExplicitModel& model_;
  std::unordered_map<std::string, model::StateIndex> by_name_;
};

}  // namespace

std::optional<PartitionResult> read_partition_result(const std::string& path,
                                                     const model::ExplicitModel& model,
                                                     std::size_t max_bytes, std::string& error) {
  MappedFile file;
  if (!file.open(path, max_bytes, error)) {
    error = "cannot read: " + error;
    return std::nullopt;
  }
  return parse_partition_result(file.text(), model, error);
}

std::optional<PartitionResult> parse_partition_result(std::string_view text,
                                                      const model::ExplicitModel& model,
                                                      std::string& error) {
  json document;
  try {
    document = json::parse(text.begin(), text.end());
  } catch (const json::exception& e) {
    // A syntax error (parse_error) or a number too large for a double (out_of_range.406).
    // nlohmann's message names the byte offset; drop its "[json.exception...]" prefix.
    const std::string what = e.what();
    const auto space = what.find("] ");
    error = "not valid JSON: " + (space == std::string::npos ? what : what.substr(space + 2));
    return std::nullopt;
  }
  try {
    return Reader(model).read(document);
  } catch (const ResultError& e) {
    error = e.message;
    return std::nullopt;
  }
}

}  // namespace oasis::verify
