// Model types oasis does not explore are refused by name.
// expect-error@+1:1: model type 'ctmc' is not supported: oasis explores dtmc and mdp programs
ctmc

module m
  x : [0..1] init 0;
  [] x=0 -> 2 : (x'=1);
endmodule
