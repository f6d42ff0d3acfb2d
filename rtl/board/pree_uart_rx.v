// SPDX-License-Identifier: Apache-2.0
// pree_uart_rx: UART receiver, 8 data bits, no parity, one stop bit (8N1), LSB first, idle high.
// Div clock cycles a bit (clock / baud rate, at least 4). The input passes two synchronising
// flip-flops; a start bit is a low level seen while idle, checked again half a bit later; the data
// bits are sampled in their middle. A byte whose stop bit is low (a framing error) is dropped.
// valid_o is high for one cycle with data_o.
`default_nettype none

module pree_uart_rx #(
  parameter Div = 100
) (
  input  wire       clk_i,
  input  wire       rst_ni,
  input  wire       rx_i,
  output reg  [7:0] data_o,
  output reg        valid_o
);

  localparam CW = $clog2(Div + 1);
  localparam [31:0] BIT32 = Div - 1, HALF32 = Div / 2 - 1;
  localparam [CW-1:0] BIT  = BIT32[CW-1:0];    // a bit's last count
  localparam [CW-1:0] HALF = HALF32[CW-1:0];  // half a bit's

  reg [1:0]    sync_q;
  reg          busy_q;
  reg [CW-1:0] cnt_q;
  reg [3:0]    bit_q;     // 0: start bit, 1..8: data bits, 9: stop bit
  reg [7:0]    sh_q;
  wire         rx = sync_q[1];

  always @(posedge clk_i) begin
    valid_o <= 1'b0;
    if (!rst_ni) begin
      sync_q <= 2'b11;
      busy_q <= 1'b0;
      cnt_q  <= {CW{1'b0}};
      bit_q  <= 4'd0;
      sh_q   <= 8'd0;
      data_o <= 8'd0;
    end else begin
      sync_q <= {sync_q[0], rx_i};
      if (!busy_q) begin
        if (!rx) begin
          busy_q <= 1'b1;
          cnt_q  <= HALF;
          bit_q  <= 4'd0;
        end
      end else if (cnt_q != {CW{1'b0}}) begin
        cnt_q <= cnt_q - 1'b1;
      end else begin
        cnt_q <= BIT;
        bit_q <= bit_q + 4'd1;
        if (bit_q == 4'd0) begin
          if (rx) busy_q <= 1'b0;                  // a glitch, not a start bit
        end else if (bit_q != 4'd9) begin
          sh_q <= {rx, sh_q[7:1]};
        end else begin
          busy_q <= 1'b0;
          if (rx) begin
            data_o  <= sh_q;
            valid_o <= 1'b1;
          end
        end
      end
    end
  end

endmodule
