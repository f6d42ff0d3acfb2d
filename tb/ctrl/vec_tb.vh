// SPDX-License-Identifier: Apache-2.0
// vec_tb.vh: the vector files of the controllers' Icarus benches (adiso_tb.v, aftso_tb.v),
// included inside the bench module after its MAXCYC, STIM_W and EXP_W; `VEC_TB is the bench's
// name in messages. vec_load reads +stim=FILE +exp=FILE +ncyc=N (stimulus and expected words, one
// a cycle, as the C vector writers emit them); vec_clock ends a cycle; vec_end stops the run with
// $fatal when any mismatch was counted in errors.
  reg [STIM_W-1:0] stim [0:MAXCYC-1];
  reg [EXP_W-1:0]  expv [0:MAXCYC-1];
  reg [1023:0]     stim_file, exp_file;
  integer          ncyc, c, errors;

  task vec_load;
    begin
      if (!$value$plusargs("stim=%s", stim_file) || !$value$plusargs("exp=%s", exp_file) ||
          !$value$plusargs("ncyc=%d", ncyc))
        $fatal(1, "%0s: need +stim=FILE +exp=FILE +ncyc=N", `VEC_TB);
      if (ncyc > MAXCYC) $fatal(1, "%0s: ncyc above %0d", `VEC_TB, MAXCYC);
      $readmemh(stim_file, stim, 0, ncyc - 1);
      $readmemh(exp_file, expv, 0, ncyc - 1);
      errors = 0;
    end
  endtask

  task vec_clock;
    begin
      #4 clk = 1'b1;
      #5 clk = 1'b0;
    end
  endtask

  task vec_end;
    begin
      if (errors != 0) $fatal(1, "%0s: FAIL, %0d mismatches in %0d cycles", `VEC_TB, errors, ncyc);
    end
  endtask
