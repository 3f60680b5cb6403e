// Knuth and Yao's fair die: a six-sided die simulated with a fair coin (dtmc).
//
// Published figures: Storm, src/test/storm/builder/ExplicitPrismModelBuilderTest.cpp, test
// "Dtmc": 13 states and 20 transitions; src/test/storm/storage/
// DeterministicModelBisimulationDecompositionTest.cpp, test "Die": a quotient of 13 blocks
// respecting every label (die.lab's: one..six and done) and of 5 blocks respecting only
// "one"; src/test/storm/storage/SymbolicBisimulationDecompositionTest.cpp, test "Die"
// (die.pm, whose labels are one, two, three and done): 11 blocks.
//
// Written for oasis from the model's description (D. Knuth and A. Yao, "The complexity of
// nonuniform random number generation", 1976): a binary tree of coin flips whose seven inner
// nodes are numbered 0..6; two leaves loop back to nodes 1 and 2, the others show a face.
// There is no reward structure: Storm's bisimulation test has none, and a reward on each
// flip (Storm's die.pm has one) would keep nodes 2, 4, 5 and 6 apart from the finished
// states: 6 blocks instead of 5 when only "one" is respected.

dtmc

module flips
  node : [0..7] init 0;  // inner node of the tree, 7 once a face is shown
  face : [0..6] init 0;  // 0 while flipping, then the face

  // the top of the tree: node n goes to its children 2n+1 and 2n+2
  [] node < 3 -> 1/2 : (node'=2*node+1) + 1/2 : (node'=2*node+2);
  // nodes 4 and 5 show two faces each: 2,3 and 4,5
  [] node = 4 | node = 5 -> 1/2 : (node'=7) & (face'=2*node-6)
                          + 1/2 : (node'=7) & (face'=2*node-5);
  // nodes 3 and 6 show face 1 or 6, or flip again from node 1 or 2
  [] node = 3 | node = 6 -> 1/2 : (node'=floor(node/3))
                          + 1/2 : (node'=7) & (face'=(node=3 ? 1 : 6));
  // a shown face stays shown
  [] node = 7 -> true;
endmodule

formula shown = node = 7;

label "one"   = shown & face = 1;
label "two"   = shown & face = 2;
label "three" = shown & face = 3;
label "four"  = shown & face = 4;
label "five"  = shown & face = 5;
label "six"   = shown & face = 6;
label "done"  = shown;
