// SPDX-License-Identifier: Apache-2.0
// pree_uart_bridge: a host link to pree_axi over one UART: the host writes and reads the
// AXI4-Lite registers, pushes beats into the three input streams, and receives every m_axis beat.
//
// Host to bridge: a command byte, then its payload, most significant byte first:
//   'W' (0x57)  6 bytes: address (16 bits, the low 12 used), data (32 bits); an AXI4-Lite write
//               with all byte strobes. Reply 'b' (OKAY) or 'e' (an error response).
//   'R' (0x52)  2 bytes: address. Reply 'r' or 'e', then the 32 read data bits (4 bytes).
//   'P' (0x50)  32 bytes: a photon beat of s_axis_ph (one 256-bit slot), TLAST low; 'L' (0x4C) the same
//               with TLAST high. Reply 'a' once the stream has taken it.
//   'C' (0x43)  4.5 NumPreu bytes rounded up: {tkeep (4 NumPreu bits), tdata (32 NumPreu bits)}
//               of s_axis_cand, zero-padded at the top to whole bytes. Reply 'a'.
//   'H' (0x48)  HpRecW / 8 bytes: a hit-point record for s_axis_hp. Reply 'a'.
//   any other byte: reply '?' (the host has lost the framing).
// Every command has exactly one reply; the host sends the next command only after it. Bytes that
// arrive while a command runs or waits for its reply are dropped and set overrun_o (sticky until
// reset). Bridge to host, between replies: every m_axis beat as a byte 0x80 | {TLAST, TUSER}
// followed by its HpRecW / 8 data bytes. Div: clock cycles per UART bit (clock / baud rate).
`default_nettype none

module pree_uart_bridge #(
  parameter NumPreu = 2,
  parameter HpRecW  = 384,
  parameter Div     = 100
) (
  input  wire                      clk_i,
  input  wire                      rst_ni,
  input  wire                      rx_i,
  output wire                      tx_o,
  output reg                       overrun_o,
  // AXI4-Lite master.
  output wire [11:0]               m_axil_awaddr,
  output wire                      m_axil_awvalid,
  input  wire                      m_axil_awready,
  output wire [31:0]               m_axil_wdata,
  output wire [3:0]                m_axil_wstrb,
  output wire                      m_axil_wvalid,
  input  wire                      m_axil_wready,
  input  wire [1:0]                m_axil_bresp,
  input  wire                      m_axil_bvalid,
  output wire                      m_axil_bready,
  output wire [11:0]               m_axil_araddr,
  output wire                      m_axil_arvalid,
  input  wire                      m_axil_arready,
  input  wire [31:0]               m_axil_rdata,
  input  wire [1:0]                m_axil_rresp,
  input  wire                      m_axil_rvalid,
  output wire                      m_axil_rready,
  // Streams into pree_axi.
  output wire [255:0]              ph_tdata,
  output wire                      ph_tlast,
  output wire                      ph_tvalid,
  input  wire                      ph_tready,
  output wire [32*NumPreu-1:0]     cand_tdata,
  output wire [4*NumPreu-1:0]      cand_tkeep,
  output wire                      cand_tvalid,
  input  wire                      cand_tready,
  output wire [HpRecW-1:0]         hp_tdata,
  output wire                      hp_tvalid,
  input  wire                      hp_tready,
  // Results out of pree_axi.
  input  wire [HpRecW-1:0]         m_tdata,
  input  wire                      m_tuser,
  input  wire                      m_tlast,
  input  wire                      m_tvalid,
  output wire                      m_tready
);

  localparam CandW = 36 * NumPreu;
  localparam BW0   = (HpRecW > 256) ? HpRecW : 256;
  localparam BW    = (CandW > BW0) ? CandW : BW0;      // the payload register
  localparam TW    = 8 + HpRecW;                        // the reply register: a byte + a beat
  localparam [7:0] OP_W = 8'h57, OP_R = 8'h52, OP_P = 8'h50, OP_L = 8'h4c, OP_C = 8'h43,
                   OP_H = 8'h48;
  localparam [31:0] CAND_B = (CandW + 7) / 8, HP_B = HpRecW / 8;
  localparam [7:0] CAND_BYTES = CAND_B[7:0], HP_BYTES = HP_B[7:0];
  localparam [6:0] BEAT_BYTES = HP_B[6:0] + 7'd1;       // a stream beat with its byte
  localparam [1:0] S_CMD = 2'd0, S_DATA = 2'd1, S_EXEC = 2'd2, S_REPLY = 2'd3;

  // Payload bytes of a command, 0 for an unknown byte.
  function [7:0] payload_bytes;
    input [7:0] op;
    begin
      case (op)
        OP_W:       payload_bytes = 8'd6;
        OP_R:       payload_bytes = 8'd2;
        OP_P, OP_L: payload_bytes = 8'd32;
        OP_C:       payload_bytes = CAND_BYTES;
        OP_H:       payload_bytes = HP_BYTES;
        default:    payload_bytes = 8'd0;
      endcase
    end
  endfunction

  wire [7:0] rx_data;
  wire       rx_valid;
  pree_uart_rx #(.Div(Div)) u_rx (.clk_i(clk_i), .rst_ni(rst_ni), .rx_i(rx_i),
                                  .data_o(rx_data), .valid_o(rx_valid));

  reg  [1:0]    st_q;
  reg  [7:0]    op_q;
  reg  [7:0]    need_q;          // payload bytes still to come
  reg  [BW-1:0] pay_q;           // the payload, shifted in from the low end
  reg           aw_done_q, w_done_q, ar_done_q;
  reg  [39:0]   reply_q;         // {reply byte, read data}
  reg  [2:0]    reply_n_q;       // its bytes: 1 or 5
  reg  [TW-1:0] tx_q;            // bytes to send, from the top
  reg  [6:0]    tx_n_q;          // bytes left in tx_q
  wire          tx_ready;

  wire exec = (st_q == S_EXEC);
  wire is_w = (op_q == OP_W), is_r = (op_q == OP_R), is_c = (op_q == OP_C), is_h = (op_q == OP_H);
  wire is_p = (op_q == OP_P) || (op_q == OP_L);

  assign m_axil_awaddr  = pay_q[43:32];
  assign m_axil_wdata   = pay_q[31:0];
  assign m_axil_wstrb   = 4'hf;
  assign m_axil_awvalid = exec && is_w && !aw_done_q;
  assign m_axil_wvalid  = exec && is_w && !w_done_q;
  assign m_axil_bready  = exec && is_w && aw_done_q && w_done_q;
  assign m_axil_araddr  = pay_q[11:0];
  assign m_axil_arvalid = exec && is_r && !ar_done_q;
  assign m_axil_rready  = exec && is_r && ar_done_q;
  assign ph_tdata    = pay_q[255:0];
  assign ph_tlast    = (op_q == OP_L);
  assign ph_tvalid   = exec && is_p;
  assign cand_tdata  = pay_q[32*NumPreu-1:0];
  assign cand_tkeep  = pay_q[32*NumPreu +: 4*NumPreu];
  assign cand_tvalid = exec && is_c;
  assign hp_tdata    = pay_q[HpRecW-1:0];
  assign hp_tvalid   = exec && is_h;

  // A stream beat goes to the host whenever nothing is being sent and no reply waits.
  assign m_tready = (tx_n_q == 7'd0) && (st_q != S_REPLY);

  wire stream_taken = (ph_tvalid && ph_tready) || (cand_tvalid && cand_tready) ||
                      (hp_tvalid && hp_tready);

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      st_q      <= S_CMD;
      op_q      <= 8'd0;
      need_q    <= 8'd0;
      pay_q     <= {BW{1'b0}};
      aw_done_q <= 1'b0;
      w_done_q  <= 1'b0;
      ar_done_q <= 1'b0;
      reply_q   <= 40'd0;
      reply_n_q <= 3'd0;
      overrun_o <= 1'b0;
    end else begin
      case (st_q)
        S_CMD: if (rx_valid) begin
          op_q   <= rx_data;
          need_q <= payload_bytes(rx_data);
          if (payload_bytes(rx_data) == 8'd0) begin
            reply_q   <= {8'h3f, 32'd0};
            reply_n_q <= 3'd1;
            st_q      <= S_REPLY;
          end else begin
            st_q <= S_DATA;
          end
        end
        S_DATA: if (rx_valid) begin
          pay_q  <= {pay_q[BW-9:0], rx_data};
          need_q <= need_q - 8'd1;
          if (need_q == 8'd1) begin
            aw_done_q <= 1'b0;
            w_done_q  <= 1'b0;
            ar_done_q <= 1'b0;
            st_q      <= S_EXEC;
          end
        end
        S_EXEC: begin
          if (m_axil_awvalid && m_axil_awready) aw_done_q <= 1'b1;
          if (m_axil_wvalid && m_axil_wready)   w_done_q  <= 1'b1;
          if (m_axil_arvalid && m_axil_arready) ar_done_q <= 1'b1;
          if (m_axil_bready && m_axil_bvalid) begin
            reply_q   <= {(m_axil_bresp == 2'b00) ? 8'h62 : 8'h65, 32'd0};
            reply_n_q <= 3'd1;
            st_q      <= S_REPLY;
          end
          if (m_axil_rready && m_axil_rvalid) begin
            reply_q   <= {(m_axil_rresp == 2'b00) ? 8'h72 : 8'h65, m_axil_rdata};
            reply_n_q <= 3'd5;
            st_q      <= S_REPLY;
          end
          if (stream_taken) begin
            reply_q   <= {8'h61, 32'd0};
            reply_n_q <= 3'd1;
            st_q      <= S_REPLY;
          end
        end
        default: if (tx_n_q == 7'd0) st_q <= S_CMD;   // S_REPLY: tx_q takes the reply
      endcase
      if (rx_valid && (st_q == S_EXEC || st_q == S_REPLY)) overrun_o <= 1'b1;
    end
  end

  // The sender: a reply or a stream beat is loaded at the top of tx_q and sent a byte at a time.
  always @(posedge clk_i) begin
    if (!rst_ni) begin
      tx_q   <= {TW{1'b0}};
      tx_n_q <= 7'd0;
    end else if (tx_n_q == 7'd0) begin
      if (st_q == S_REPLY) begin
        tx_q   <= {reply_q, {(TW-40){1'b0}}};
        tx_n_q <= {4'd0, reply_n_q};
      end else if (m_tvalid) begin
        tx_q   <= {6'b100000, m_tlast, m_tuser, m_tdata};
        tx_n_q <= BEAT_BYTES;
      end
    end else if (tx_ready) begin
      tx_q   <= {tx_q[TW-9:0], 8'd0};
      tx_n_q <= tx_n_q - 7'd1;
    end
  end

  pree_uart_tx #(.Div(Div)) u_tx (.clk_i(clk_i), .rst_ni(rst_ni), .data_i(tx_q[TW-1 -: 8]),
                                  .valid_i(tx_n_q != 7'd0), .ready_o(tx_ready), .tx_o(tx_o));

endmodule
