// SPDX-License-Identifier: Apache-2.0
// preu_bench.cpp: Verilator bench for rtl/pree_preu.v in both modes, scoreboarded bit for bit
// against model/pree/preu_fp32.c or model/pree/preu_stable.c (expected values computed by
// tb/preu/preu_vec.c). Built once per datapath: -DPREU_DATAPATH=0 (paper) or 1 (stable), with
// the RTL's Datapath parameter to match.
//
// Usage: preu_bench [count [seed]] [+trace=FILE.fst]   (defaults 200000, 1; no trace)
//        preu_bench --chain N [alpha]   one hit point fed N accepted photons in update mode,
//                                       each result written back as a top would (one operation
//                                       in flight), every state word checked against the model;
//                                       prints r2 and radiance against a double reference at
//                                       every decade (the stress suite's RTL leg, make stress)
// The sequence (preu_seq_gen) starts with directed cases, then alternates update and radiance
// phases of random length with back-to-back and gapped valid_i. The bench behaves as a top
// would: it switches mode_i only in a cycle where busy_o = 0, answers lreq_o by driving the
// operation's pixel sum on l_i in the next cycle, and drives random junk on every input that
// is not meant to be read (so stale data cannot hide). Scoreboard keyed on the handshake:
// an expected result is pushed when valid_i is high and popped at valid_o, which must come
// exactly UPD_LAT or RAD_LAT cycles later with the same tag (the PREU's public latencies: paper
// 10 / stable 12 and 12 with PipeFast 0); lreq_o must come LREQ_AT cycles after entry with its tag. Update results are compared whether accepted or not.
// Prints the first 20 mismatches with their inputs in hex; exit status 1 on any failure. A
// failing run (without +trace) runs itself again traced and leaves the cycles around its first
// mismatch in build/.../preu_bench*-fail-cN.fst (tb/lib/fail_trace.h), named in its last line.
// +inject_error=N flips a bit of op N's expected result: the check of that failure path.
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <vector>

#include "Vpree_preu.h"
#include "Vpree_preu_pree_preu.h"   // the PREU's public latencies
#include "fail_trace.h"
#include "vharness.h"
#include "preu_vec.h"

