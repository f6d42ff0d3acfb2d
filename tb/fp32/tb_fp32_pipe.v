// SPDX-License-Identifier: Apache-2.0
// tb_fp32_pipe: self-checking Icarus/Verilog-2005 testbench for one pipelined binary32 unit, or
// one of the stable datapath's pree_wacc and pree_u64_to_f32 (64-bit a; 64-bit y for wacc).
//
// The unit is chosen at compile time: -DUNIT_ADD, -DUNIT_MUL, -DUNIT_SQR, -DUNIT_DIV, -DUNIT_WACC
// or -DUNIT_U2F. Any unit's configuration: -DUNIT_PIPEFAST=1 (its PipeFast parameter),
// -DUNIT_STAGES=N (its Stages parameter), and -DUNIT_LATENCY=L, the latency that the testbench
// requires (mk/fp32.mk passes the three, from config/pree_config.json); without UNIT_LATENCY, the
// latency is the configuration's Stages (rtl/pree_unit_stages.vh: compile with -Irtl).
// Operand a and the result are handled as 64 bits; the 32-bit units use the low half
// (and the vector file's fields are as wide as the unit's).
// Run: vvp -N <sim> +vec=<file> [+seed=<n>]; the vector file comes from fp32_vecgen
// ("a b sub expected" in hex per line). Operations enter with random gaps in valid_i; each
// accepted operation's expected result goes into a FIFO and is compared, bit for bit, when
// valid_o appears, which must be exactly LATENCY cycles after the operation entered.
// Prints the first 20 mismatches in hex with their inputs; ends with $fatal on any error.
`default_nettype none

module tb_fp32_pipe;

// The unit's parameters: PipeFast, and Stages when given (0: the unit's default).
`ifndef UNIT_PIPEFAST
`define UNIT_PIPEFAST 0
`endif
`ifdef UNIT_STAGES
`define UNIT_PARAMS #(.PipeFast(`UNIT_PIPEFAST), .Stages(`UNIT_STAGES))
  localparam STAGES = `UNIT_STAGES;
`else
`define UNIT_PARAMS #(.PipeFast(`UNIT_PIPEFAST))
  localparam STAGES = 0;
`endif

`include "pree_unit_stages.vh"
`ifdef UNIT_ADD
  localparam KIND = PREU_ADD;
  localparam NAME = "add";
  localparam AW = 32, YW = 32;   // widths of a and y
`elsif UNIT_MUL
  localparam KIND = PREU_MUL;
  localparam NAME = "mul";
  localparam AW = 32, YW = 32;
`elsif UNIT_SQR
  localparam KIND = PREU_SQR;
  localparam NAME = "sqr";
  localparam AW = 32, YW = 32;
`elsif UNIT_DIV
  localparam KIND = PREU_DIV;
  localparam NAME = "div";
  localparam AW = 32, YW = 32;
`elsif UNIT_WACC
  localparam KIND = PREU_WACC;
  localparam NAME = "wacc";
  localparam AW = 64, YW = 64;
`elsif UNIT_U2F
  localparam KIND = PREU_U2F;
  localparam NAME = "u2f";
  localparam AW = 64, YW = 32;
