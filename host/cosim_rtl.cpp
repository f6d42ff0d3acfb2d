// SPDX-License-Identifier: Apache-2.0
// cosim_rtl.cpp: the Verilated pree_top behind the C interface of cosim_rtl.h. C++ only because
// Verilator's models are C++ classes; one template, clocked by the bench harness
// (tb/lib/vharness.h), serves every model of the build. mk/cosim.mk includes each model's header
// (-include) and lists the build's models in COSIM_MODELS, X(class, PREU count, datapath,
// PipeFast) each: the one list of configurations. Each model's update hazard window is its
// pree_top's public WIN_UPD, and whether it has PipeFast 1's registered flow (A's offer register,
// B's queue) its public REG_FLOW.
#include "cosim_rtl.h"

#include <cstdio>
#include <cstring>

#include "vharness.h"
#include "vport.h"

using vport::get;
using vport::get32;
using vport::put;
using vport::put32;

#ifndef COSIM_MODELS
#error "COSIM_MODELS (the build's pree_top models) comes from mk/cosim.mk"
#endif

struct cosim_rtl {
    virtual ~cosim_rtl() {}
    cosim_in_t in;
    virtual void tick() = 0;
    virtual int ph_ready() = 0;
    virtual int idle() = 0;
    virtual uint32_t photons_done() = 0;
    virtual void hp_rdata(preu_hpw_t *hp, uint32_t *pixel) = 0;
    virtual void px_rdata(uint32_t L[3]) = 0;
    virtual void counters(uint64_t *cnt) = 0;
    virtual const char *trace_error() = 0;
    virtual int hp_bank_w() = 0;
    virtual int update_window() = 0;
    virtual int radiance_depth() = 0;
    virtual uint64_t cycle() = 0;
    virtual void trace_window(uint64_t from, uint64_t to) = 0;
    virtual int reg_flow() = 0;
    virtual int ppc() = 0;
    virtual void set_reset(int on) = 0;
};

namespace {

template <class V, int NP, int HPB, int PPC, int DP, int WIN, int RAD, int REG_FLOW>
struct Rtl : cosim_rtl {
    static const unsigned SW = DP ? 320 : 160;   // state bits of a hit point
    // Trace time in picoseconds (the models' time precision): the paper's 125 MHz clock, 8 ns a
    // cycle, so a waveform viewer shows real times; cycle n's rising edge is at (8n + 4) ns.
    static constexpr uint64_t HALF_PERIOD_PS = 4000;
    VHarness<V> top;      // the model, its clock and its trace (fst: a file or NULL)
    cosim_in_t applied;   // the inputs last written to the model (only changes are copied)

    explicit Rtl(const char *fst) : top(0, nullptr, fst, HALF_PERIOD_PS)
    {
        std::memset(&in, 0, sizeof in);
        std::memset(&applied, 0xff, sizeof applied);
        apply();
        top.reset(2);
    }
    const char *trace_error() override { return top.trace_error(); }
    void apply()
    {
        V &t = top.dut();
        t.mode_i = in.mode;
        t.cnt_en_i = in.cnt_en;
        t.rad_start_i = in.rad_start;
        t.ne_i = in.ne;
        t.alpha_i = in.alpha;
        t.kappa_i = in.kappa;
        t.n_hit_i = in.n_hit;
        t.ph_valid_i = in.ph_valid;
        for (int k = 0; k < PPC; k++) {
            if (std::memcmp(applied.ph_pos[k], in.ph_pos[k], sizeof in.ph_pos[k]) ||
                std::memcmp(applied.ph_phi[k], in.ph_phi[k], sizeof in.ph_phi[k])) {
                for (int c = 0; c < 3; c++) {
                    put32(t.ph_data_i, 192 * k + 32 * c, in.ph_pos[k][c]);
                    put32(t.ph_data_i, 192 * k + 96 + 32 * c, in.ph_phi[k][c]);
                }
                std::memcpy(applied.ph_pos[k], in.ph_pos[k], sizeof in.ph_pos[k]);
                std::memcpy(applied.ph_phi[k], in.ph_phi[k], sizeof in.ph_phi[k]);
            }
            put(t.ph_paddr_i, k * COSIM_IDXAW, COSIM_IDXAW, in.ph_paddr[k]);
            put(t.ph_n_i, k * COSIM_CNTW, COSIM_CNTW, in.ph_n[k]);
        }
        uint32_t we = 0;
        for (int j = 0; j < NP; j++) {
            if (!in.idx_we[j]) continue;
            we |= 1u << j;
            put(t.idx_addr_i, j * COSIM_IDXAW, COSIM_IDXAW, in.idx_addr[j]);
            put(t.idx_data_i, j * COSIM_HPAW, COSIM_HPAW, in.idx_data[j]);
        }
        t.idx_we_i = we;
        t.hp_we_i = in.hp_we;
        t.hp_re_i = in.hp_re;
        t.hp_addr_i = in.hp_addr;
        if (in.hp_we) {
            const preu_hpw_t &h = in.hp_wdata;
            for (unsigned k = 0; k < SW / 32; k++) put32(t.hp_wdata_i, 32 * k, h.st[k]);
            for (int c = 0; c < 3; c++) {
                put32(t.hp_wdata_i, SW + 32 * c, h.pos[c]);
                put32(t.hp_wdata_i, SW + 96 + 32 * c, h.f[c]);
            }
            put(t.hp_wdata_i, SW + 192, COSIM_PXAW, in.hp_pixel);
        }
        t.px_we_i = in.px_we;
        t.px_re_i = in.px_re;
        t.px_addr_i = in.px_addr;
        if (in.px_we)
            for (int c = 0; c < 3; c++) put32(t.px_wdata_i, 32 * c, in.px_wdata[c]);
    }
    // One cycle with the new inputs, traced or not (the harness evaluates once per edge).
    void tick() override
    {
        apply();
        top.tick();
    }
    int hp_bank_w() override { return HPB; }
    int update_window() override { return WIN; }
    int radiance_depth() override { return RAD; }
    uint64_t cycle() override { return top.trace_cycle(); }
    void trace_window(uint64_t from, uint64_t to) override { top.set_trace_window(from, to); }
    int reg_flow() override { return REG_FLOW; }
    int ppc() override { return PPC; }
    void set_reset(int on) override
    {
        top->rst_ni = on ? 0 : 1;
        top->eval();
    }
    int ph_ready() override { return top->ph_ready_o; }
    int idle() override { return top->idle_o; }
    uint32_t photons_done() override { return top->photons_done_o; }
    void hp_rdata(preu_hpw_t *h, uint32_t *pixel) override
    {
        const auto &d = top->hp_rdata_o;
        std::memset(h, 0, sizeof *h);
        for (unsigned k = 0; k < SW / 32; k++) h->st[k] = get32(d, 32 * k);
        for (int c = 0; c < 3; c++) {
            h->pos[c] = get32(d, SW + 32 * c);
            h->f[c] = get32(d, SW + 96 + 32 * c);
        }
        *pixel = static_cast<uint32_t>(get(d, SW + 192, COSIM_PXAW));
    }
    void px_rdata(uint32_t L[3]) override
    {
        for (int c = 0; c < 3; c++) L[c] = get32(top->px_rdata_o, 32 * c);
    }
    void counters(uint64_t *cnt) override
    {
        for (int k = 0; k < COSIM_NCNT; k++) cnt[k] = 0;
        for (int k = 0; k < 7 + NP; k++) cnt[k] = get(top->cnt_o, COSIM_CTRW * k, COSIM_CTRW);
    }
};

}  // namespace

