// SPDX-License-Identifier: Apache-2.0
// pree_preu_stub: the formal jobs' stand-in for pree_preu (same module name, ports and
// parameters), read instead of rtl/pree_preu.v. It keeps the PREU's timing contract and leaves
// its data free:
//   - an operation presented with valid_i leaves with valid_o and its tag exactly UPD_LATENCY
//     cycles later in update mode, RAD_LATENCY in radiance mode (rtl/pree_preu_lat.vh, the
//     same latencies pree_preu builds its plan from);
//   - in radiance mode lreq_o and lreq_tag_o ask for the pixel sum in stage RAD_LATENCY - (the
//     add's latency) - 1;
//   - busy_o while an operation is in flight;
//   - accept_o, state_o and l_o are free at every cycle (any value the real datapath could give,
//     and more), so the proofs hold whatever the arithmetic computes.
// mode_i is sampled per operation (it may change only while busy_o is low).
`default_nettype none

module pree_preu #(
  parameter TagW       = 32,
  parameter Datapath   = 0,
  parameter PipeFast   = 0,
  parameter AddStages  = 0,
  parameter MulStages  = 0,
  parameter SqrStages  = 0,
  parameter DivStages  = 0,
  parameter U2fStages  = 0,
  parameter WaccStages = 0,
  parameter StateW     = (Datapath != 0) ? 320 : 160
) (
  input  wire              clk_i,
  input  wire              rst_ni,
  input  wire              mode_i,
  input  wire              valid_i,
  input  wire [TagW-1:0]   tag_i,
  input  wire [95:0]       hp_pos_i,
  input  wire [95:0]       hp_f_i,
  input  wire [StateW-1:0] hp_state_i,
  input  wire [95:0]       ph_pos_i,
  input  wire [95:0]       ph_phi_i,
  input  wire [31:0]       alpha_i,
  input  wire [31:0]       kappa_i,
  input  wire [31:0]       ne_i,
  output wire              lreq_o,
  output wire [TagW-1:0]   lreq_tag_o,
  input  wire [95:0]       l_i,
  output wire              valid_o,
  output wire [TagW-1:0]   tag_o,
  output wire              accept_o,
  output wire [StateW-1:0] state_o,
  output wire [95:0]       l_o,
  output wire              busy_o
);

`include "pree_preu_lat.vh"

  // The latencies as pree_preu has them (rtl/pree_preu_lat.vh): UPD_LATENCY, RAD_LATENCY.
  localparam LREQ    = RAD_LATENCY - LAT_ADD - 1;
  localparam DEPTH   = (UPD_LATENCY > RAD_LATENCY) ? UPD_LATENCY : RAD_LATENCY;

  // Stage s (1 .. DEPTH) holds the operation presented s cycles ago: valid, mode, tag.
  reg [DEPTH:1]      v_q;
  reg [DEPTH:1]      m_q;
  reg [TagW-1:0]     t_q [1:DEPTH];

  integer s;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) v_q <= {DEPTH{1'b0}};
    else         v_q <= {v_q[DEPTH-1:1], valid_i};
  end
  always @(posedge clk_i) begin
    m_q    <= {m_q[DEPTH-1:1], mode_i};
    t_q[1] <= tag_i;
    for (s = 2; s <= DEPTH; s = s + 1) t_q[s] <= t_q[s-1];
  end

  wire upd_out = v_q[UPD_LATENCY] && !m_q[UPD_LATENCY];
  wire rad_out = v_q[RAD_LATENCY] && m_q[RAD_LATENCY];
  assign valid_o    = upd_out || rad_out;
  assign tag_o      = upd_out ? t_q[UPD_LATENCY] : t_q[RAD_LATENCY];
  assign lreq_o     = (LREQ == 0) ? (valid_i && mode_i) : (v_q[LREQ] && m_q[LREQ]);
  assign lreq_tag_o = (LREQ == 0) ? tag_i : t_q[LREQ];
  assign busy_o     = |v_q;

  (* anyseq *) reg              f_accept;
  (* anyseq *) reg [StateW-1:0] f_state;
  (* anyseq *) reg [95:0]       f_l;
  assign accept_o = f_accept;
  assign state_o  = f_state;
  assign l_o      = f_l;

  wire unused = ^{hp_pos_i, hp_f_i, hp_state_i, ph_pos_i, ph_phi_i, alpha_i, kappa_i, ne_i, l_i};

endmodule

`default_nettype wire
