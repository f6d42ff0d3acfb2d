// SPDX-License-Identifier: Apache-2.0
// pree_adiso_rec: approximate data-independent schedule-oriented radiance evaluation controller
// (ADISO-REC, paper 000 Sec. IV.C, Eq. 10-13, Fig. 9-10): the leaping-address generator.
//
// Purpose: during radiance evaluation, hand every hit-point address in [0, N) to exactly one
// of NumPreu groups (one per PREU), exactly once, in an order that keeps neighbouring
// addresses (hit points of one pixel are allocated next to each other) apart in time.
//
// Rule (per group i, all groups in parallel, one address per group per cycle):
//   SHIFT    = ceil(log2(NumPreu * PipeDepth))             (6 for 4 x 12, as in Fig. 10)
//   lv       = N >> SHIFT                                  (Eq. 10), replaced by 1 when 0
//   size     = N >> log2(NumPreu)                          (NumPreu must be a power of two)
//   group i  = [size*i, end_i), end_i = size*(i+1); the last group ends at N and so also
//              takes the N mod NumPreu left-over addresses
//   first address start = leap = size*i; then per cycle     (Eq. 12, 13)
//     leap + lv >= end_i ? (start = start + 1, leap = start + 1) : leap = leap + lv
//   group i stops after end_i - size*i addresses.
// Within a group this walks the residue classes size*i + r (mod lv), r = 0 .. lv-1, each
// upwards, so every address of the group appears exactly once. With lv = 0 (N < 2^SHIFT) the
// paper's recurrence would repeat one address forever; lv = 1 walks each group in order.
// Groups with no address (N < NumPreu) are never valid. N = 0 gives no valid cycle at all.
// Deviation from Fig. 10: Reg_end2 there is (N >> 2) + (N >> 1), which overlaps group 3 when
// N mod 4 is 2 or 3; here every end is size*(i+1), so the groups partition [0, N).
//
// Handshake:
//   start_i    loads n_hit_i (N) and starts a pass; it may come at any time and aborts a
//              pass in progress. The first addresses appear in the cycle after the start edge.
//   addr_*_o   registered. addr_valid_o[i] high: addr_o[i] is offered to PREU i; it is taken
//              on every rising edge with stall_i low (then the group steps). While stall_i is
//              high nothing changes. Invalid groups drive address 0.
//   busy_o     some group still has addresses (registered, = |addr_valid_o).
// The number of cycles of a pass (no stalls) is the largest group, N - (NumPreu-1)*size.
//
// Parameters: NumPreu groups (a power of two), PipeDepth PREU pipeline stages in radiance
// mode (12 in the paper), AddrW address bits (N <= 2^AddrW - 1).
`default_nettype none

module pree_adiso_rec #(
  parameter NumPreu   = 4,
  parameter PipeDepth = 12,
  parameter AddrW     = 32
) (
  input  wire                     clk_i,
  input  wire                     rst_ni,
  input  wire                     start_i,
  input  wire [AddrW-1:0]         n_hit_i,
  input  wire                     stall_i,
  output wire [NumPreu-1:0]       addr_valid_o,
  output wire [NumPreu*AddrW-1:0] addr_o,
  output wire                     busy_o
);

  localparam SHIFT   = $clog2(NumPreu * PipeDepth);
  localparam LOG_SET = $clog2(NumPreu);

  // NumPreu must be a power of two (groups are cut by a shift, as in Fig. 10).
  generate
    if ((1 << LOG_SET) != NumPreu) begin : g_bad_numpreu
      pree_adiso_rec_numpreu_must_be_a_power_of_two u_fail ();
    end
  endgenerate

  // x * k for a constant k, as shifts and adds (keeps synthesis off DSP multipliers).
  function [AddrW-1:0] times_const;
    input [AddrW-1:0] x;
    input [31:0]      k;
    integer b;
    begin
      times_const = {AddrW{1'b0}};
      for (b = 0; b < 32; b = b + 1)
        if (k[b]) times_const = times_const + (x << b);
    end
  endfunction

  // ---------------------------------------------------------------------------------------------
  // Pass set-up from n_hit_i (used on start_i only).
  wire [AddrW-1:0] lv_raw  = n_hit_i >> SHIFT;
  wire [AddrW-1:0] lv_load = (lv_raw == {AddrW{1'b0}}) ? {{(AddrW-1){1'b0}}, 1'b1} : lv_raw;
  wire [AddrW-1:0] size    = n_hit_i >> LOG_SET;

  reg [AddrW-1:0] lv_q;

  always @(posedge clk_i) begin
    if (start_i) lv_q <= lv_load;
  end

  genvar gi;
  generate
    for (gi = 0; gi < NumPreu; gi = gi + 1) begin : g_group
      localparam [31:0] IDX_32  = gi;
      localparam [31:0] IDX1_32 = gi + 1;
      // Group bounds: base = size*i, end = size*(i+1) or N for the last group.
      wire [AddrW-1:0] base_load = times_const(size, IDX_32);
      wire [AddrW-1:0] end_load  = (gi == NumPreu - 1) ? n_hit_i : times_const(size, IDX1_32);

      reg  [AddrW-1:0] start_q, start_d;   // start_addr (Reg_start)
      reg  [AddrW-1:0] leap_q,  leap_d;    // leaping_addr (Reg_leaping_addr), the output
      reg  [AddrW-1:0] end_q,   end_d;     // end address, exclusive (Reg_end)
      reg  [AddrW-1:0] rem_q,   rem_d;     // addresses still to be produced

      wire             active = rem_q != {AddrW{1'b0}};
      wire [AddrW:0]   next   = {1'b0, leap_q} + {1'b0, lv_q};
      wire             wrap   = next >= {1'b0, end_q};

      always @* begin
        start_d = start_q;
        leap_d  = leap_q;
        end_d   = end_q;
        rem_d   = rem_q;
        if (start_i) begin
          // Load a new pass.
          start_d = base_load;
          leap_d  = base_load;
          end_d   = end_load;
          rem_d   = end_load - base_load;
        end else if (!stall_i && active) begin
          // Step: next address of the residue class, or the start of the next class.
          rem_d = rem_q - {{(AddrW-1){1'b0}}, 1'b1};
          if (wrap) begin
            start_d = start_q + {{(AddrW-1){1'b0}}, 1'b1};
            leap_d  = start_q + {{(AddrW-1){1'b0}}, 1'b1};
          end else begin
            leap_d  = next[AddrW-1:0];
          end
        end
      end

      always @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) rem_q <= {AddrW{1'b0}};
        else         rem_q <= rem_d;
      end

      always @(posedge clk_i) begin
        start_q <= start_d;
        leap_q  <= leap_d;
        end_q   <= end_d;
      end

      assign addr_valid_o[gi]          = active;
      assign addr_o[gi*AddrW +: AddrW] = active ? leap_q : {AddrW{1'b0}};
    end
  endgenerate

  assign busy_o = |addr_valid_o;

endmodule

`default_nettype wire
