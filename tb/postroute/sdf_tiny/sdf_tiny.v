// SPDX-License-Identifier: Apache-2.0
// sdf_tiny: the small design of the timing-annotated post-route check
// (tests/checks/postroute_sdf.sh; docs/fpga_board.md, "Timing-annotated run"), with the board
// top's ports (pree_ulx3s: clk_25mhz, btn_pwr_n, ftdi_txd, ftdi_rxd, led) so that the same replay
// bench drives it. The board's UART (rtl/board/, 25 clock cycles a bit) receives a byte b; the
// next cycle adds the 16 x 16 product {b, b} * {b, ~b} (a MULT18X18D without registers) to a
// 32-bit sum (a carry chain): a one-cycle path through the multiplier and the carry chain that a
// too-short clock period breaks. The same product also goes through a MULT18X18D that registers
// its inputs and its product (rtl/pree_fp32_dsp_mul.v under PREE_ECP5_DSP, as in the PREU) into
// a second sum, so that the clock-to-product delays are annotated too. The reply, once both sums
// hold the byte: sum[23:16] ^ sum2[15:8] ^ b.
`default_nettype none

module sdf_tiny (
  input  wire       clk_25mhz,
  input  wire       btn_pwr_n,
  input  wire       ftdi_txd,
  output wire       ftdi_rxd,
  output wire [3:0] led
);
  wire       clk = clk_25mhz;
  wire       rst_n, rx_valid, tx_ready;
  wire [7:0] rx_data;
  reg        add_q, prod_q, add2_q, send_q;
  reg [7:0]  b_q;
  reg [31:0] sum_q, sum2_q;
  wire [31:0] p_reg;

  pree_reset_sync #(.Stages(2)) u_rst (.clk_i(clk), .arst_ni(btn_pwr_n), .rst_no(rst_n));
  pree_uart_rx #(.Div(25)) u_rx (.clk_i(clk), .rst_ni(rst_n), .rx_i(ftdi_txd), .data_o(rx_data),
                                 .valid_o(rx_valid));

  always @(posedge clk) begin
    if (!rst_n) begin
      add_q  <= 1'b0;
      prod_q <= 1'b0;
      add2_q <= 1'b0;
      send_q <= 1'b0;
      b_q    <= 8'd0;
      sum_q  <= 32'd0;
      sum2_q <= 32'd0;
    end else begin
      add_q  <= rx_valid;
      prod_q <= add_q;
      add2_q <= prod_q;
      send_q <= add2_q;
      if (rx_valid) b_q <= rx_data;
      if (add_q) sum_q <= sum_q + {b_q, b_q} * {b_q, ~b_q};
      if (add2_q) sum2_q <= sum2_q + p_reg;
    end
  end

  // Operands taken at add_q's edge, the product at prod_q's.
  pree_fp32_dsp_mul #(.AW(16), .BW(16)) u_mul_reg (
      .clk_i(clk), .in_en_i(add_q), .a_i({b_q, b_q}), .b_i({b_q, ~b_q}), .out_en_i(prod_q),
      .p_o(p_reg));

  pree_uart_tx #(.Div(25)) u_tx (.clk_i(clk), .rst_ni(rst_n),
                                 .data_i(sum_q[23:16] ^ sum2_q[15:8] ^ b_q),
                                 .valid_i(send_q), .ready_o(tx_ready), .tx_o(ftdi_rxd));

  assign led = {tx_ready, send_q, add_q, rst_n};
endmodule