extern "C" {

cosim_rtl_t *cosim_rtl_new(int preu, int datapath, int pipefast, const char *fst, char *err, size_t errlen)
{
    cosim_rtl_t *r = nullptr;
#define X(V, NP, DP, PF) \
    if (!r && preu == (NP) && (datapath != 0) == (DP) && (pipefast != 0) == (PF)) \
        r = new Rtl<V, NP, COSIM_HPB_##NP, COSIM_PPC_##NP, DP, V##_pree_top::WIN_UPD, V##_pree_top::RAD_LAT, \
                    V##_pree_top::REG_FLOW>(fst);
    COSIM_MODELS
#undef X
    if (!r) {
        std::snprintf(err, errlen, "no pree_top model with %d PREUs, the %s datapath and PipeFast %d in this build%s",
                      preu, datapath ? "stable" : "paper", pipefast != 0,
                      datapath || pipefast ? " (make COSIM_STABLE_PREUS=\"4 8 16\" COSIM_FAST_PREUS=\"4 8 16\" builds them all)" : "");
        return nullptr;
    }
    if (r->trace_error()) {
        std::snprintf(err, errlen, "%s", r->trace_error());
        delete r;
        return nullptr;
    }
    return r;
}

void cosim_rtl_free(cosim_rtl_t *r) { delete r; }
cosim_in_t *cosim_rtl_in(cosim_rtl_t *r) { return &r->in; }
void cosim_rtl_tick(cosim_rtl_t *r) { r->tick(); }
int cosim_rtl_ph_ready(cosim_rtl_t *r) { return r->ph_ready(); }
int cosim_rtl_idle(cosim_rtl_t *r) { return r->idle(); }
uint32_t cosim_rtl_photons_done(cosim_rtl_t *r) { return r->photons_done(); }
void cosim_rtl_hp_rdata(cosim_rtl_t *r, preu_hpw_t *hp, uint32_t *pixel) { r->hp_rdata(hp, pixel); }
void cosim_rtl_px_rdata(cosim_rtl_t *r, uint32_t L[3]) { r->px_rdata(L); }
void cosim_rtl_counters(cosim_rtl_t *r, uint64_t cnt[COSIM_NCNT]) { r->counters(cnt); }
int cosim_rtl_hp_bank_w(cosim_rtl_t *r) { return r->hp_bank_w(); }
int cosim_rtl_update_window(cosim_rtl_t *r) { return r->update_window(); }
int cosim_rtl_radiance_depth(cosim_rtl_t *r) { return r->radiance_depth(); }
uint64_t cosim_rtl_cycle(cosim_rtl_t *r) { return r->cycle(); }
void cosim_rtl_trace_window(cosim_rtl_t *r, uint64_t from, uint64_t to) { r->trace_window(from, to); }
int cosim_rtl_reg_flow(cosim_rtl_t *r) { return r->reg_flow(); }
int cosim_rtl_ppc(cosim_rtl_t *r) { return r->ppc(); }

int cosim_rtl_config(int preu, int *hp_bank_w, int *ppc)
{
#define X(NP) \
    if (preu == (NP)) { *hp_bank_w = COSIM_HPB_##NP; *ppc = COSIM_PPC_##NP; return 0; }
    COSIM_PREU_COUNTS
#undef X
    return -1;
}
void cosim_rtl_set_reset(cosim_rtl_t *r, int on) { r->set_reset(on); }

}  // extern "C"