namespace {

const int MAX_REPORT = 20;
const int DP = PREU_DATAPATH;
const int NST = DP ? 10 : 5;              // state words
// The latencies follow from the PREU's stage plan (its units' latencies, PipeFast).
const uint64_t UPD_LAT = Vpree_preu_pree_preu::UPD_LATENCY;
const uint64_t RAD_LAT = Vpree_preu_pree_preu::RAD_LATENCY;
const uint64_t LREQ_AT = Vpree_preu_pree_preu::LREQ_STAGE;

struct Pending {
    uint32_t index;
    uint64_t due;      // cycle in which the result must appear
};

uint64_t errors = 0;
uint64_t first_cycle = 0;   // of the first mismatch

void report(const preu_vec_t &v, uint32_t idx, const char *what, uint64_t cycle)
{
    if (errors == 0) first_cycle = cycle;
    if (errors++ >= MAX_REPORT) return;
    std::printf("MISMATCH op %u (%s mode) cycle %" PRIu64 ": %s\n", idx,
                v.mode ? "radiance" : "update", cycle, what);
    std::printf("  hp pos %08x %08x %08x f %08x %08x %08x state", v.hp.pos[0], v.hp.pos[1], v.hp.pos[2],
                v.hp.f[0], v.hp.f[1], v.hp.f[2]);
    for (int k = NST; k-- > 0;) std::printf(" %08x", v.hp.st[k]);
    std::printf("\n  ph pos %08x %08x %08x phi %08x %08x %08x alpha %08x kappa %08x ne %08x l %08x %08x %08x\n",
                v.ph.pos[0], v.ph.pos[1], v.ph.pos[2], v.ph.phi[0], v.ph.phi[1], v.ph.phi[2],
                v.alpha, v.kappa, v.ne, v.l[0], v.l[1], v.l[2]);
    std::printf("  expected accept %d l %08x %08x %08x state", v.accept, v.lo[0], v.lo[1], v.lo[2]);
    for (int k = NST; k-- > 0;) std::printf(" %08x", v.sto[k]);
    std::printf("\n");
}

template <std::size_t N> void put(VlWide<N> &port, const uint32_t *w)
{
    for (std::size_t k = 0; k < N; k++) port[k] = w[k];
}

template <std::size_t N> bool eq(const VlWide<N> &port, const uint32_t *w)
{
    for (std::size_t k = 0; k < N; k++) if (port[k] != w[k]) return false;
    return true;
}

// One hit point at distance 0 from every photon (all accepted), constant flux, state written
// back after each result: the RTL must equal the model word for word at every step.
int chain(VHarness<Vpree_preu> &h, uint64_t n, double alpha)
{
    Vpree_preu *const dut = &h.dut();
    auto tick = [&h]() { h.tick(); };
    const uint32_t a32 = preu_f32(alpha), k32 = preu_kappa(a32);
    preu_hpw_t hw;
    std::memset(&hw, 0, sizeof hw);
    const uint32_t pos[3] = {preu_f32(1.0), preu_f32(2.0), preu_f32(3.0)};
    const uint32_t f[3] = {preu_f32(0.5), preu_f32(0.25), preu_f32(1.0)};
    preu_photon_t ph;
    for (int c = 0; c < 3; c++) { ph.pos[c] = pos[c]; ph.phi[c] = preu_f32(1.0 + c); }
    preu_hp_t hp;
    preu_shp_t sp;
    std::memcpy(hp.pos, pos, sizeof pos); std::memcpy(hp.f, f, sizeof f);
    hp.tau[0] = hp.tau[1] = hp.tau[2] = 0; hp.r2 = preu_f32(1.0); hp.n = 0;
    std::memcpy(sp.pos, pos, sizeof pos); std::memcpy(sp.f, f, sizeof f);
    preu_stable_init(&sp, 1.0);
    if (DP) preu_hpw_from_stable(&hw, &sp); else preu_hpw_from_paper(&hw, &hp);
    double r2d = 1.0, taud = 0.0;                 // smallppm's double update, integer count
    const double md = 0.5 * (1.0 / 3.14159265358979);   // f_r * phi_r / PI, channel r
    uint64_t next = 10, errors = 0, cycles = 0;
    dut->mode_i = 0; dut->alpha_i = a32; dut->kappa_i = k32;
    for (uint64_t i = 1; i <= n; i++) {
        put(dut->hp_pos_i, hw.pos); put(dut->hp_f_i, hw.f); put(dut->hp_state_i, hw.st);
        put(dut->ph_pos_i, ph.pos); put(dut->ph_phi_i, ph.phi);
        dut->valid_i = 1; dut->tag_i = (uint32_t)i;
        tick(); cycles++;
        dut->valid_i = 0;
        while (!dut->valid_o && cycles < (UPD_LAT + 20) * n + 100) { tick(); cycles++; }
        const int acc = DP ? preu_stable_update(&sp, &ph, k32) : preu_update(&hp, &ph, a32);
        preu_hpw_t want;
        if (DP) preu_hpw_from_stable(&want, &sp); else preu_hpw_from_paper(&want, &hp);
        if (!dut->valid_o || dut->accept_o != acc || !eq(dut->state_o, want.st)) {
            if (errors++ < 5) std::printf("MISMATCH chain step %llu: valid %d accept %d (model %d)\n",
                                          (unsigned long long)i, dut->valid_o, dut->accept_o, acc);
            if (!dut->valid_o) break;
        }
        for (int k = 0; k < NST; k++) hw.st[k] = dut->state_o[k];
        const double g = ((double)(i - 1) * alpha + alpha) / ((double)(i - 1) * alpha + 1.0);
        r2d *= g;
        taud = (taud + md) * g;
        if (i == next || i == n) {
            const double r2 = DP ? preu_stable_r2(&sp) : (double)fp32_from_bits(hp.r2);
            const double tau = DP ? preu_stable_tau(&sp, 0) : (double)fp32_from_bits(hp.tau[0]);
            std::printf("preu_bench chain: %s datapath, accepts %12llu: r2 %+.3e  radiance %+.3e (relative to double)\n",
                        DP ? "stable" : "paper", (unsigned long long)i, r2 / r2d - 1, (tau / r2) / (taud / r2d) - 1);
            if (i == next) next *= 10;
        }
        tick(); cycles++;
    }
    std::printf("preu_bench chain: %s datapath, alpha %g: %llu updates, %llu cycles, %llu mismatches: %s\n",
                DP ? "stable" : "paper", alpha, (unsigned long long)n, (unsigned long long)cycles,
                (unsigned long long)errors, errors ? "FAIL" : "PASS");
    return errors ? 1 : 0;
}

// The random-sequence run: the sequence, what is in flight, the counters; one cycle is drive()
// (this cycle's inputs: junk, then the operation offered, if any), then check() (this cycle's
// outputs against the expected ones), then the harness's tick.
struct Run {
    Vpree_preu *dut;
    const std::vector<preu_vec_t> &seq;
    const int count;
    std::deque<Pending> results, lreqs;
    uint32_t junk_state = 12345;
    int next = 0, gap_left, mode = 0;
    bool l_due = false;            // lreq_o was high last cycle: drive that op's L now
    uint32_t l_index = 0, ne_cur = 0, alpha_cur = 0, kappa_cur = 0;
    uint64_t cycle = 0, issued = 0, checked = 0, accepted = 0, switches = 0, idle = 0;

