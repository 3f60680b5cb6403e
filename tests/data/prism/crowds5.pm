// Crowds, Reiter and Rubin's anonymity protocol, with a crowd of five members of which the
// sender is member 0, repeated over TotalRuns runs (dtmc). Set TotalRuns with --const.
//
// Published figures (TotalRuns=5): Storm, src/test/storm/builder/
// ExplicitPrismModelBuilderTest.cpp, test "Dtmc" (crowds-5-5.pm): 8607 states and 15113
// transitions; src/test/storm/storage/DeterministicModelBisimulationDecompositionTest.cpp,
// test "Crowds" (crowds5_5.tra/.lab, the same chain with the labels init, deadlock,
// observe0Greater1, observeIGreater1 and observeOnlyTrueSender): a quotient of 334 blocks
// respecting all those labels and of 65 blocks respecting only "observe0Greater1";
// src/test/storm/storage/SymbolicBisimulationDecompositionTest.cpp, test "Crowds"
// (crowds5_5.pm, whose labels are the seven observe... labels below): 2007 blocks
// respecting those seven labels, 65 respecting "observe0Greater1". Since the label sets
// differ, published.json names the respected labels of each figure explicitly.
//
// Written for oasis from the model's description (M. Reiter and A. Rubin, "Crowds:
// anonymity for web transactions", 1998, in the simplified form Storm's tests use): each
// run, the message goes to a crowd member that is corrupt with probability 0.167; an honest
// member passes it on with probability 0.8 (a member chosen uniformly is remembered as the
// last one seen) or delivers it; a corrupt member records the last member seen and the
// message is delivered. The attacker counts how often it saw each member.
//
// The figures count a self-loop on each state where all runs are done (Storm adds one to
// every deadlock and labels it "deadlock"); this program writes that loop as a command and
// names those states "runs_done" (Storm's "deadlock" states), so neither count nor
// quotient depends on how deadlocks are treated. No reward structure.

dtmc

const int TotalRuns;

// The numbers start with their point, as the copy Storm's tests use writes them (PRISM's
// lexer accepts it; prism_numbers_test reads this file for that).
const double forward = .8;         // an honest member forwards
const double corrupt = .167;       // a member is corrupt
const double honest  = .833;       // = 1 - corrupt

// how often the attacker has seen the last member
formula times_seen = last=0 ? seen0 : (last=1 ? seen1 : (last=2 ? seen2 : (last=3 ? seen3 : seen4)));

module crowd
  // 0: between runs, 1: a member receives the message, 2: the member acts,
  // 3: an honest member decides to forward or deliver, 4: delivered
  step : [0..4] init 0;
  honest_member : bool init false;  // the member holding the message is honest
  runs : [0..TotalRuns] init 0;     // runs started
  last : [0..4] init 0;             // last member seen before the current one
  seen0 : [0..TotalRuns] init 0;    // times the attacker saw member i
  seen1 : [0..TotalRuns] init 0;
  seen2 : [0..TotalRuns] init 0;
  seen3 : [0..TotalRuns] init 0;
  seen4 : [0..TotalRuns] init 0;

  [] step = 0 & runs < TotalRuns -> (step'=1) & (runs'=runs+1) & (last'=0);
  [] step = 0 & runs = TotalRuns -> true;  // all runs done

  [] step = 1 -> honest : (step'=2) & (honest_member'=true)
               + corrupt : (step'=2) & (honest_member'=false);

  // an honest member: the last member seen becomes one of the five, uniformly
  [] step = 2 & honest_member -> 1/5 : (step'=3) & (last'=0) + 1/5 : (step'=3) & (last'=1)
                               + 1/5 : (step'=3) & (last'=2) + 1/5 : (step'=3) & (last'=3)
                               + 1/5 : (step'=3) & (last'=4);
  // a corrupt member: the attacker records the last member seen
  [] step = 2 & !honest_member & times_seen < TotalRuns ->
       (seen0'=seen0 + (last=0 ? 1 : 0)) & (seen1'=seen1 + (last=1 ? 1 : 0))
     & (seen2'=seen2 + (last=2 ? 1 : 0)) & (seen3'=seen3 + (last=3 ? 1 : 0))
     & (seen4'=seen4 + (last=4 ? 1 : 0)) & (step'=4);

  [] step = 3 -> forward : (step'=1) + (1-forward) : (step'=4);
  [] step = 4 -> (step'=0);
endmodule

label "observe0Greater1" = seen0 > 1;
label "observe1Greater1" = seen1 > 1;
label "observe2Greater1" = seen2 > 1;
label "observe3Greater1" = seen3 > 1;
label "observe4Greater1" = seen4 > 1;
label "observeIGreater1" = seen1 > 1 | seen2 > 1 | seen3 > 1 | seen4 > 1;
label "observeOnlyTrueSender" = seen0 > 1 & seen1 <= 1 & seen2 <= 1 & seen3 <= 1 & seen4 <= 1;
label "runs_done" = step = 0 & runs = TotalRuns;
