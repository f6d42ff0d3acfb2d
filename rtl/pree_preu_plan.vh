// SPDX-License-Identifier: Apache-2.0
// pree_preu_plan.vh: the PREU's stage plan as constant functions of its units' latencies, written
// once for pree_preu (which builds the plan), pree_top (which sizes its hazard windows and
// ADISO-REC's depth from it) and the formal PREU stub, through pree_preu_lat.vh, which includes it
// and resolves the latencies from their parameters. a, m, q, d, u, w: the latencies of
// pree_fp32_add, _mul, _sqr, _div, pree_u64_to_f32 and pree_wacc in the PREU (preu_unit_lat: each
// unit's InRegs + Stages); the comparator is combinational. docs/preu_datapath.md gives the plan
// and its figures.
//
// Update (both datapaths): d = pos - pos (add, stage 0), q = d * d (sqr, stage a), s = qx + qy
// (add, a + q), d2 = s + qz (add, 2a + q, ready at 3a + q).
//   Paper:  na = n + alpha, n1 = n + 1 (add, 0); g = na / n1 (div, a); t = m * 1/PI (mul, m);
//           u = tau + t (add, 2m); tau' = u * g (mul, when both are ready); r2' = r2 * g
//           (mul, a + d); accept = d2 <= r2 (cmp, 3a + q).
//   Stable: kf = fl(k + 1) (u2f, 0); e = kappa / kf (div, u); t = m * w (mul, m); p = w * e
//           (mul, u + d); d2w = d2 * w (mul, 3a + q); accept = d2w <= 1 (cmp, 3a + q + m);
//           T' = T + t, w' = w + p (wacc, ending with the result).
//   The result stage: the accept bit registered twice after the comparison (the paper's S9 and
//   S10), or later when a result is ready later.
// Radiance (both): a = PI * r2 (mul, 0), b = a * NE (mul, m), k = 1 / b (div, 2m), c = tau * k
// (mul, 2m + d), L' = L + c (add, 3m + d; the pixel sum is asked for one stage before).

// The unit kinds (PREU_ADD .. PREU_WACC) and preu_stages(kind, pipe_fast, stages), a unit's
// stages: stages when set (non-zero), else the unit's own default for pipe_fast; generated from
// the configuration table (config/pree_config.json).
`include "pree_unit_stages.vh"

// Operand registers in front of every unit (each unit's InRegs): one with PipeFast 1, so that
// the mode's operand selects (some thousand select bits from one input) end in a register of
// each unit's own; none with PipeFast 0.
function integer preu_in_regs;
  input integer pipe_fast;
  begin
    preu_in_regs = (pipe_fast != 0) ? 1 : 0;
  end
endfunction

// A unit's latency in the PREU: its stages and its operand registers. The plan below takes these.
function integer preu_unit_lat;
  input integer kind, pipe_fast, stages;
  begin
    preu_unit_lat = preu_stages(kind, pipe_fast, stages) + preu_in_regs(pipe_fast);
  end
endfunction

function integer preu_max;
  input integer x, y;
  begin
    preu_max = (x > y) ? x : y;
  end
endfunction

// Stage in which the paper datapath's tau' = u * g is fed: u and g both ready.
function integer preu_taun_feed;
  input integer a, m, d;
  begin
    preu_taun_feed = preu_max(2 * m + a, a + d);
  end
endfunction

// Stage of the comparison: paper d2 <= r2, stable d2 * w <= 1.
function integer preu_cmp_stage;
  input integer stable, a, m, q;
  begin
    preu_cmp_stage = (stable != 0) ? 3 * a + q + m : 3 * a + q;
  end
endfunction

// The update latency (stage of the result, of valid_o and of accept_o).
function integer preu_upd_latency;
  input integer stable, a, m, q, d, u, w;
  begin
    if (stable != 0)
      preu_upd_latency = preu_max(preu_cmp_stage(1, a, m, q) + 2, preu_max(2 * m, u + d + m) + w);
    else
      preu_upd_latency = preu_max(preu_cmp_stage(0, a, m, q) + 2, preu_taun_feed(a, m, d) + m);
  end
endfunction

// The radiance latency; the pixel sum is asked for (lreq_o) in stage preu_rad_latency - a - 1
// and driven on l_i in the next cycle.
function integer preu_rad_latency;
  input integer a, m, d;
  begin
    preu_rad_latency = 3 * m + d + a;
  end
endfunction
