// SPDX-License-Identifier: Apache-2.0
// axi_wave_tb: the timing diagrams of docs/integration.md (docs/wave/*.json) replayed on pree_axi.
// Each scenario drives its diagram's stimulus and prints, for every cycle (sampled in the middle
// of the cycle), the rows of the diagram that are ports of pree_axi:
//   ROWS <diagram> <row> ...        the rows, in the order of the samples
//   SMP <diagram> <sample> ...      one cycle: a bit as 0, 1 or x; a bus as x while its stream
//                                   holds no beat, else the number of the beat it holds
// (to standard output, or to the file that +out=FILE names). scripts/wave_check.py turns them
// into WaveDrom waves and compares them with the JSON sources
// (a diagram's gap stands for the cycles between its first and its last part). Rows inside
// pree_axi (its engine intake, STATUS bits, HP_PTR, memory reads) are not recorded.
// Icarus (-g2005) and Verilator (--binary) print the same; NumPreu 4 as the diagrams, small
// memories.
`default_nettype none

module axi_wave_tb;
  localparam NP = 4;

  reg aclk = 1'b0;
  always #5 aclk = ~aclk;
  reg aresetn = 1'b0;

  reg  [11:0] awaddr = 12'd0, araddr = 12'd0;
  reg         awvalid = 1'b0, wvalid = 1'b0, bready = 1'b1, arvalid = 1'b0, rready = 1'b1;
  reg  [31:0] wdata = 32'd0;
  wire        awready, wready, bvalid, arready, rvalid;
  wire [1:0]  bresp, rresp;
  wire [31:0] rdata;
  reg  [255:0] ph_data = 256'd0;
  reg          ph_last = 1'b0, ph_valid = 1'b0;
  wire         ph_ready;
  reg  [32*NP-1:0] cand_data = {32*NP{1'b0}};
  reg  [4*NP-1:0]  cand_keep = {4*NP{1'b0}};
  reg              cand_valid = 1'b0;
  wire             cand_ready;
  reg  [383:0] hp_data = 384'd0;
  reg          hp_valid = 1'b0;
  wire         hp_ready;
  wire [383:0] m_data;
  wire         m_user, m_last, m_valid, irq;
  reg          m_ready = 1'b1;

  pree_axi #(.NumPreu(NP), .HpAW(6), .HpBankW(3), .IdxAW(6), .PxAW(4), .PxBankW(2)) dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axil_awaddr(awaddr), .s_axil_awvalid(awvalid), .s_axil_awready(awready),
    .s_axil_wdata(wdata), .s_axil_wstrb(4'hf), .s_axil_wvalid(wvalid), .s_axil_wready(wready),
    .s_axil_bresp(bresp), .s_axil_bvalid(bvalid), .s_axil_bready(bready),
    .s_axil_araddr(araddr), .s_axil_arvalid(arvalid), .s_axil_arready(arready),
    .s_axil_rdata(rdata), .s_axil_rresp(rresp), .s_axil_rvalid(rvalid), .s_axil_rready(rready),
    .s_axis_ph_tdata(ph_data), .s_axis_ph_tlast(ph_last), .s_axis_ph_tvalid(ph_valid),
    .s_axis_ph_tready(ph_ready),
    .s_axis_cand_tdata(cand_data), .s_axis_cand_tkeep(cand_keep), .s_axis_cand_tvalid(cand_valid),
    .s_axis_cand_tready(cand_ready),
    .s_axis_hp_tdata(hp_data), .s_axis_hp_tvalid(hp_valid), .s_axis_hp_tready(hp_ready),
    .m_axis_tdata(m_data), .m_axis_tuser(m_user), .m_axis_tlast(m_last), .m_axis_tvalid(m_valid),
    .m_axis_tready(m_ready), .irq_o(irq));

  // Beats taken so far on each channel: a bus row shows the beat its channel holds.
  integer ph_n = 0, cand_n = 0, hp_n = 0, m_n = 0, aw_n = 0, ar_n = 0, r_n = 0;
  always @(posedge aclk) begin
    if (ph_valid && ph_ready)     ph_n   <= ph_n + 1;
    if (cand_valid && cand_ready) cand_n <= cand_n + 1;
    if (hp_valid && hp_ready)     hp_n   <= hp_n + 1;
    if (m_valid && m_ready)       m_n    <= m_n + 1;
    if (awvalid && awready)       aw_n   <= aw_n + 1;
    if (arvalid && arready)       ar_n   <= ar_n + 1;
    if (rvalid && rready)         r_n    <= r_n + 1;
  end

  // Where the lines go: standard output, or +out=FILE.
  integer fd = 32'h8000_0001;
  reg [8*256-1:0] out_name;
  initial if ($value$plusargs("out=%s", out_name)) begin
    fd = $fopen(out_name, "w");
    if (fd == 0) $fatal(1, "axi_wave_tb: cannot write %0s", out_name);
  end

  // One cycle's samples of the current diagram, printed in the middle of the cycle.
  reg [8*16-1:0] diagram = "";
  integer scen = 0;
  task put_bus;   // a bus sample: x without a beat, else the beat number
    input held; input integer n;
    begin
      if (held) $fwrite(fd, " b%0d", n); else $fwrite(fd, " x");
    end
  endtask
  task put_bit;
    input v;
    begin
      $fwrite(fd, " %b", v);
    end
  endtask
  always @(negedge aclk) if (scen != 0) begin
    $fwrite(fd, "SMP %0s", diagram);
    case (scen)
      1: begin   // stream_hp
        put_bit(hp_valid); put_bus(hp_valid, hp_n); put_bit(hp_ready);
      end
      2: begin   // stream_ph_cand
        put_bit(ph_valid); put_bus(ph_valid, ph_n); put_bit(ph_last); put_bit(ph_ready);
        put_bit(cand_valid); put_bus(cand_valid && &cand_keep[3:0], cand_n);
        put_bus(cand_valid && &cand_keep[7:4], cand_n); put_bus(cand_valid && &cand_keep[11:8], cand_n);
        put_bus(cand_valid && &cand_keep[15:12], cand_n); put_bus(cand_valid, cand_n); put_bit(cand_ready);
        put_bit(irq);
      end
      3: begin   // stream_m
        put_bus(awvalid && wvalid, aw_n); put_bit(m_valid); put_bus(m_valid, m_n); put_bit(m_user); put_bit(m_last);
        put_bit(m_ready); put_bit(irq);
      end
      4: begin   // axil_cmd
        put_bit(awvalid); put_bus(awvalid, aw_n); put_bit(wvalid); put_bus(wvalid, aw_n); put_bit(awready && wready);
        put_bit(bvalid); put_bit(bready); put_bit(arvalid); put_bus(arvalid, ar_n); put_bit(arready); put_bit(rvalid);
        put_bus(rvalid, r_n); put_bit(rready); put_bit(irq);
      end
      default: ;
    endcase
    $fwrite(fd, "\n");
  end

  // Stimulus: inputs change just after a rising edge.
  task cycle; begin @(posedge aclk); #1; end endtask
  task reg_write;   // an AXI4-Lite write, outside the recorded cycles
    input [11:0] a; input [31:0] d;
    begin
      awaddr = a; wdata = d; awvalid = 1'b1; wvalid = 1'b1; cycle;
      awvalid = 1'b0; wvalid = 1'b0; cycle; cycle;
    end
  endtask
  task wait_irq;    // until the start of the first cycle with irq_o high
    integer t;
    begin
      t = 0;
      while (irq !== 1'b1) begin
        t = t + 1;
        if (t > 5000) $fatal(1, "axi_wave_tb: %0s: no interrupt", diagram);
        cycle;
      end
    end
  endtask

  integer i;
  initial begin
    repeat (3) @(posedge aclk);
    #1 aresetn = 1'b1;
    cycle; cycle;
    reg_write(12'h01C, 32'd3);   // IRQ_EN: batch and command done

    // Hit points in: h0 .. h2; a command that runs for one cycle (CMD 3 with PX_COUNT 0),
    // written with h1, makes the engine busy while h2 waits.
    diagram = "stream_hp";
    $fdisplay(fd, "ROWS stream_hp s_axis_hp_tvalid s_axis_hp_tdata s_axis_hp_tready");
    scen = 1; cycle;
    hp_valid = 1'b1; cycle;
    awaddr = 12'h014; wdata = 32'd3; awvalid = 1'b1; wvalid = 1'b1; cycle;
    awvalid = 1'b0; wvalid = 1'b0; cycle;
    cycle;
    hp_valid = 1'b0; cycle;
    cycle;
    scen = 0;
    for (i = 0; i < 5; i = i + 1) begin hp_valid = 1'b1; cycle; end   // h3 .. h7, unrecorded
    hp_valid = 1'b0; cycle;
    reg_write(12'h020, 32'd3);   // clear IRQ_STATUS

    // Photons A (N^P 5: a0 .. a4) and B (N^P 2, tlast: b0, b1); the second candidate beat has
    // a4 in lane 0, lane 1 empty, b0 and b1 in lanes 2 and 3.
    diagram = "stream_ph_cand";
    $fdisplay(fd, "ROWS stream_ph_cand s_axis_ph.tvalid s_axis_ph.tdata s_axis_ph.tlast s_axis_ph.tready s_axis_cand.tvalid s_axis_cand.lane_0_[31:0] s_axis_cand.lane_1_[63:32] s_axis_cand.lane_2_[95:64] s_axis_cand.lane_3_[127:96] s_axis_cand.tkeep s_axis_cand.tready irq_o");
    scen = 2; cycle;
    ph_valid = 1'b1; ph_data[192 +: 16] = 16'd5; cand_valid = 1'b1;
    cand_data = {32'd3, 32'd2, 32'd1, 32'd0}; cand_keep = 16'hFFFF; cycle;
    ph_data[192 +: 16] = 16'd2; ph_last = 1'b1;
    cand_data = {32'd7, 32'd6, 32'd0, 32'd4}; cand_keep = 16'hFF0F; cycle;
    ph_valid = 1'b0; ph_last = 1'b0; cand_valid = 1'b0; cand_keep = 16'h0000;
    wait_irq; cycle;
    scen = 0;
    reg_write(12'h020, 32'd3);
    reg_write(12'h048, 32'd0);   // PX_BASE
    reg_write(12'h04C, 32'd3);   // PX_COUNT
    reg_write(12'h014, 32'd3);   // clear the three pixels
    wait_irq;
    reg_write(12'h020, 32'd3);

    // Read command: CMD 4 (pixels, PX_COUNT 3), m_axis_tready low for one cycle.
    diagram = "stream_m";
    $fdisplay(fd, "ROWS stream_m AW_+_W m_axis_tvalid m_axis_tdata m_axis_tuser m_axis_tlast m_axis_tready irq_o");
    scen = 3;
    awaddr = 12'h014; wdata = 32'd4; awvalid = 1'b1; wvalid = 1'b1; cycle;
    awvalid = 1'b0; wvalid = 1'b0; cycle;
    cycle; cycle;
    m_ready = 1'b0; cycle;
    m_ready = 1'b1;
    wait_irq; cycle;
    scen = 0;
    reg_write(12'h020, 32'd3);

    // AXI4-Lite: CMD 4 again, its interrupt, IRQ_STATUS read and its bit 1 cleared.
    diagram = "axil_cmd";
    $fdisplay(fd, "ROWS axil_cmd write.s_axil_awvalid write.s_axil_awaddr write.s_axil_wvalid write.s_axil_wdata write.s_axil_aw/wready write.s_axil_bvalid write.s_axil_bready read.s_axil_arvalid read.s_axil_araddr read.s_axil_arready read.s_axil_rvalid read.s_axil_rdata read.s_axil_rready irq_o");
    scen = 4; cycle;
    awaddr = 12'h014; wdata = 32'd4; awvalid = 1'b1; wvalid = 1'b1; cycle;
    awvalid = 1'b0; wvalid = 1'b0; cycle;
    cycle;
    wait_irq; cycle;
    araddr = 12'h020; arvalid = 1'b1; cycle;
    arvalid = 1'b0;
    if (rdata !== 32'd2) $fatal(1, "axi_wave_tb: IRQ_STATUS reads %h, not 2", rdata);
    cycle;
    awaddr = 12'h020; wdata = 32'd2; awvalid = 1'b1; wvalid = 1'b1; cycle;
    awvalid = 1'b0; wvalid = 1'b0; cycle;
    cycle;
    scen = 0;
    $fdisplay(fd, "DONE");
    if (fd != 32'h8000_0001) $fclose(fd);
    $finish;
  end
endmodule

`default_nettype wire
