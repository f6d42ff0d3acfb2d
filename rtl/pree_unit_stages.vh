// SPDX-License-Identifier: Apache-2.0
// pree_unit_stages.vh: GENERATED from config/pree_config.json by scripts/pree_config.py (make config): do not edit.
// The PREU's fp32 unit kinds and each unit's default Stages, included inside a module
// (rtl/pree_preu_plan.vh, tb/fp32/tb_fp32_pipe.v). A unit's latency is Stages + InRegs.
// kind  module            Stages  default (PipeFast 0 / 1)
//  0    pree_fp32_add      1 .. 7  2 / 7
//  1    pree_fp32_mul      1 .. 8  2 / 7
//  2    pree_fp32_sqr      1 .. 6  2 / 6
//  3    pree_fp32_div      2 .. 31 4 / 31
//  4    pree_u64_to_f32    1 .. 5  2 / 5
//  5    pree_wacc          1 .. 5  2 / 5
localparam PREU_ADD = 0;
localparam PREU_MUL = 1;
localparam PREU_SQR = 2;
localparam PREU_DIV = 3;
localparam PREU_U2F = 4;
localparam PREU_WACC = 5;

// A unit's stages: stages when set (non-zero), else the unit's own default for pipe_fast.
function integer preu_stages;
  input integer kind, pipe_fast, stages;
  begin
    if (stages != 0)         preu_stages = stages;
    else if (pipe_fast == 0) preu_stages = (kind == 0) ? 2 : (kind == 1) ? 2 : (kind == 2) ? 2 : (kind == 3) ? 4 : (kind == 4) ? 2 : 2;
    else                     preu_stages = (kind == 0) ? 7 : (kind == 1) ? 7 : (kind == 2) ? 6 : (kind == 3) ? 31 : (kind == 4) ? 5 : 5;
  end
endfunction
