// SPDX-License-Identifier: Apache-2.0
// tb_preu: self-checking Icarus Verilog testbench for pree_preu over a vector file.
//
// The vector file (tb/preu/preu_vecgen.c, layout in tb/preu/preu_vec.c: preu_vec_words) holds
// NOps operations of PREU_VEC_WORDS = 44 hex words each: mode, gap, inputs, expected outputs,
// computed by model/pree/preu_fp32.c (Datapath 0) or model/pree/preu_stable.c (Datapath 1). The bench plays them in order as a top would: it leaves `gap`
// idle cycles before each, switches mode_i only when the pipeline is empty, answers lreq_o with
// the operation's pixel sum on l_i in the next cycle, and drives junk on unread inputs. Every
// result is checked against its vector by tag, with the PREU's own latency (dut.UPD_LATENCY,
// dut.RAD_LATENCY: paper 10 / stable 12 and 12 with PipeFast 0);
// the first 20 mismatches are printed; any failure ends in $fatal (run as `vvp -N`).
// With BadSwitch = 1 it breaks the mode-switch rule on purpose: pree_preu's PREE_ASSERT check
// must then stop the run (mk/preu.mk: sim-preu-badswitch expects that failure).
`timescale 1ns / 1ps
`default_nettype none

module tb_preu;
  parameter NOps    = 100;
  parameter VecFile = "preu_vec.hex";
  parameter BadSwitch = 0;   // 1: switch modes without waiting for the drain (the RTL must stop)
  parameter Datapath  = 0;   // 0 paper, 1 stable
  parameter PipeFast  = 0;   // 0 the paper's units, 1 the deep plans (the latencies follow)
  localparam W   = 44;
  localparam SW  = (Datapath != 0) ? 320 : 160;   // state bits
  // Word offsets in a vector (tb/preu/preu_vec.c preu_vec_words).
  localparam O_POS = 2, O_F = 5, O_ST = 8, O_PPOS = 18, O_PHI = 21, O_NE = 24, O_L = 25;
  localparam O_ALPHA = 28, O_KAPPA = 29, O_ACC = 30, O_STO = 31, O_LO = 41;

  reg [31:0] vec [0:NOps*W-1];
  initial $readmemh(VecFile, vec);

  reg clk = 1'b0;
  always #5 clk = ~clk;
  reg rst_n = 1'b0;

  reg         mode, valid;
  reg  [31:0] tag, ne, alpha, kappa;
  reg  [95:0] hp_pos, hp_f, ph_pos, ph_phi, l_in;
  reg  [SW-1:0] hp_state;
  wire        lreq, valid_out, accept, busy;
  wire [31:0] lreq_tag, tag_out;
  wire [95:0] l_out;
  wire [SW-1:0] state_out;

  pree_preu #(.TagW(32), .Datapath(Datapath), .PipeFast(PipeFast)) dut (
    .clk_i(clk), .rst_ni(rst_n), .mode_i(mode), .valid_i(valid), .tag_i(tag),
    .hp_pos_i(hp_pos), .hp_f_i(hp_f), .hp_state_i(hp_state),
    .ph_pos_i(ph_pos), .ph_phi_i(ph_phi), .alpha_i(alpha), .kappa_i(kappa), .ne_i(ne),
    .lreq_o(lreq), .lreq_tag_o(lreq_tag), .l_i(l_in), .valid_o(valid_out), .tag_o(tag_out),
    .accept_o(accept), .state_o(state_out), .l_o(l_out), .busy_o(busy));

  function [95:0] w96;
    input integer base;
    begin
      w96 = {vec[base+2], vec[base+1], vec[base]};
    end
  endfunction

  // The SW/32 state words at base, low word first.
  function [SW-1:0] wst;
    input integer base;
    integer i;
    begin
      for (i = 0; i < SW / 32; i = i + 1) wst[32*i +: 32] = vec[base + i];
    end
  endfunction

  // Issue-cycle bookkeeping for the latency check.
  reg [63:0] issue_cycle [0:NOps-1];
  reg [63:0] cycle = 0;
  integer next = 0, gap_left = 0, checked = 0, errors = 0, accepted = 0, switches = 0;
  integer expect_next = 0, b, jk;
  reg     can_switch;

  task fail;
    input [8*64-1:0] what;
    input integer idx;
    begin
      errors = errors + 1;
      if (errors <= 20) begin
        b = idx * W;
        $display("MISMATCH op %0d (mode %0d) cycle %0d: %0s", idx, vec[b], cycle, what);
        $display("  got  accept %0d state %h l %h tag %0d", accept, state_out, l_out, tag_out);
        $display("  want accept %0d state %h l %h", vec[b+O_ACC], wst(b+O_STO), w96(b+O_LO));
        $display("  in   hp pos %h f %h state %h", w96(b+O_POS), w96(b+O_F), wst(b+O_ST));
        $display("       ph pos %h phi %h alpha %h kappa %h ne %h l %h", w96(b+O_PPOS), w96(b+O_PHI),
                 vec[b+O_ALPHA], vec[b+O_KAPPA], vec[b+O_NE], w96(b+O_L));
      end
    end
  endtask

  // Drive junk on every input nobody reads.
  task junk;
    begin
      valid  <= 1'b0;
      tag    <= $random;
      hp_pos <= {$random, $random, $random};
      hp_f   <= {$random, $random, $random};
      for (jk = 0; jk < SW / 32; jk = jk + 1) hp_state[32*jk +: 32] <= $random;
      ph_pos <= {$random, $random, $random};
      ph_phi <= {$random, $random, $random};
    end
  endtask

  initial begin
    mode = 1'b0; valid = 1'b0; ne = 32'd0; l_in = 96'd0; tag = 32'd0;
    hp_pos = 0; hp_f = 0; hp_state = 0; ph_pos = 0; ph_phi = 0; alpha = 0; kappa = 0;
    can_switch = 1'b0;
    repeat (2) @(posedge clk);
    @(negedge clk);
    rst_n = 1'b1;
  end

  // At each rising edge: check the outputs of the cycle that ends, then drive the next cycle's
  // inputs (nonblocking, so the DUT samples the old ones at this edge).
  always @(posedge clk) if (rst_n) begin
    // ---- check
    if (valid_out) begin
      b = expect_next * W;
      if (expect_next >= NOps) fail("valid_o with nothing in flight", 0);
      else begin
        if (tag_out != expect_next)
          fail("result out of order (tag)", expect_next);
        /* verilator lint_off WIDTH */  // the PREU's 32-bit latency parameters against 64-bit cycles
        else if (cycle != issue_cycle[expect_next] + (vec[b][0] ? dut.RAD_LATENCY : dut.UPD_LATENCY))
        /* verilator lint_on WIDTH */
          fail("wrong latency", expect_next);
        else if (vec[b] == 0 && (accept !== vec[b+O_ACC][0] || state_out !== wst(b+O_STO)))
          fail("update result", expect_next);
        else if (vec[b] == 1 && (accept !== 1'b0 || l_out !== w96(b+O_LO)))
          fail("radiance result", expect_next);
        if (vec[b] == 0 && accept) accepted = accepted + 1;
        checked = checked + 1;
        expect_next = expect_next + 1;
      end
    end
    // ---- next cycle's inputs
    l_in <= lreq ? w96(lreq_tag * W + O_L) : {$random, $random, $random};
    junk;
    // The pipeline is empty in the next cycle if it is empty now and nothing enters now.
    can_switch = !busy && !valid;
    if (next < NOps) begin
      b = next * W;
      if (gap_left > 0) begin
        gap_left = gap_left - 1;
      end else if (vec[b][0] != mode && !can_switch && BadSwitch == 0) begin
        // wait for the drain
      end else begin
        if (vec[b][0] != mode) switches = switches + 1;
        mode   <= vec[b][0];
        valid  <= 1'b1;
        tag    <= next;
        hp_pos <= w96(b + O_POS);
        hp_f   <= w96(b + O_F);
        hp_state <= wst(b + O_ST);
        ph_pos <= w96(b + O_PPOS);
        ph_phi <= w96(b + O_PHI);
        if (vec[b][0]) ne <= vec[b + O_NE];
        else begin alpha <= vec[b + O_ALPHA]; kappa <= vec[b + O_KAPPA]; end
        issue_cycle[next] = cycle + 1;
        next = next + 1;
        if (next < NOps) gap_left = vec[next * W + 1];
      end
    end
    cycle = cycle + 1;
    /* verilator lint_off WIDTH */  // the PREU's 32-bit latency parameters against 64-bit cycles
    if (checked == NOps || cycle > NOps * (40 + dut.RAD_LATENCY) + 1000) begin
    /* verilator lint_on WIDTH */
      $display("tb_preu: %0d operations checked (%0d update accepted), %0d mode switches, %0d cycles, %0d mismatches: %0s",
               checked, accepted, switches, cycle, errors, (errors == 0 && checked == NOps) ? "PASS" : "FAIL");
      if (errors != 0 || checked != NOps) $fatal(1, "tb_preu: FAIL");
      $finish;
    end
  end

  initial gap_left = 0;
endmodule
