// SPDX-License-Identifier: Apache-2.0
// ecp5_pnr_route_delay: ROUTE_DELAY, the wire delay in front of one cell input of the routed design
// in the timing-annotated simulation (docs/fpga_board.md, "Timing-annotated run"):
// scripts/postroute_sdf.py puts one where nextpnr's SDF gives an input a wire delay (INTERCONNECT,
// which Icarus Verilog 11 does not apply) or a setup time that no IOPATH of its cell can carry,
// and writes that delay as this cell's IOPATH A Z. Z follows A; without an SDF it is a wire.
`default_nettype none

module ROUTE_DELAY (
  input  wire A,
  output wire Z
);
  assign Z = A;
  specify
    (A => Z) = 0;
  endspecify
endmodule
