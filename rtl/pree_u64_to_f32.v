// SPDX-License-Identifier: Apache-2.0
// pree_u64_to_f32: an unsigned 64-bit integer rounded once to binary32, round to nearest even,
// Stages pipeline stages (2 by default, the paper's; 5 with PipeFast = 1).
//
// Bit-exact with u64_to_f32() of model/pree/wide_acc.h (the same as the C conversion (float)k):
// exact up to 2^24, 0 -> +0, never negative, never infinite (2^64 - 1 rounds to 2^64 =
// 0x5F800000, far below the overflow threshold), no NaN.
//
// Parameters:
//   PipeFast  0: the paper's configuration (Stages = 2); 1: the deep configuration for FPGA
//             clock rates (Stages = 5: every seam below registered). docs/fpga.md.
//   Stages    1 .. 5, the latency of the datapath; overrides PipeFast's choice. Every value
//             gives the same bits.
//   InRegs    0 or 1: registers on the operands before the datapath (seam 0), so that a
//             caller's operand select ends in a register (the PREU with PipeFast = 1).
//             LATENCY = InRegs + Stages.
//
// Protocol: fixed latency, no stalls. An operation presented with valid_i at a rising edge
// appears on y_o with valid_o exactly LATENCY edges later; one operation may enter every cycle.
// y_o holds its last value while valid_o is low. Only the valid bits are reset.
//
// The datapath is cut at five seams (pree_fp32_pipe each, a register or a wire):
//   A1 the leading-zero count of each byte of a (pree_fp32_lzc, 8 bits each), and which bytes
//      are non-zero                                                                 -> seam 1
//   A2 the count lz of a (0 .. 64; 64 only for a = 0): the first non-zero byte and its count
//                                                                                   -> seam 2
//   B1 the normalising left shift by whole bytes (lz[5:3])                          -> seam 3
//   B2 the shift by lz[2:0] (the leading one to bit 63); the top 27 bits and the OR of the 37
//      below (sticky); exponent 63 - lz + 127                                       -> seam 4
//   C  pree_fp32_final, no special result (round, Denorm = 0: the exponent is at least 127, so no
//      subnormal and no overflow can occur) rounds to nearest even and packs       -> seam 5
//   Zero needs no special case: its normalised word is 0, which packs as +0.
// Stage plan (registered seams per Stages; the last seam is always the output register):
//   Stages 1: 5 | 2: 2 5 | 3: 2 4 5 | 4: 1 2 4 5 | 5: all
// Stages = 2 is the paper's split (stage 1 = the count, stage 2 = shift and round): with the
// count per byte it measures 4 / 4 LUT levels after Yosys mapping (the earlier 64-bit priority
// chain: 9 / 9; count and shift together in stage 1: 14 / 3; docs/fp32_units.md).
`default_nettype none

module pree_u64_to_f32 #(
  parameter PipeFast = 0,
  parameter Stages   = (PipeFast != 0) ? 5 : 2,
  parameter InRegs   = 0
) (
  input  wire        clk_i,
  input  wire        rst_ni,
  input  wire        valid_i,
  input  wire [63:0] a_i,
  output wire        valid_o,
  output wire [31:0] y_o
);

  localparam MAX_STAGES = 5;

  // Registers at seam s (1 .. 5) under the stage plan above: bit s-1 of row Stages of PLANS
  // (rows Stages = 5 .. 1, left to right).
  localparam [5*5-1:0] PLANS = {5'b11111, 5'b11011, 5'b11010, 5'b10010,
                                5'b10000};
  function integer seam_regs;
    input integer s;
    seam_regs = PLANS[((Stages < 1) ? 0 : (Stages > MAX_STAGES) ? MAX_STAGES - 1 : Stages - 1)
                      * MAX_STAGES + s - 1] ? 1 : 0;
  endfunction

  // ---------------------------------------------------------------- entry: seam 0, the check
  // A Stages value outside its range, or PipeFast other than 0 or 1, stops elaboration (Verilator,
  // Icarus, Yosys) with a module named after the problem, however the unit is instantiated.
  generate
    if (Stages < 1 || Stages > MAX_STAGES) begin : g_bad_stages
      pree_u64_to_f32_stages_is_1_to_5 u_fail ();
    end
    if (PipeFast < 0 || PipeFast > 1) begin : g_bad_pipefast
      pree_u64_to_f32_pipefast_is_0_or_1 u_fail ();
    end
  endgenerate

  // InRegs operand registers before A1 (pree_fp32_entry, which refuses InRegs other than 0, 1).
  wire        valid0;
  wire [63:0] a0;

  pree_fp32_entry #(.InRegs(InRegs), .Width(64)) u_entry (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid_i), .d_i ({a_i}),
    .valid_o (valid0), .q_o ({a0})
  );

  // ---------------------------------------------------------------- A1: per-byte counts
  // Byte 7 is the most significant (a0[63:56]).
  wire [31:0] byte_lz;                             // 4 bits per byte: 0 .. 8
  wire [7:0]  byte_nz;

  genvar g;
  generate
    for (g = 0; g < 8; g = g + 1) begin : g_byte
      pree_fp32_lzc #(.Width(8), .CntWidth(4)) u_lzc (
        .x_i   (a0[8*g +: 8]),
        .cnt_o (byte_lz[4*g +: 4])
      );
      assign byte_nz[g] = (a0[8*g +: 8] != 8'd0);
    end
  endgenerate

  wire        s1_valid;
  wire [63:0] s1_a;
  wire [31:0] s1_byte_lz;
  wire [7:0]  s1_byte_nz;

  pree_fp32_pipe #(.Width(64 + 32 + 8), .Regs(seam_regs(1))) u_seam1 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (valid0),
    .d_i   ({a0, byte_lz, byte_nz}),
    .valid_o (s1_valid), .q_o ({s1_a, s1_byte_lz, s1_byte_nz})
  );

  // ---------------------------------------------------------------- A2: the count
  // The first non-zero byte from the top (its index from the top: 0 .. 7; 8 for a = 0) and
  // the count within it (0 .. 7: the byte is not zero).
  wire [3:0] first;
  pree_fp32_lzc #(.Width(8), .CntWidth(4)) u_lzc_bytes (
    .x_i   (s1_byte_nz),
    .cnt_o (first)
  );
  wire [2:0] first_byte = 3'd7 - first[2:0];      // its position (a = 0: unused)
  wire [2:0] byte_cnt   = s1_byte_lz[4*first_byte +: 3];
  // 64 for a = 0; else 8 * first + the count within the byte.
  wire [6:0] lz         = first[3] ? 7'd64 : {1'b0, first[2:0], byte_cnt};

  wire        s2_valid;
  wire [63:0] s2_a;
  wire [6:0]  s2_lz;

  pree_fp32_pipe #(.Width(64 + 7), .Regs(seam_regs(2))) u_seam2 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s1_valid),
    .d_i   ({s1_a, lz}),
    .valid_o (s2_valid), .q_o ({s2_a, s2_lz})
  );

  // ---------------------------------------------------------------- B1: byte shift
  wire [63:0] coarse = s2_a << {s2_lz[5:3], 3'd0};    // a = 0: lz[5:0] = 0

  wire        s3_valid;
  wire [63:0] s3_coarse;
  wire [6:0]  s3_lz;

  pree_fp32_pipe #(.Width(64 + 7), .Regs(seam_regs(3))) u_seam3 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s2_valid),
    .d_i   ({coarse, s2_lz}),
    .valid_o (s3_valid), .q_o ({s3_coarse, s3_lz})
  );

  // ---------------------------------------------------------------- B2: bit shift, sticky
  wire [63:0] norm   = s3_coarse << s3_lz[2:0];
  wire [9:0]  exp    = 10'd190 - {3'd0, s3_lz};       // 63 - lz + 127 (a = 0: 126, unused)
  wire [26:0] man    = norm[63:37];                   // 24 bits, guard, 2 more
  wire        sticky = (norm[36:0] != 37'd0);

  wire        s4_valid;
  wire [9:0]  s4_exp;
  wire [26:0] s4_man;
  wire        s4_sticky;

  pree_fp32_pipe #(.Width(10 + 27 + 1), .Regs(seam_regs(4))) u_seam4 (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s3_valid),
    .d_i   ({exp, man, sticky}),
    .valid_o (s4_valid), .q_o ({s4_exp, s4_man, s4_sticky})
  );

  // ---------------------------------------------------------------- C: round and pack
  // (pree_fp32_final with no special result: a count has none.)
  pree_fp32_final #(.Regs(seam_regs(5))) u_final (
    .clk_i (clk_i), .rst_ni (rst_ni), .valid_i (s4_valid),
    .special_i (1'b0), .special_y_i (32'd0), .sign_i (1'b0),
    .exp_i (s4_exp), .man_i (s4_man), .sticky_i (s4_sticky),
    .valid_o (valid_o), .y_o (y_o)
  );

endmodule
