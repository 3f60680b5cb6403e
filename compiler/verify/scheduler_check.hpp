#pragma once
// The independent check of a scheduler file (`oasisc query --scheduler`): each memoryless
// scheduler of `Pmax=? [F T]`, `Pmin=? [F T]` or `[phi U T]` (reachability_property.hpp) is
// optimal on the model, exactly. It shares no code with the model checker: only the model,
// GMP rationals, and the small graph searches and elimination written here.
//
// Setting. States outside phi and T are absorbing with value 0 (the until's failures), states
// of T absorbing with value 1; the others are "live": there the scheduler chooses among the
// enabled actions (a live state without one is a deadlock, value 0). Phi(x)(s) is 1 on T,
// 0 on the other absorbing states and deadlocks, and max_a (Pmax) or min_a (Pmin) of
// sum_t P(s,a,t) x(t) elsewhere. The checks:
//
// 1. Every state is named once and every action named is enabled in its state. null ("any
//    action") is accepted where the choice cannot change anything: an absorbing state, a live
//    state with at most one action, a state from which no path reaches T (every scheduler
//    gives 0), or a state of Prob1A (every scheduler gives 1: no path avoiding T reaches Z,
//    see 3). Such a state's value is the same under every scheduler, so the value of every
//    other state is too, whatever a null resolves to.
//
// 2. v, the value of the Markov chain the scheduler induces, exactly: 1 on T and on the null
//    states of Prob1A; a backward search from those along the chosen actions' edges gives the
//    states that reach them (the others: 0); the linear system x = b + A x on the rest is
//    solved by Gaussian elimination over GMP rationals, the rows kept sparse (state
//    elimination: eliminating a state adds its row, times the coefficient, into the rows that
//    refer to it; every number stays non-negative). Every state it solves reaches T with
//    positive probability, so I - A is invertible and 1 - A(k,k) > 0 at each step. v is the
//    value of a scheduler, so Pmin <= v <= Pmax.
//
// 3. Optimality by a certificate, checked exactly in every live state and every enabled action:
//    Pmax: v(s) >= sum_t P(s,a,t) v(t). Then v >= Phi(v) (equal on the absorbing states).
//      Phi is monotone and Phi^n(0)(s) is the largest probability of reaching T within n steps
//      over all (history-dependent) schedulers; by induction Phi^n(0) <= Phi^n(v) <= v, so
//      Pmax = sup_n Phi^n(0) <= v. With v <= Pmax: v = Pmax.
//    Pmin: let A be the least set holding T and every live state that has an action and whose
//      every action has a successor in A (a fixed point, computed by counting down each
//      state's actions that have no successor in A yet); Z = the states outside A. From a state
//      of Z some action keeps every successor in Z (or there is none), so some scheduler stays
//      in Z and never reaches T: Pmin = 0 on Z (Prob0E). From A every scheduler reaches T
//      within |S| steps with probability at least some p > 0 (by induction on the stage at
//      which a state joined A). The check: v = 0 on Z, and v(s) <= sum_t P(s,a,t) v(t) at every
//      live s outside Z. Then for any scheduler pi (history-dependent too) from s, let tau be
//      the first time in T or Z and M_n = v(X_{min(n, tau)}): before tau the state is live
//      outside Z, where the expected next v is >= the current one whatever pi chooses, so
//      v(s) <= E[M_n]. tau is finite with probability 1 (from A, T within |S| steps with
//      probability >= p, whatever the history), so E[M_n] -> E[v(X_tau)] = P(X_tau in T)
//      <= P^pi(F T). Hence v <= Pmin, and with v >= Pmin: v = Pmin. This is the equation
//      system for minimal reachability probabilities (Baier and Katoen, Principles of Model
//      Checking, Section 10.6.1): its solution is unique once the states of Pmin = 0 are
//      fixed to 0, and fixing Z is essential: without it v = 1 on a cycle of non-target
//      states would pass "equal for the chosen action, <= for the others".
//    Prob1A, for the nulls of 1: Pmin(s) < 1 exactly when some path avoiding T leads from s
//      to Z. If one does, a scheduler follows it and then stays in Z. If none does, every
//      state reachable from s before T lies in A, and the bound p above gives probability 1.
//
// Cost: linear in the model for the graph searches and the certificate, plus the elimination,
// which refuses more than kMaxSolvedStates states to solve or kMaxEliminationWork
// multiply-adds, and any number longer than the --max-number-bits limit.

#include <cstddef>
#include <string>
#include <vector>

#include "model/explicit_model.hpp"
#include "support/limits.hpp"
#include "verify/catalog_check.hpp"
#include "verify/scheduler_reader.hpp"

namespace oasis::verify {

inline constexpr std::size_t kMaxSolvedStates = 100'000;
inline constexpr std::size_t kMaxEliminationWork = 50'000'000;

struct SchedulerCheckOptions {
  std::size_t max_number_bits = limits::kDefaultMaxNumberBits;
};

// One entry per scheduler of `file`, in order ("scheduler for 'Pmax=? [F \"six\"]'"); each is
// checked even after another fails. A model whose contexts have transitions of their own
// gives one failed entry (the schedulers of `oasisc query` are for models whose contexts share
// theirs).
std::vector<CatalogCheck> check_schedulers(const model::ExplicitModel& model,
                                           const SchedulerFile& file,
                                           const SchedulerCheckOptions& options = {});

}  // namespace oasis::verify
