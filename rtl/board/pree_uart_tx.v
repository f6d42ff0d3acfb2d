// SPDX-License-Identifier: Apache-2.0
// pree_uart_tx: UART transmitter, 8N1, LSB first, idle high; Div clock cycles a bit (clock / baud
// rate). A byte is taken when valid_i and ready_o are both high; ready_o is high while nothing is
// being sent (the stop bit included).
`default_nettype none

module pree_uart_tx #(
  parameter Div = 100
) (
  input  wire       clk_i,
  input  wire       rst_ni,
  input  wire [7:0] data_i,
  input  wire       valid_i,
  output wire       ready_o,
  output wire       tx_o
);

  localparam CW = $clog2(Div + 1);
  localparam [31:0] BIT32 = Div - 1;
  localparam [CW-1:0] BIT  = BIT32[CW-1:0];    // a bit's last count

  reg [9:0]    sh_q;      // {stop, data, start}, sent from bit 0
  reg [3:0]    left_q;    // bits left to send
  reg [CW-1:0] cnt_q;

  assign ready_o = (left_q == 4'd0);
  assign tx_o    = sh_q[0];

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      sh_q   <= 10'h3ff;
      left_q <= 4'd0;
      cnt_q  <= {CW{1'b0}};
    end else if (left_q == 4'd0) begin
      if (valid_i) begin
        sh_q   <= {1'b1, data_i, 1'b0};
        left_q <= 4'd10;
        cnt_q  <= BIT;
      end
    end else if (cnt_q != {CW{1'b0}}) begin
      cnt_q <= cnt_q - 1'b1;
    end else begin
      sh_q   <= {1'b1, sh_q[9:1]};
      left_q <= left_q - 4'd1;
      cnt_q  <= BIT;
    end
  end

endmodule
