// The bounded retransmission protocol: a file of N chunks sent over two lossy channels,
// each chunk retransmitted at most MAX times (dtmc). Set N and MAX with --const.
//
// Published figures: N=16,MAX=2: Storm, src/test/storm/builder/
// ExplicitPrismModelBuilderTest.cpp, test "Dtmc" (brp-16-2.pm): 677 states and 867
// transitions; also the PRISM benchmark suite, models/dtmcs/brp/logs/
// brp.pm.const.N=16,MAX=2.fixdl.log (677 states, 867 transitions). N=64,MAX=5: the PRISM
// benchmark suite, models/dtmcs/brp/logs/brp.pm.const.N=64,MAX=5.fixdl.log: 5192 states,
// 6915 transitions.
//
// Written for oasis from the model's description (P. D'Argenio, B. Jeannet, H. Jensen and
// K. Larsen, "Reachability analysis of probabilistic systems by successive refinements",
// PAPM-PROBMIV 2001; the PRISM case study "Bounded Retransmission Protocol"): a sender, a
// receiver, a check that only one file is sent, a frame channel losing 2% and an
// acknowledgement channel losing 1%. Frames carry first/last flags and an alternating bit.
//
// Once the file is done (sent or given up) nothing can move. Storm, and PRISM with -fixdl,
// add a self-loop to such deadlocks and count it; this program writes that loop as a
// command, so the figures do not depend on how deadlocks are treated. The reward structure
// counts first-frame sends; no quotient figure is checked for this model.

dtmc

const int N;    // chunks in the file
const int MAX;  // retransmissions allowed per chunk

module sender
  // 0 idle, 1 next frame, 2 wait for ack, 3 retransmit, 4 chunk ok, 5 error, 6 wait for sync
  snd : [0..6] init 0;
  snd_report : [0..3] init 0;   // 0 none, 1 not ok, 2 don't know, 3 ok
  retries : [0..MAX] init 0;
  chunk : [0..N] init 0;
  frame_bit : bool init false;  // bit of the frame on its way
  snd_bit : bool init false;    // the sender's alternating bit
  is_first : bool init false;   // the frame on its way is the first chunk
  is_last : bool init false;    // ... the last chunk

  [new_file] snd = 0 -> (snd'=1) & (chunk'=1) & (snd_report'=0);
  [] snd = 0 & file_taken -> true;  // the file is done: stay (the deadlock loop)

  [send_frame] snd = 1 ->
      (snd'=2) & (is_first'=(chunk=1)) & (is_last'=(chunk=N)) & (frame_bit'=snd_bit) & (retries'=0);
  [deliver_ack] snd = 2 -> (snd'=4) & (snd_bit'=!snd_bit);
  [lose_frame] snd = 2 -> (snd'=3);
  [lose_ack] snd = 2 -> (snd'=3);
  [send_frame] snd = 3 & retries < MAX ->
      (snd'=2) & (is_first'=(chunk=1)) & (is_last'=(chunk=N)) & (frame_bit'=snd_bit) & (retries'=retries+1);
  [] snd = 3 & retries = MAX -> (snd'=5) & (snd_report'=(chunk < N ? 1 : 2));
  [] snd = 4 & chunk < N -> (snd'=1) & (chunk'=chunk+1);
  [] snd = 4 & chunk = N -> (snd'=0) & (snd_report'=3);
  [sync] snd = 5 -> (snd'=6);
  [sync] snd = 6 -> (snd'=0) & (snd_bit'=false);
endmodule

module receiver
  // 0 new file, 1 first safe frame, 2 frame received, 3 frame reported, 4 idle, 5 resync
  rcv : [0..5] init 0;
  rcv_report : [0..4] init 0;   // 0 none, 1 first, 2 intermediate, 3 ok, 4 not ok
  got_first : bool init false;
  got_last : bool init false;
  got_bit : bool init false;
  rcv_bit : bool init false;
  got_any : bool init false;

  [sync] rcv = 0 -> true;
  [deliver_frame] rcv = 0 ->
      (rcv'=1) & (got_first'=is_first) & (got_last'=is_last) & (got_bit'=frame_bit) & (got_any'=file_taken);
  [] rcv = 1 -> (rcv'=2) & (rcv_bit'=got_bit);
  [] rcv = 2 & rcv_bit = got_bit & !(got_first & got_last) ->
      (rcv'=3) & (rcv_report'=(got_first ? 1 : (got_last ? 3 : 2)));
  [send_ack] rcv = 2 & rcv_bit != got_bit -> (rcv'=4);
  [send_ack] rcv = 3 -> (rcv'=4) & (rcv_bit'=!rcv_bit);
  [deliver_frame] rcv = 4 ->
      (rcv'=2) & (got_first'=is_first) & (got_last'=is_last) & (got_bit'=frame_bit) & (got_any'=file_taken);
  [sync] rcv = 4 -> (rcv'=5) & (rcv_report'=(is_last ? rcv_report : 4));
  [sync] rcv = 5 -> (rcv'=0) & (rcv_report'=0);
endmodule

module one_file
  file_taken : bool init false;
  [new_file] !file_taken -> (file_taken'=true);
endmodule

module frame_channel
  fc : [0..2] init 0;  // 0 empty, 1 carrying, 2 lost
  [send_frame] fc = 0 -> 0.98 : (fc'=1) + 0.02 : (fc'=2);
  [deliver_frame] fc = 1 -> (fc'=0);
  [lose_frame] fc = 2 -> (fc'=0);
endmodule

module ack_channel
  ac : [0..2] init 0;
  [send_ack] ac = 0 -> 0.99 : (ac'=1) + 0.01 : (ac'=2);
  [deliver_ack] ac = 1 -> (ac'=0);
  [lose_ack] ac = 2 -> (ac'=0);
endmodule

rewards "first_frames"
  [send_frame] chunk = 1 : 1;
endrewards

label "error" = snd = 5;
