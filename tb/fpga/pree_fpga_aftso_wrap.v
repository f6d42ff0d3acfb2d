// SPDX-License-Identifier: Apache-2.0
// pree_fpga_aftso_wrap: the dispatcher AFTSO-HpUOC between registers, with pree_top's widths, for
// place and route (scripts/fpga_timing.sh aftso; docs/fpga.md). The photon's data, address and
// count come from one register that a serial pin shifts (scan_i); in_valid and stall from their
// own registers; every output goes to a register, folded into one pin (pree_fpga_fold). So every
// path between registers is the dispatcher's, or the one-net hop into or out of it.
`default_nettype none

module pree_fpga_aftso_wrap #(
  parameter NumPreu = 4,
  parameter AddrW   = 12,
  parameter CntW    = 16
) (
  input  wire clk_i,
  input  wire rst_ni,
  input  wire valid_i,
  input  wire stall_i,
  input  wire scan_i,
  output wire fold_o
);

  localparam DataW = 192;
  localparam IN_W  = DataW + AddrW + CntW;
  localparam OUT_W = NumPreu * (1 + AddrW + DataW + 1 + 1) + 3;

  reg            valid_q, stall_q;
  reg [IN_W-1:0] in_q;
  always @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_q <= 1'b0;
      stall_q <= 1'b0;
    end else begin
      valid_q <= valid_i;
      stall_q <= stall_i;
    end
  end
  always @(posedge clk_i) in_q <= {in_q[IN_W-2:0], scan_i};

  wire [NumPreu-1:0]       lane_valid, lane_last, lane_id;
  wire [NumPreu*AddrW-1:0] lane_ref;
  wire [NumPreu*DataW-1:0] lane_data;
  wire                     ready, busy, empty;

  pree_aftso_hpuoc #(.NumPreu(NumPreu), .BufDepth(4), .DataW(DataW), .IdW(1), .AddrW(AddrW),
                     .CntW(CntW), .EarlyReady(1), .PhotonsPerCycle(1)) u_aftso (
    .clk_i(clk_i), .rst_ni(rst_ni), .in_valid_i(valid_q), .in_ready_o(ready),
    .in_data_i(in_q[0 +: DataW]), .in_id_i(in_q[0]), .in_p_addr_i(in_q[DataW +: AddrW]),
    .in_n_i(in_q[DataW + AddrW +: CntW]), .stall_i(stall_q), .lane_valid_o(lane_valid),
    .lane_ref_addr_o(lane_ref), .lane_data_o(lane_data), .lane_id_o(lane_id),
    .lane_last_o(lane_last), .busy_o(busy), .empty_o(empty));

  reg [OUT_W-1:0] out_q;
  always @(posedge clk_i) out_q <= {lane_valid, lane_ref, lane_data, lane_id, lane_last, ready, busy, empty};

  pree_fpga_fold #(.W(OUT_W)) u_fold (.clk_i(clk_i), .d_i(out_q), .fold_o(fold_o));

endmodule

`default_nettype wire
