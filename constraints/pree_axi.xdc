# SPDX-License-Identifier: Apache-2.0
# pree_axi.xdc: Vivado timing template for rtl/pree_axi.v (docs/integration.md, "Clocking and reset").
# One clock: every port of pree_axi is synchronous to aclk. The 8 ns period is a placeholder (no
# pree_axi Fmax has been measured; docs/fpga.md gives the units' ECP5 figures): set your own.
create_clock -name aclk -period 8.000 [get_ports aclk]

# Out-of-context runs (pree_axi as the top): the AXI ports meet registers of the neighbouring IP;
# budget 30 % of the period outside. In a block design these ports are internal: drop both lines.
set_input_delay  -clock aclk 2.400 [get_ports -filter {DIRECTION == IN && NAME != aclk && NAME != aresetn}]
set_output_delay -clock aclk 2.400 [get_ports -filter {DIRECTION == OUT}]

# aresetn is taken asynchronously by the reset synchroniser (rtl/pree_reset_sync.v, ASYNC_REG);
# its release is re-timed there, so the path from the port is not timed.
set_false_path -from [get_ports aresetn]

# UltraScale+ with URAM: hit-point memories in UltraRAM where docs/integration.md's fit table says
# so (uncomment the parts you want; the names are pree_top's generate blocks).
# set_property RAM_STYLE ULTRA [get_cells -hier -filter {NAME =~ *u_top/g_hp[*].u_state/mem_q_reg*}]
# set_property RAM_STYLE ULTRA [get_cells -hier -filter {NAME =~ *u_top/g_hp[*].u_const/mem_q_reg*}]
# Everything else (index table, pixels) in block RAM:
# set_property RAM_STYLE BLOCK [get_cells -hier -filter {NAME =~ *u_top/g_px[*].u_ram/mem_q_reg*}]
