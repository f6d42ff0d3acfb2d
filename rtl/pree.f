// pree.f: the PREE RTL in dependency order (leaves first), for Vivado (read_verilog -f / add_files),
// Verilator (-f), Icarus (-c) and Yosys (read_verilog of each line). Top for an FPGA build:
// pree_axi (docs/integration.md); pree_top for the bare engine. Paths relative to the repository.
// Generated from pree.core's rtl fileset by `make pree-f` (scripts/pree_filelist.py): edit the core.
// The include directory is rtl/: -Irtl for Verilator and Icarus, +incdir+rtl or Vivado's
// include_dirs elsewhere. Include files:
//   rtl/pree_unit_stages.vh, rtl/pree_preu_plan.vh, rtl/pree_preu_lat.vh, rtl/pree_hp_bank.vh, rtl/pree_axi_regs.vh.
rtl/pree_ram_sdp.v
rtl/pree_ram_banks.v
rtl/pree_reset_sync.v
rtl/pree_fp32_lzc.v
rtl/pree_fp32_class.v
rtl/pree_fp32_special.v
rtl/pree_fp32_entry.v
rtl/pree_fp32_unpack_lz.v
rtl/pree_fp32_unpack_norm.v
rtl/pree_fp32_unpack.v
rtl/pree_fp32_denorm_amt.v
rtl/pree_fp32_denorm.v
rtl/pree_fp32_denorm_sel.v
rtl/pree_fp32_round.v
rtl/pree_fp32_tail.v
rtl/pree_fp32_final.v
rtl/pree_fp32_mul_back.v
rtl/pree_fp32_pipe.v
rtl/pree_fp32_dsp_mul.v
rtl/pree_fp32_add.v
rtl/pree_fp32_mul.v
rtl/pree_fp32_sqr.v
rtl/pree_fp32_div_steps.v
rtl/pree_fp32_div.v
rtl/pree_fp32_cmp.v
rtl/pree_u64_to_f32.v
rtl/pree_wacc.v
rtl/pree_preu.v
rtl/pree_aftso_hpuoc.v
rtl/pree_adiso_rec.v
rtl/pree_counters.v
rtl/pree_top_offer.v
rtl/pree_top_read.v
rtl/pree_top_issue.v
rtl/pree_top_queue.v
rtl/pree_top_hpmem.v
rtl/pree_top_pxmem.v
rtl/pree_top.v
rtl/pree_axil_slave.v
rtl/pree_axi.v
