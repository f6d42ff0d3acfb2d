# SPDX-License-Identifier: Apache-2.0
# pree_axi.sdc: SDC timing template for rtl/pree_axi.v (Quartus, Lattice Radiant, Synopsys-style
# tools; docs/integration.md, "Clocking and reset"). One clock, every port synchronous to aclk; the
# 8 ns period is a placeholder (no pree_axi Fmax measured): set your own.
create_clock -name aclk -period 8.000 [get_ports aclk]

# Out-of-context: 30 % of the period outside pree_axi on every AXI port (drop when the ports are
# internal to your design).
set_input_delay  -clock aclk 2.400 [remove_from_collection [all_inputs] [get_ports {aclk aresetn}]]
set_output_delay -clock aclk 2.400 [all_outputs]

# aresetn enters the reset synchroniser (rtl/pree_reset_sync.v) asynchronously.
set_false_path -from [get_ports aresetn]
