// NAND multiplexing: a NAND gate made reliable by replacing it with bundles of N unreliable
// gates and K restorative stages (dtmc). Set N and K with --const.
//
// Published figures: N=5,K=2: Storm, src/test/storm/builder/ExplicitPrismModelBuilderTest.cpp,
// test "Dtmc" (nand-5-2.pm): 1728 states and 2505 transitions. N=20,K=2: the PRISM benchmark
// suite, models/dtmcs/models.csv and models/dtmcs/nand/logs/nand.pm.const.N=20,K=2.log:
// 154942 states, 239832 transitions. N=20,K=1: same place, 78332 states, 121512 transitions.
//
// Written for oasis from the model's description (J. Han and P. Jonker, "A system
// architecture solution for unreliable nanoelectronic devices", IEEE Trans. Nanotechnology
// 1(4), 2002; the PRISM case study "NAND Multiplexing"): the 2K+1 multiplexing units are
// simulated one after the other, one gate at a time, reusing the same variables. Each gate
// takes one input from each of the previous unit's two output bundles (a random
// permutation, drawn without replacement) and fails (von Neumann fault, output inverted)
// with probability 0.02; the first unit's inputs are each stimulated with probability 0.9.
// The reward structure is the fraction of stimulated outputs at the end; no quotient
// figure is checked for this model.

dtmc

const int N;  // gates per bundle
const int K;  // restorative stages
const int units = 2*K + 1;

const double fault = 0.02;       // a gate inverts its output
const double stimulated = 0.9;   // an input of the first unit is 1

module multiplexer
  unit : [1..units] init 1;   // the unit being simulated
  gates : [0..N] init 0;      // gates of this unit done so far
  phase : [0..4] init 0;      // 0 next gate, 1 pick input x, 2 pick input y, 3 fire, 4 done
  ones : [0..N] init 0;       // outputs of this unit equal to 1 so far
  left_x : [0..N] init 0;     // previous unit's 1-outputs not yet taken as x
  left_y : [0..N] init 0;     // the same for y
  x : [0..1] init 0;
  y : [0..1] init 0;

  [] phase = 0 & gates < N -> (phase'=1);
  [] phase = 0 & gates = N & unit < units ->
       (phase'=1) & (unit'=unit+1) & (gates'=0) & (left_x'=ones) & (left_y'=ones) & (ones'=0);
  [] phase = 0 & gates = N & unit = units ->
       (phase'=4) & (left_x'=0) & (left_y'=0) & (x'=0) & (y'=0);

  // input x: at random in the first unit; otherwise the permutation is taken in order
  [] phase = 1 & unit = 1 -> stimulated : (phase'=2) & (x'=1) + (1-stimulated) : (phase'=2) & (x'=0);
  [] phase = 1 & unit > 1 -> (phase'=2) & (x'=(left_x > 0 ? 1 : 0)) & (left_x'=max(left_x-1, 0));

  // input y: at random in the first unit; otherwise drawn from the outputs not yet taken
  [] phase = 2 & unit = 1 -> stimulated : (phase'=3) & (y'=1) + (1-stimulated) : (phase'=3) & (y'=0);
  [] phase = 2 & unit > 1 & left_y = 0 -> (phase'=3) & (y'=0);
  [] phase = 2 & unit > 1 & left_y = N-gates & gates < N -> (phase'=3) & (y'=1) & (left_y'=left_y-1);
  [] phase = 2 & unit > 1 & left_y > 0 & left_y < N-gates ->
       left_y/(N-gates) : (phase'=3) & (y'=1) & (left_y'=left_y-1)
     + (1 - left_y/(N-gates)) : (phase'=3) & (y'=0);

  // fire the gate: NAND, or its negation on a fault
  [] phase = 3 & ones < N & gates < N ->
       (1-fault) : (phase'=0) & (gates'=gates+1) & (ones'=ones + 1 - x*y) & (x'=0) & (y'=0)
     + fault : (phase'=0) & (gates'=gates+1) & (ones'=ones + x*y) & (x'=0) & (y'=0);

  [] phase = 4 -> true;
endmodule

rewards "fraction_stimulated"
  [] phase = 0 & gates = N & unit = units : ones / N;
endrewards

label "end" = phase = 4;
label "target" = phase = 4 & ones/N < 0.1;
