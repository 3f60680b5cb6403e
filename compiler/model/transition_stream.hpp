#pragma once
// Builds a TransitionMatrix from distributions given in increasing choice order, as an
// explorer finds them (state by state, each state's actions in order): the edges go straight
// into the CSR arrays. TransitionBuilder, which takes edges in any order, keeps three more
// arrays of every edge and sorts them by choice at the end; at 10^7 states those copies were
// most of exploration's memory and a large part of its time (page faults).
//
// The matrix is the one TransitionBuilder gives for the same edges: each distribution is
// sorted by target, stably, and repeated targets merged by adding their probabilities. A
// merged probability is interned in finish(), in choice order, as TransitionBuilder interns
// it, so that the pool's ids (and every file written from them) stay the same.

#include <cstdint>
#include <vector>

#include "model/explicit_model.hpp"
#include "support/huge_page_growth.hpp"
#include "support/rational.hpp"

namespace oasis::model {

class TransitionStream {
 public:
  // `values` holds every probability added, and outlives the stream.
  TransitionStream(std::uint32_t num_actions, const RationalPool& values)
      : num_actions_(num_actions), values_(&values) {}

  [[nodiscard]] std::uint32_t num_actions() const { return num_actions_; }

  // Changes the number of actions, for an explorer that finds its actions as it goes: the
  // choices begun so far move to their indices under the new count (a pass over them). No
  // choice begun may be of an action beyond the new count.
  void set_num_actions(std::uint32_t num_actions);

  // Starts the distribution of choice `choice`, which must exceed every choice begun before.
  void begin(ChoiceIndex choice);
  // Called per edge: the two arrays grow together, out of line, so that the rest is inlined.
  void add(StateIndex target, ValueId probability) {
    if (matrix_.edge_target.size() >= UINT32_MAX) throw_too_many_edges();
    if (matrix_.edge_target.size() == matrix_.edge_target.capacity()) [[unlikely]]
      grow_edges();
    matrix_.edge_target.push_back(target);
    matrix_.edge_probability.push_back(probability);
  }

  // The matrix over `num_states` states; the stream is empty afterwards.
  // `values` is the pool given to the constructor.
  [[nodiscard]] TransitionMatrix finish(std::uint32_t num_states, RationalPool& values);

 private:
  // A probability of merged edges, interned in finish(): {edge, the sum}.
  struct Merge {
    EdgeIndex edge;
    Rational sum;
  };

  [[noreturn]] static void throw_too_many_edges();
  void grow_edges();
  [[noreturn]] static void throw_action_beyond_count();
  // Sorts the distribution begun last by target and merges its repeated targets.
  void close_row();
  void sort_row(std::size_t begin, std::size_t end);
  void merge_row(std::size_t begin, std::size_t end);

  std::uint32_t num_actions_;
  const RationalPool* values_;
  TransitionMatrix matrix_;
  std::size_t row_begin_ = 0;  // where the distribution begun last starts
  std::vector<Merge> merges_;
};

}  // namespace oasis::model
