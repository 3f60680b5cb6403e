// Itai and Rodeh's synchronous leader election in a ring of four processes (dtmc). Each
// round every process draws an id uniformly from K values; the ids travel round the ring;
// if some id is unique a leader is elected, otherwise a new round starts. Set K with
// --const (K = 2, 3, 4, 5, 6 or 8).
//
// Published figures: the PRISM benchmark suite, models/dtmcs/leader_sync/logs/
// leader_sync4_4.pm.log (and models/dtmcs/models.csv): K=4: 812 states, 1067 transitions;
// leader_sync4_3.pm.log: K=3: 274 states, 354 transitions.
//
// Written for oasis from the model's description (A. Itai and M. Rodeh, "Symmetry breaking
// in distributed networks", 1990; the PRISM case study "Synchronous Leader Election
// Protocol"): a counter module clocks the N-1 reading steps of a round; process i reads
// process i+1. A process that has seen its own id come back is no longer unique. The reward
// structure counts rounds; no quotient figure is checked for this model.

dtmc

const int K;      // ids are drawn from 0..K-1
const int N = 4;  // processes in the ring

module clock
  round_step : [1..N-1] init 1;  // which neighbour is being read

  [read]  round_step < N-1 -> (round_step'=round_step+1);
  [read]  round_step = N-1 -> true;
  [done]  unique1 | unique2 | unique3 | unique4 -> true;
  [retry] !(unique1 | unique2 | unique3 | unique4) -> (round_step'=1);
  [loop]  st1 = 3 -> true;
endmodule

module ring1
  st1 : [0..3] init 0;        // 0 draw, 1 read, 2 decide, 3 finished
  unique1 : bool init false;  // own id not seen again so far
  msg1 : [0..7] init 0;       // the id passed on to the neighbour
  own1 : [0..7] init 0;       // own id this round

  [pick] st1 = 0 & K = 2 -> 1/2 : (st1'=1) & (own1'=0) & (msg1'=0) & (unique1'=true)
                      + 1/2 : (st1'=1) & (own1'=1) & (msg1'=1) & (unique1'=true);
  [pick] st1 = 0 & K = 3 -> 1/3 : (st1'=1) & (own1'=0) & (msg1'=0) & (unique1'=true)
                      + 1/3 : (st1'=1) & (own1'=1) & (msg1'=1) & (unique1'=true)
                      + 1/3 : (st1'=1) & (own1'=2) & (msg1'=2) & (unique1'=true);
  [pick] st1 = 0 & K = 4 -> 1/4 : (st1'=1) & (own1'=0) & (msg1'=0) & (unique1'=true)
                      + 1/4 : (st1'=1) & (own1'=1) & (msg1'=1) & (unique1'=true)
                      + 1/4 : (st1'=1) & (own1'=2) & (msg1'=2) & (unique1'=true)
                      + 1/4 : (st1'=1) & (own1'=3) & (msg1'=3) & (unique1'=true);
  [pick] st1 = 0 & K = 5 -> 1/5 : (st1'=1) & (own1'=0) & (msg1'=0) & (unique1'=true)
                      + 1/5 : (st1'=1) & (own1'=1) & (msg1'=1) & (unique1'=true)
                      + 1/5 : (st1'=1) & (own1'=2) & (msg1'=2) & (unique1'=true)
                      + 1/5 : (st1'=1) & (own1'=3) & (msg1'=3) & (unique1'=true)
                      + 1/5 : (st1'=1) & (own1'=4) & (msg1'=4) & (unique1'=true);
  [pick] st1 = 0 & K = 6 -> 1/6 : (st1'=1) & (own1'=0) & (msg1'=0) & (unique1'=true)
                      + 1/6 : (st1'=1) & (own1'=1) & (msg1'=1) & (unique1'=true)
                      + 1/6 : (st1'=1) & (own1'=2) & (msg1'=2) & (unique1'=true)
                      + 1/6 : (st1'=1) & (own1'=3) & (msg1'=3) & (unique1'=true)
                      + 1/6 : (st1'=1) & (own1'=4) & (msg1'=4) & (unique1'=true)
                      + 1/6 : (st1'=1) & (own1'=5) & (msg1'=5) & (unique1'=true);
  [pick] st1 = 0 & K = 8 -> 1/8 : (st1'=1) & (own1'=0) & (msg1'=0) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=1) & (msg1'=1) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=2) & (msg1'=2) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=3) & (msg1'=3) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=4) & (msg1'=4) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=5) & (msg1'=5) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=6) & (msg1'=6) & (unique1'=true)
                      + 1/8 : (st1'=1) & (own1'=7) & (msg1'=7) & (unique1'=true);
  // read the neighbour's message; the last read moves on to deciding
  [read] st1 = 1 & round_step < N-1 -> (unique1'=unique1 & own1 != msg2) & (msg1'=msg2)
                                     & (own1'=(unique1 ? own1 : 0));
  [read] st1 = 1 & round_step = N-1 -> (st1'=2) & (unique1'=unique1 & own1 != msg2) & (msg1'=0)
                                     & (own1'=(unique1 ? 0 : own1));
  [done]  st1 = 2 -> (st1'=3) & (unique1'=false) & (msg1'=0) & (own1'=0);
  [retry] st1 = 2 -> (st1'=0) & (unique1'=false) & (msg1'=0) & (own1'=0);
  [loop]  st1 = 3 -> true;
endmodule

module ring2 = ring1 [ st1=st2, unique1=unique2, msg1=msg2, own1=own2, msg2=msg3 ] endmodule
module ring3 = ring1 [ st1=st3, unique1=unique3, msg1=msg3, own1=own3, msg2=msg4 ] endmodule
module ring4 = ring1 [ st1=st4, unique1=unique4, msg1=msg4, own1=own4, msg2=msg1 ] endmodule

rewards "rounds"
  [pick] true : 1;
endrewards

label "elected" = st1 = 3 & st2 = 3 & st3 = 3 & st4 = 3;
