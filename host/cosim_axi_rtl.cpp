// SPDX-License-Identifier: Apache-2.0
// cosim_axi_rtl.cpp: the Verilated pree_axi behind cosim_axi_rtl.h (one model per program: the
// make rule passes AXI_MODEL, AXI_MODEL_H, AXI_NP, AXI_DP, AXI_PF, AXI_HPB, AXI_PPC). C++ only because Verilator's
// models are C++ classes. Every field of the wrapper's streams sits on a 32-bit boundary, so the
// wide ports are filled and read a word at a time. Clocked by the benches' harness
// (tb/lib/vharness.h) with the wrapper's aclk and aresetn.
#include "cosim_axi_rtl.h"

#include <cstdio>
#include <cstring>
#include <memory>

#include AXI_MODEL_H
#include "pree_be_verilated.h"
#include "vharness.h"
#include "vport.h"

namespace {
const unsigned SW = AXI_DP ? 320 : 160;   // state bits of a hit point
const unsigned HPW = SW / 32;             // state words
struct AxiPorts {
    static void clk(AXI_MODEL &t, int v) { t.aclk = v; }
    static void rst(AXI_MODEL &t, int v) { t.aresetn = v; }
};
}

struct cosim_rtl {
    VHarness<AXI_MODEL, AxiPorts> h;   // the model, its clock and its trace (fst: a file or NULL)
    AXI_MODEL *top;
    cosim_in_t in;          // alpha and kappa only (cosim_main.c sets them)
    cosim_axi_in_t ain;
    cosim_axi_out_t out;

    explicit cosim_rtl(const char *fst) : h(0, nullptr, fst), top(&h.dut())
    {
        std::memset(&in, 0, sizeof in);
        std::memset(&ain, 0, sizeof ain);
        std::memset(&out, 0, sizeof out);
        apply();
        top->eval();
        // The reset synchroniser releases two edges after aresetn rises.
        h.reset(2, 2);
    }
    void apply()
    {
        AXI_MODEL &t = *top;
        const cosim_axi_in_t &a = ain;
        t.s_axil_awaddr = a.awaddr;
        t.s_axil_awvalid = a.awvalid;
        t.s_axil_wdata = a.wdata;
        t.s_axil_wstrb = 0xf;
        t.s_axil_wvalid = a.wvalid;
        t.s_axil_bready = a.bready;
        t.s_axil_araddr = a.araddr;
        t.s_axil_arvalid = a.arvalid;
        t.s_axil_rready = a.rready;
        for (int s = 0; s < AXI_PPC; s++) {   // 256-bit slots: pos, phi, N^P, a reserved 0
            for (int c = 0; c < 3; c++) {
                t.s_axis_ph_tdata[8 * s + c] = a.ph[s].pos[c];
                t.s_axis_ph_tdata[8 * s + 3 + c] = a.ph[s].phi[c];
            }
            t.s_axis_ph_tdata[8 * s + 6] = a.ph_n[s];
            t.s_axis_ph_tdata[8 * s + 7] = 0;
        }
        t.s_axis_ph_tlast = a.ph_last;
        t.s_axis_ph_tvalid = a.ph_valid;
        uint64_t keep = 0;
        for (int j = 0; j < AXI_NP; j++) {
            vport::put32(t.s_axis_cand_tdata, 32 * j, a.cand[j]);   // a word of VlWide, or of QData (2 PREUs)
            if (a.cand_keep >> j & 1u) keep |= 0xfull << (4 * j);
        }
        t.s_axis_cand_tkeep = keep;
        t.s_axis_cand_tvalid = a.cand_valid;
        for (unsigned k = 0; k < HPW; k++) t.s_axis_hp_tdata[k] = a.hp.st[k];
        for (int c = 0; c < 3; c++) {
            t.s_axis_hp_tdata[HPW + c] = a.hp.pos[c];
            t.s_axis_hp_tdata[HPW + 3 + c] = a.hp.f[c];
        }
        t.s_axis_hp_tdata[HPW + 6] = a.hp_pixel;
        t.s_axis_hp_tvalid = a.hp_valid;
        t.m_axis_tready = a.m_ready;
    }
    // The handshakes of this cycle, seen with the clock low and the inputs settled.
    void sample()
    {
        AXI_MODEL &t = *top;
        unsigned f = 0;
        if (t.s_axil_awvalid && t.s_axil_awready) f |= AXI_AW;
        if (t.s_axil_wvalid && t.s_axil_wready) f |= AXI_W;
        if (t.s_axil_bvalid && t.s_axil_bready) f |= AXI_B;
        if (t.s_axil_arvalid && t.s_axil_arready) f |= AXI_AR;
        if (t.s_axil_rvalid && t.s_axil_rready) { f |= AXI_R; out.rdata = t.s_axil_rdata; }
        if (t.s_axis_ph_tvalid && t.s_axis_ph_tready) f |= AXI_PH;
        if (t.s_axis_cand_tvalid && t.s_axis_cand_tready) f |= AXI_CAND;
        if (t.s_axis_hp_tvalid && t.s_axis_hp_tready) f |= AXI_HP;
        if (t.m_axis_tvalid && t.m_axis_tready) {
            f |= AXI_M;
            out.m_user = t.m_axis_tuser;
            out.m_last = t.m_axis_tlast;
            for (unsigned k = 0; k < HPW; k++) out.m_hp.st[k] = t.m_axis_tdata[k];
            for (int c = 0; c < 3; c++) {
                out.m_hp.pos[c] = t.m_axis_tdata[HPW + c];
                out.m_hp.f[c] = t.m_axis_tdata[HPW + 3 + c];
                out.m_px[c] = t.m_axis_tdata[c];
            }
            out.m_pixel = t.m_axis_tdata[HPW + 6];
        }
        out.irq = t.irq_o;
        out.fired = f;
    }
    void tick()
    {
        apply();
        h.tick([this] { sample(); });
    }
};

