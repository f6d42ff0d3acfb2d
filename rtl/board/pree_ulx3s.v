// SPDX-License-Identifier: Apache-2.0
// pree_ulx3s: PREE on the ULX3S board (Lattice ECP5 LFE5U-85F, CABGA381; pins in
// constraints/pree_ulx3s.lpf). The 25 MHz board clock feeds an EHXPLLL whose CLKOP is the core
// clock (25 MHz x PllFbDiv / PllInDiv; the VCO, CLKOP x PllOpDiv, must lie in 400..800 MHz); the
// whole design runs on it. pree_axi's streams are hundreds of bits wide, so the host reaches it
// through pree_uart_bridge (pree_uart_axi) on the board's FTDI UART (ftdi_txd in, ftdi_rxd out, Baud bits a
// second, 8N1; the protocol is in that file's header): AXI4-Lite register writes and reads,
// beats pushed into s_axis_ph, s_axis_cand and s_axis_hp, and every m_axis beat sent back.
// Reset: until the PLL locks, and while the PWR button (active low) is held.
// LEDs: led[0] PLL locked, led[1] pree_axi's irq_o, led[2] bridge overrun (a byte came while a
// command ran), led[3] a heartbeat (about 1.5 Hz at 100 MHz).
// Parameters: pree_axi's configuration (its header), the PLL's dividers, the baud rate.
`default_nettype none

module pree_ulx3s #(
  parameter NumPreu  = 2,
  parameter HpAW     = 12,
  parameter HpBankW  = 3,
  parameter IdxAW    = 12,
  parameter PxAW     = 12,
  parameter PxBankW  = 2,
  parameter CntW     = 16,
  parameter Datapath = 0,
  parameter PipeFast = 1,
  parameter PllInDiv = 1,
  parameter PllFbDiv = 4,
  parameter PllOpDiv = 6,
  parameter Baud     = 1000000
) (
  input  wire       clk_25mhz,
  input  wire       btn_pwr_n,
  input  wire       ftdi_txd,
  output wire       ftdi_rxd,
  output wire [3:0] led
);

  localparam ClkHz  = 25000000 / PllInDiv * PllFbDiv;

  wire       clk, locked;
  wire [5:0] pll_unused;   // the PLL's other outputs
  EHXPLLL #(
    .PLLRST_ENA("DISABLED"), .INTFB_WAKE("DISABLED"), .STDBY_ENABLE("DISABLED"),
    .DPHASE_SOURCE("DISABLED"), .OUTDIVIDER_MUXA("DIVA"), .OUTDIVIDER_MUXB("DIVB"),
    .OUTDIVIDER_MUXC("DIVC"), .OUTDIVIDER_MUXD("DIVD"), .CLKI_DIV(PllInDiv),
    .CLKOP_ENABLE("ENABLED"), .CLKOP_DIV(PllOpDiv), .CLKOP_CPHASE(PllOpDiv / 2 - 1),
    .CLKOP_FPHASE(0), .FEEDBK_PATH("CLKOP"), .CLKFB_DIV(PllFbDiv)
  ) u_pll (
    .RST(1'b0), .STDBY(1'b0), .CLKI(clk_25mhz), .CLKOP(clk), .CLKFB(clk), .CLKINTFB(pll_unused[0]),
    .PHASESEL0(1'b0), .PHASESEL1(1'b0), .PHASEDIR(1'b1), .PHASESTEP(1'b1),
    .PHASELOADREG(1'b1), .PLLWAKESYNC(1'b0), .ENCLKOP(1'b0), .ENCLKOS(1'b0), .ENCLKOS2(1'b0),
    .ENCLKOS3(1'b0), .CLKOS(pll_unused[1]), .CLKOS2(pll_unused[2]), .CLKOS3(pll_unused[3]),
    .INTLOCK(pll_unused[4]), .REFCLK(pll_unused[5]), .LOCK(locked));

  wire arst_n = locked & btn_pwr_n;
  wire rst_n;
  pree_reset_sync #(.Stages(2)) u_rst (.clk_i(clk), .arst_ni(arst_n), .rst_no(rst_n));

  wire irq, overrun;
  pree_uart_axi #(
    .NumPreu(NumPreu), .HpAW(HpAW), .HpBankW(HpBankW), .IdxAW(IdxAW), .PxAW(PxAW),
    .PxBankW(PxBankW), .CntW(CntW), .Datapath(Datapath), .PipeFast(PipeFast),
    .Div(ClkHz / Baud)
  ) u_link (
    .clk_i(clk), .rst_ni(rst_n), .rx_i(ftdi_txd), .tx_o(ftdi_rxd), .overrun_o(overrun),
    .irq_o(irq));

  reg [26:0] beat_q;
  always @(posedge clk) beat_q <= rst_n ? beat_q + 27'd1 : 27'd0;

  assign led = {beat_q[26], overrun, irq, locked};

endmodule
