// Syntax errors in a PRISM program: each is reported, and parsing goes on after it.
dtmc

module coin
  x : [0..2] init 0;
  y : [0..1]
  // expect-error@+1:3: expected ';' after the variable, found '['
  [] x=0 -> 0.5 : (x'=1) + 0.5 : (x'=2);
  // expect-error@+1:10: expected '->' between the guard and the updates, found '0.5'
  [] x=1 0.5 : (x'=0) + 0.5 : (x'=2);
  // expect-error@+2:20: unexpected character '#' in a PRISM program
  // expect-error@+1:22: expected ';' after the command, found '('
  [] x=2 -> (x'=2) # (y'=1);
endmodule

label "heads" = x=1;