extern "C" {

cosim_rtl_t *cosim_rtl_new(int preu, int datapath, int pipefast, const char *fst, char *err, size_t errlen)
{
    if (preu != AXI_NP || (datapath != 0) != (AXI_DP != 0) || (pipefast != 0) != (AXI_PF != 0)) {
        std::snprintf(err, errlen, "this program holds pree_axi with %d PREUs, the %s datapath and PipeFast %d, not %d, %s and %d",
                      AXI_NP, AXI_DP ? "stable" : "paper", AXI_PF, preu, datapath ? "stable" : "paper", pipefast != 0);
        return nullptr;
    }
    cosim_rtl_t *r = new cosim_rtl(fst);
    if (r->h.trace_error()) {
        std::snprintf(err, errlen, "%s", r->h.trace_error());
        delete r;
        return nullptr;
    }
    return r;
}

void cosim_rtl_free(cosim_rtl_t *r) { delete r; }
cosim_in_t *cosim_rtl_in(cosim_rtl_t *r) { return &r->in; }
int cosim_rtl_hp_bank_w(cosim_rtl_t *) { return AXI_HPB; }
// pree_axi's pree_top with the units' default stages for PipeFast (AXI_PF): 1 + the PREU's
// update latency (PipeFast 0: 10 paper, 12 stable; PipeFast 1: 48, 52), as rtl/pree_top.v's
// WIN_UPD (cosim_main.c checks it against the host's own figure).
int cosim_rtl_update_window(cosim_rtl_t *) { return PREE_UPDATE_WINDOW(AXI_DP, AXI_PF); }
// ... and PipeFast 1's registered flow (A's offer register, B's queue) with PipeFast 1.
int cosim_rtl_reg_flow(cosim_rtl_t *) { return AXI_PF ? 1 : 0; }
// The wrapper's PhotonsPerCycle (photon slots a beat, passed to its pree_top); --model-only is
// for the pree_top programs.
int cosim_rtl_ppc(cosim_rtl_t *) { return AXI_PPC; }
int cosim_rtl_radiance_depth(cosim_rtl_t *) { return PREE_RADIANCE_DEPTH(AXI_PF); }   // RAD_LAT
uint64_t cosim_rtl_cycle(cosim_rtl_t *r) { return r->h.trace_cycle(); }
void cosim_rtl_trace_window(cosim_rtl_t *r, uint64_t from, uint64_t to) { r->h.set_trace_window(from, to); }
int cosim_rtl_config(int, int *, int *) { return -1; }
cosim_axi_in_t *cosim_axi_in(cosim_rtl_t *r) { return &r->ain; }
const cosim_axi_out_t *cosim_axi_tick(cosim_rtl_t *r) { r->tick(); return &r->out; }
int cosim_axi_backend(pree_backend_t *be, cosim_rtl_t *r, const cosim_drv_opts_t *opt, char *err, size_t errlen)
{
    if (!pree_be_verilated_attach(be, r, opt->preu, opt->datapath, opt->gap, opt->seed,
                                  opt->schedule ? COSIM_LEAD_ENTRIES(opt->preu) : 0))
        return 0;
    std::snprintf(err, errlen, "out of memory");
    return -1;
}

}  // extern "C"
