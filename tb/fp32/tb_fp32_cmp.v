// SPDX-License-Identifier: Apache-2.0
// tb_fp32_cmp: self-checking Icarus/Verilog-2005 testbench for the combinational comparator.
//
// Run: vvp -N <sim> +vec=<file>; the vector file comes from fp32_vecgen cmp ("a b 0 flags" in hex
// per line, flags = {unordered, eq, le, lt}). Each vector is applied, the outputs settle, and
// the four flags are compared. Prints the first 20 mismatches; ends with $fatal on any error.
`default_nettype none

module tb_fp32_cmp;

  localparam MAX_REPORT = 20;

  reg  [31:0] a;
  reg  [31:0] b;
  wire        lt, le, eq, unordered;

  pree_fp32_cmp dut (.a_i(a), .b_i(b), .lt_o(lt), .le_o(le), .eq_o(eq), .unordered_o(unordered));

  reg [8*1024-1:0] vec_file;
  integer    fd, nread, vectors, errors;
  reg [31:0] va, vb, vs, vy;

  initial begin
    vectors = 0; errors = 0;
    if (!$value$plusargs("vec=%s", vec_file)) $fatal(1, "tb_fp32_cmp: +vec=<file> missing");
    fd = $fopen(vec_file, "r");
    if (fd == 0) $fatal(1, "tb_fp32_cmp: cannot open %0s", vec_file);
    nread = $fscanf(fd, "%h %h %h %h\n", va, vb, vs, vy);
    while (nread == 4) begin
      a = va; b = vb;
      #1;
      vectors = vectors + 1;
      if ({unordered, eq, le, lt} !== vy[3:0]) begin
        errors = errors + 1;
        if (errors <= MAX_REPORT)
          $display("MISMATCH cmp: a=%08h b=%08h expected=%01h got=%01h (unordered eq le lt)",
                   va, vb, vy[3:0], {unordered, eq, le, lt});
      end
      nread = $fscanf(fd, "%h %h %h %h\n", va, vb, vs, vy);
    end
    $fclose(fd);
    $display("tb_fp32_cmp: %0d vectors, %0d mismatches", vectors, errors);
    if (errors != 0 || vectors == 0) $fatal(1, "tb_fp32_cmp: FAILED");
    $finish;
  end

endmodule
