// An update that leaves a variable's range is found in exploration, with the state.
dtmc

module counter
  n : [0..3] init 0;
  // expect-error@+1:21: update sets 'n' to 4, outside its range [0 .. 3], in state (n=3)
  [] true -> 0.5 : (n'=n+1) + 0.5 : (n'=n);
endmodule