    Run(Vpree_preu *d, const std::vector<preu_vec_t> &s, int n) : dut(d), seq(s), count(n), gap_left(s[0].gap) {}
    uint32_t junk() { junk_state = junk_state * 1664525u + 1013904223u; return junk_state; }
    bool done() const { return next >= count && results.empty(); }

    void drive()
    {
        uint32_t j[PREU_STATE_MAX];
        for (auto *w : {&dut->hp_pos_i, &dut->hp_f_i, &dut->ph_pos_i, &dut->ph_phi_i, &dut->l_i}) {
            j[0] = junk(); j[1] = junk(); j[2] = junk();
            put(*w, j);
        }
        for (int k = 0; k < NST; k++) j[k] = junk();
        put(dut->hp_state_i, j);
        dut->tag_i = junk();
        dut->valid_i = 0;
        dut->mode_i = mode;
        if (l_due) put(dut->l_i, seq[l_index].l);
        dut->eval();

        bool offer = next < count && gap_left == 0;
        if (offer && seq[next].mode != mode) {
            if (dut->busy_o) offer = false;   // wait for the pipeline to drain
            else { mode = seq[next].mode; dut->mode_i = mode; switches++; }
        }
        // NE is held for a whole radiance phase; junk in update mode, where nothing reads it.
        // alpha and kappa are held for a whole update phase (they change only at a phase
        // change, when the pipeline has drained); junk in radiance mode.
        if (offer && mode == 1) ne_cur = seq[next].ne;
        if (offer && mode == 0) { alpha_cur = seq[next].alpha; kappa_cur = seq[next].kappa; }
        dut->ne_i = mode ? ne_cur : junk();
        dut->alpha_i = mode ? junk() : alpha_cur;
        dut->kappa_i = mode ? junk() : kappa_cur;
        if (offer) {
            const preu_vec_t &v = seq[next];
            dut->valid_i = 1;
            dut->tag_i = (uint32_t)next;
            put(dut->hp_pos_i, v.hp.pos); put(dut->hp_f_i, v.hp.f);
            put(dut->hp_state_i, v.hp.st);
            put(dut->ph_pos_i, v.ph.pos); put(dut->ph_phi_i, v.ph.phi);
            results.push_back({(uint32_t)next, cycle + (mode ? RAD_LAT : UPD_LAT)});
            if (mode) lreqs.push_back({(uint32_t)next, cycle + LREQ_AT});
            issued++;
            next++;
            if (next < count) gap_left = seq[next].gap;
        } else {
            if (next < count && gap_left > 0) gap_left--;
            idle++;
        }
        dut->eval();
    }

    void check_lreq()
    {
        l_due = false;
        if (dut->lreq_o) {
            if (lreqs.empty() || lreqs.front().due != cycle || dut->lreq_tag_o != lreqs.front().index) {
                uint32_t idx = lreqs.empty() ? 0 : lreqs.front().index;
                report(seq[idx], idx, "lreq_o at the wrong cycle or with the wrong tag", cycle);
            } else {
                l_due = true;
                l_index = lreqs.front().index;
                lreqs.pop_front();
            }
        } else if (!lreqs.empty() && lreqs.front().due == cycle) {
            report(seq[lreqs.front().index], lreqs.front().index, "lreq_o missing", cycle);
            lreqs.pop_front();
        }
    }

