// SPDX-License-Identifier: Apache-2.0
// pree_fpga_preu_wrap: one PREU between registers, for place and route on a part with fewer pins
// than the PREU has port bits (scripts/fpga_timing.sh preu / preu_fast; docs/fpga.md).
//
// Every PREU input comes from one wide register that a serial pin shifts (scan_i), and the
// control inputs (mode, valid) from their own registers; every PREU output goes to a register,
// and those registers fold into one output pin through a pipelined XOR tree, one LUT4 level per
// register stage. So every path between registers is a path of the PREU (or the one-net hop into
// or out of it), no PREU input or output can be removed by synthesis, and the wrapper's own
// paths are one LUT deep. The pins' own delays are outside the clock domain's figure.
`default_nettype none

module pree_fpga_preu_wrap #(
  parameter Datapath = 0,
  parameter PipeFast = 0,
  parameter TagW     = 8
) (
  input  wire clk_i,
  input  wire rst_ni,
  input  wire mode_i,
  input  wire valid_i,
  input  wire scan_i,
  output wire fold_o
);

  localparam StateW = (Datapath != 0) ? 320 : 160;
  // The data inputs in one register: tag, hp_pos, hp_f, state, ph_pos, ph_phi, alpha, kappa, ne, l.
  localparam IN_W  = TagW + 96 + 96 + StateW + 96 + 96 + 32 + 32 + 32 + 96;
  localparam OUT_W = 1 + TagW + 1 + TagW + 1 + StateW + 96 + 1;

  reg            mode_q, valid_q;
  reg [IN_W-1:0] in_q;

  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= 1'b0;
    else         valid_q <= valid_i;
  end
  always @(posedge clk_i) begin
    mode_q <= mode_i;
    in_q   <= {in_q[IN_W-2:0], scan_i};
  end

  wire              lreq, vout, acc, busy;
  wire [TagW-1:0]   lreq_tag, tag;
  wire [StateW-1:0] state;
  wire [95:0]       l;

  pree_preu #(.TagW(TagW), .Datapath(Datapath), .PipeFast(PipeFast)) u_preu (
    .clk_i(clk_i), .rst_ni(rst_ni), .mode_i(mode_q), .valid_i(valid_q),
    .tag_i     (in_q[0 +: TagW]),
    .hp_pos_i  (in_q[TagW +: 96]),
    .hp_f_i    (in_q[TagW + 96 +: 96]),
    .hp_state_i(in_q[TagW + 192 +: StateW]),
    .ph_pos_i  (in_q[TagW + 192 + StateW +: 96]),
    .ph_phi_i  (in_q[TagW + 288 + StateW +: 96]),
    .alpha_i   (in_q[TagW + 384 + StateW +: 32]),
    .kappa_i   (in_q[TagW + 416 + StateW +: 32]),
    .ne_i      (in_q[TagW + 448 + StateW +: 32]),
    .l_i       (in_q[TagW + 480 + StateW +: 96]),
    .lreq_o(lreq), .lreq_tag_o(lreq_tag), .valid_o(vout), .tag_o(tag), .accept_o(acc),
    .state_o(state), .l_o(l), .busy_o(busy));

  // Output registers, then the XOR tree (pree_fpga_fold).
  reg [OUT_W-1:0] out_q;
  always @(posedge clk_i) out_q <= {lreq, lreq_tag, vout, tag, acc, state, l, busy};

  pree_fpga_fold #(.W(OUT_W)) u_fold (.clk_i(clk_i), .d_i(out_q), .fold_o(fold_o));

endmodule