`endif
`ifdef UNIT_LATENCY
  localparam LATENCY = `UNIT_LATENCY;   // the configuration's latency (mk/fp32.mk)
`else
  localparam LATENCY = preu_stages(KIND, `UNIT_PIPEFAST, STAGES);   // the configuration's Stages
`endif
  localparam FIFO = 64;       // > LATENCY: room for every operation in flight
  localparam MAX_REPORT = 20;

  reg         clk;
  reg         rst_n;
  reg         valid_in;
  reg  [63:0] a;
  reg  [31:0] b;
  reg         sub;
  wire        valid_out;
  wire [63:0] y;

`ifdef UNIT_ADD
  pree_fp32_add `UNIT_PARAMS dut (.clk_i(clk), .rst_ni(rst_n), .valid_i(valid_in), .a_i(a[31:0]), .b_i(b),
                     .sub_i(sub), .valid_o(valid_out), .y_o(y[31:0]));
`elsif UNIT_MUL
  pree_fp32_mul `UNIT_PARAMS dut (.clk_i(clk), .rst_ni(rst_n), .valid_i(valid_in), .a_i(a[31:0]), .b_i(b),
                     .valid_o(valid_out), .y_o(y[31:0]));
`elsif UNIT_SQR
  pree_fp32_sqr `UNIT_PARAMS dut (.clk_i(clk), .rst_ni(rst_n), .valid_i(valid_in), .a_i(a[31:0]),
                     .valid_o(valid_out), .y_o(y[31:0]));
`elsif UNIT_DIV
  pree_fp32_div `UNIT_PARAMS dut (.clk_i(clk), .rst_ni(rst_n), .valid_i(valid_in), .a_i(a[31:0]), .b_i(b),
                     .valid_o(valid_out), .y_o(y[31:0]));
`elsif UNIT_WACC
  pree_wacc `UNIT_PARAMS dut (.clk_i(clk), .rst_ni(rst_n), .valid_i(valid_in), .a_i(a), .t_i(b),
                 .valid_o(valid_out), .y_o(y));
`elsif UNIT_U2F
  pree_u64_to_f32 `UNIT_PARAMS dut (.clk_i(clk), .rst_ni(rst_n), .valid_i(valid_in), .a_i(a),
                       .valid_o(valid_out), .y_o(y[31:0]));
`endif
`ifndef UNIT_WACC
  assign y[63:32] = 32'd0;   // the 32-bit results, compared as 64 bits
`endif

  // Scoreboard FIFO of operations in flight.
  reg [63:0] q_a   [0:FIFO-1];
  reg [31:0] q_b   [0:FIFO-1];
  reg        q_sub [0:FIFO-1];
  reg [63:0] q_y   [0:FIFO-1];
  reg [63:0] q_cyc [0:FIFO-1];
  integer    wr, rd;

  reg [8*1024-1:0] vec_file;
  integer    fd, nread, seed, density;
  reg [63:0] va, vy;
  reg [31:0] vb, vs;
  reg        have_vec;
  reg [63:0] cycle;
  integer    vectors, checked, errors;

  always #5 clk = ~clk;

  // Read the next vector into va, vb, vs, vy; have_vec = 0 at the end of the file.
  task next_vector;
    begin
      nread = $fscanf(fd, "%h %h %h %h\n", va, vb, vs, vy);
      have_vec = (nread == 4);
    end
  endtask

  initial begin
    clk = 1'b0; rst_n = 1'b0; valid_in = 1'b0; a = 32'd0; b = 32'd0; sub = 1'b0;
    wr = 0; rd = 0; cycle = 64'd0; vectors = 0; checked = 0; errors = 0; density = 16;
    if (!$value$plusargs("vec=%s", vec_file)) $fatal(1, "tb_fp32_pipe: +vec=<file> missing");
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    fd = $fopen(vec_file, "r");
    if (fd == 0) $fatal(1, "tb_fp32_pipe: cannot open %0s", vec_file);
    next_vector;

    repeat (3) @(posedge clk);
    #1 rst_n = 1'b1;

    while (have_vec || wr != rd) begin
      // Drive between edges: issue the next vector with the current density (in 1/16).
      @(negedge clk);
      if (cycle % 256 == 0) density = 1 + ({$random(seed)} % 16);
      if (have_vec && ({$random(seed)} % 16) < density) begin
        valid_in = 1'b1; a = va; b = vb; sub = vs[0];
        q_a[wr % FIFO] = va; q_b[wr % FIFO] = vb; q_sub[wr % FIFO] = vs[0];
        q_y[wr % FIFO] = vy; q_cyc[wr % FIFO] = cycle;
        wr = wr + 1; vectors = vectors + 1;
        next_vector;
      end else begin
        valid_in = 1'b0; a = {$random(seed), $random(seed)}; b = $random(seed); sub = $random(seed);
      end

      @(posedge clk);
      cycle = cycle + 1;
      #1;
      if (wr != rd && q_cyc[rd % FIFO] + LATENCY == cycle) begin
        if (!valid_out) begin
          $display("MISMATCH %0s: valid_o missing %0d cycles after a=%h b=%08h",
                   NAME, LATENCY, q_a[rd % FIFO][AW-1:0], q_b[rd % FIFO]);
          $fatal(1, "tb_fp32_pipe %0s: handshake error", NAME);
        end
        checked = checked + 1;
        if (y !== q_y[rd % FIFO]) begin
          errors = errors + 1;
          if (errors <= MAX_REPORT)
            $display("MISMATCH %0s: a=%h b=%08h sub=%0d expected=%h got=%h", NAME,
                     q_a[rd % FIFO][AW-1:0], q_b[rd % FIFO], q_sub[rd % FIFO],
                     q_y[rd % FIFO][YW-1:0], y[YW-1:0]);
        end
        rd = rd + 1;
      end else if (valid_out) begin
        $fatal(1, "tb_fp32_pipe %0s: valid_o without an operation due", NAME);
      end
    end

    $fclose(fd);
    $display("tb_fp32_pipe %0s (latency %0d): %0d vectors, %0d checked, %0d mismatches",
             NAME, LATENCY, vectors, checked, errors);
    if (errors != 0 || checked != vectors || vectors == 0)
      $fatal(1, "tb_fp32_pipe %0s: FAILED", NAME);
    $finish;
  end

endmodule