    void check_result()
    {
        if (!dut->valid_o) {
            if (!results.empty() && results.front().due == cycle) {
                report(seq[results.front().index], results.front().index, "valid_o missing", cycle);
                results.pop_front();
            }
            return;
        }
        if (results.empty()) {
            report(seq[0], 0, "valid_o with nothing in flight", cycle);
            return;
        }
        Pending p = results.front();
        results.pop_front();
        const preu_vec_t &v = seq[p.index];
        char msg[240];
        if (p.due != cycle || dut->tag_o != p.index) {
            std::snprintf(msg, sizeof msg, "result at cycle %" PRIu64 " tag %u, expected cycle %" PRIu64 " tag %u",
                          cycle, dut->tag_o, p.due, p.index);
            report(v, p.index, msg, cycle);
        } else if (v.mode == 0) {
            if (dut->accept_o != v.accept || !eq(dut->state_o, v.sto)) {
                int n = std::snprintf(msg, sizeof msg, "got accept %d state", dut->accept_o);
                for (int k = NST; k-- > 0 && n < (int)sizeof msg - 10;)
                    n += std::snprintf(msg + n, sizeof msg - n, " %08x", dut->state_o[k]);
                report(v, p.index, msg, cycle);
            }
            accepted += v.accept;
        } else if (dut->accept_o || !eq(dut->l_o, v.lo)) {
            std::snprintf(msg, sizeof msg, "got accept %d l %08x %08x %08x", dut->accept_o,
                          dut->l_o[0], dut->l_o[1], dut->l_o[2]);
            report(v, p.index, msg, cycle);
        }
        checked++;
    }
};

}  // namespace

int main(int argc, char **argv)
{
    if (argc >= 3 && !std::strcmp(argv[1], "--chain")) {
        const uint64_t n = std::strtoull(argv[2], nullptr, 0);
        const double alpha = argc >= 4 ? std::atof(argv[3]) : 0.7;
        if (n < 1 || !(alpha > 0 && alpha <= 1)) { std::fprintf(stderr, "preu_bench: bad --chain arguments\n"); return 2; }
        VHarness<Vpree_preu> h(argc, argv);
        if (h.trace_error()) { std::fprintf(stderr, "preu_bench: %s\n", h.trace_error()); return 2; }
        h->valid_i = 0;
        h.reset(2);
        return chain(h, n, alpha);
    }
    std::vector<const char *> pos;
    for (int i = 1; i < argc; i++) if (argv[i][0] != '+') pos.push_back(argv[i]);
    int count = pos.size() > 0 ? std::atoi(pos[0]) : 200000;
    uint64_t seed = pos.size() > 1 ? std::strtoull(pos[1], nullptr, 0) : 1;
    if (count < 1) { std::fprintf(stderr, "preu_bench: count must be >= 1\n"); return 2; }

    // The harness holds the plusargs for the model; tracing is compiled in but off unless
    // +trace=FILE is given.
    VHarness<Vpree_preu> h(argc, argv);
    if (h.trace_error()) { std::fprintf(stderr, "preu_bench: %s\n", h.trace_error()); return 2; }
    Vpree_preu *const dut = &h.dut();

    std::vector<preu_vec_t> seq(count);
    preu_seq_gen(seq.data(), count, seed, DP);
    for (int i = 1; i < argc; i++) {
        unsigned long long bad;
        if (std::sscanf(argv[i], "+inject_error=%llu", &bad) == 1 && bad < (unsigned long long)count) {
            if (seq[bad].mode) seq[bad].lo[0] ^= 1; else seq[bad].sto[0] ^= 1;
        }
    }

    // Reset: two cycles with rst_ni low, inputs idle.
    dut->valid_i = 0; dut->mode_i = 0;
    h.reset(2);

    Run r(dut, seq, count);
    const uint64_t max_cycles = (uint64_t)count * (40 + RAD_LAT) + 1000;
    while (!r.done() && r.cycle < max_cycles) {
        r.drive();
        r.check_lreq();
        r.check_result();
        h.tick();
        r.cycle++;
    }

    const uint64_t cycle = r.cycle;
    bool ok = errors == 0 && r.checked == (uint64_t)count && r.results.empty();
    std::printf("preu_bench: %s datapath, seed %" PRIu64 ": %" PRIu64 " operations issued, %" PRIu64 " checked "
                "(%" PRIu64 " update accepted), %" PRIu64 " mode switches, %" PRIu64 " cycles, %" PRIu64
                " idle, %" PRIu64 " mismatches: %s\n",
                DP ? "stable" : "paper", seed, r.issued, r.checked, r.accepted, r.switches, cycle, r.idle, errors,
                ok ? "PASS" : "FAIL");
    if (!ok) {
        if (errors == 0) first_cycle = cycle;   // the run ended short: trace its last cycles
        fail_trace_bench(argc, argv, "preu_bench", DP ? "stable" : "paper", first_cycle, RAD_LAT + 16, 8);
    }
    return ok ? 0 : 1;
}
