// SPDX-License-Identifier: Apache-2.0
// fp32_bench.cpp: Verilator bench for one binary32 unit, checked bit for bit against
// model/pree/fp32_ops.h, or for the stable datapath's pree_wacc and pree_u64_to_f32 against
// model/pree/wide_acc.h (through fp32_gen.c).
//
// Built once per unit configuration with -DFP32_UNIT_<ADD|MUL|SQR|DIV|CMP|WACC|U2F> and the
// matching Verilated model and -DFP32_LATENCY=<its latency> (mk/fp32.mk, from the configuration
// table), which the bench then requires of every operation; without it, the unit's default
// latency at PipeFast 0 (model/pree/pree_config.h).
// Usage: fp32_bench_<unit> [random_count [seed [sweep]]]  (defaults 200000, 1). Runs the
// directed list, then (with the word "sweep", squarer only) the exhaustive significand sweep of
// fp32_gen.c, then random_count random cases. Pipelined units get random gaps in valid_i (bursts of varying
// density) and a scoreboard keyed on the handshake: an expected result is pushed when an
// operation is accepted and popped when valid_o appears, which must be exactly LATENCY cycles
// later. Operands driven while valid_i is low are random, so stale data cannot hide.
// Prints the first 20 mismatches in hex with their inputs; exit status 1 on any mismatch.
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>

#include "fp32_gen.h"
#include "pree/pree_config.h"
#include "vharness.h"

// Per unit: the model, the module name and the latency; then the hex digits of a and y in reports.
#ifdef FP32_LATENCY
#define UNIT_LATENCY(default_latency) (FP32_LATENCY)   // the configuration's, from mk/fp32.mk
#else
#define UNIT_LATENCY(default_latency) (default_latency)   // the unit's default (PipeFast 0)
#endif
#if defined(FP32_UNIT_ADD)
#include "Vpree_fp32_add.h"
typedef Vpree_fp32_add Dut;
static const fp32_unit_t UNIT = FP32_ADD;
static const char *const TOP = "pree_fp32_add";
static const int LATENCY = UNIT_LATENCY(PREE_ADD_STAGES_PF0);
#elif defined(FP32_UNIT_MUL)
#include "Vpree_fp32_mul.h"
typedef Vpree_fp32_mul Dut;
static const fp32_unit_t UNIT = FP32_MUL;
static const char *const TOP = "pree_fp32_mul";
static const int LATENCY = UNIT_LATENCY(PREE_MUL_STAGES_PF0);
#elif defined(FP32_UNIT_SQR)
#include "Vpree_fp32_sqr.h"
typedef Vpree_fp32_sqr Dut;
static const fp32_unit_t UNIT = FP32_SQR;
static const char *const TOP = "pree_fp32_sqr";
static const int LATENCY = UNIT_LATENCY(PREE_SQR_STAGES_PF0);
#elif defined(FP32_UNIT_DIV)
#include "Vpree_fp32_div.h"
typedef Vpree_fp32_div Dut;
static const fp32_unit_t UNIT = FP32_DIV;
static const char *const TOP = "pree_fp32_div";
static const int LATENCY = UNIT_LATENCY(PREE_DIV_STAGES_PF0);
#elif defined(FP32_UNIT_CMP)
#include "Vpree_fp32_cmp.h"
typedef Vpree_fp32_cmp Dut;
static const fp32_unit_t UNIT = FP32_CMP;
static const char *const TOP = "pree_fp32_cmp";
static const int LATENCY = 0;
#elif defined(FP32_UNIT_WACC)
#include "Vpree_wacc.h"
typedef Vpree_wacc Dut;
static const fp32_unit_t UNIT = FP32_WACC;
static const char *const TOP = "pree_wacc";
static const int LATENCY = UNIT_LATENCY(PREE_WACC_STAGES_PF0);
#elif defined(FP32_UNIT_U2F)
#include "Vpree_u64_to_f32.h"
typedef Vpree_u64_to_f32 Dut;
static const fp32_unit_t UNIT = FP32_U2F;
static const char *const TOP = "pree_u64_to_f32";
static const int LATENCY = UNIT_LATENCY(PREE_U2F_STAGES_PF0);
#else
#error "define FP32_UNIT_ADD, _MUL, _SQR, _DIV, _CMP, _WACC or _U2F"
#endif
static const int A_DIGITS = (UNIT == FP32_WACC || UNIT == FP32_U2F) ? 16 : 8;
static const int Y_DIGITS = UNIT == FP32_WACC ? 16 : 8;

namespace {

const int MAX_REPORT = 20;

struct Pending {
    fp32_case_t c;
    uint64_t issue_cycle;
};

// Counts and prints mismatches; only the first MAX_REPORT are printed.
struct Scoreboard {
    uint64_t checked = 0, errors = 0;

    void fail(const fp32_case_t &c, uint64_t got, const char *why)
    {
        if (errors++ < MAX_REPORT)
            std::printf("MISMATCH %s: a=%0*" PRIx64 " b=%08" PRIx32 " sub=%" PRIu32
                        " expected=%0*" PRIx64 " got=%0*" PRIx64 " (%s)\n",
                        fp32_unit_name(UNIT), A_DIGITS, c.a, c.b, c.sub, Y_DIGITS, c.y,
                        Y_DIGITS, got, why);
    }

    void check(const fp32_case_t &c, uint64_t got)
    {
        checked++;
        if (got != c.y) fail(c, got, "value");
    }
};

// The next case: the directed list first, then random ones.
struct Source {
    size_t directed, swept, next = 0;
    uint64_t total;
    uint64_t rng;

    Source(uint64_t random_count, uint64_t seed, bool sweep)
        : directed(fp32_directed_count(UNIT)), swept(sweep ? fp32_sweep_count(UNIT) : 0),
          total(directed + swept + random_count), rng(seed * 0x9E3779B97F4A7C15ULL + 1) {}

    bool done() const { return next >= total; }

    fp32_case_t take()
    {
        fp32_case_t c;
        if (next < directed) fp32_directed(UNIT, next, &c);
        else if (next < directed + swept) fp32_sweep(UNIT, next - directed, &c);
        else fp32_random(UNIT, &rng, &c);
        next++;
        return c;
    }
};

#if !defined(FP32_UNIT_CMP)
void drive(Dut &dut, const fp32_case_t &c)
{
    dut.a_i = c.a;   // 64-bit port (QData) for wacc and u2f, else the low 32 bits
#if defined(FP32_UNIT_WACC)
    dut.t_i = c.b;
#elif !defined(FP32_UNIT_SQR) && !defined(FP32_UNIT_U2F)
    dut.b_i = c.b;
#endif
#if defined(FP32_UNIT_ADD)
    dut.sub_i = c.sub;
#endif
}

// Clocked units: random valid gaps, handshake-keyed scoreboard, exact latency check.
int run(VHarness<Dut> &h, Source &src, Scoreboard &sb)
{
    Dut &dut = h.dut();
    std::deque<Pending> queue;
    uint32_t density = 16;   // valid_i probability in 1/16 steps, changed every burst

    dut.valid_i = 0;
    h.reset(3);
    h.tick();

    while (!src.done() || !queue.empty()) {
        const uint64_t cycle = h.cycles();
        if (cycle % 256 == 0) {
            static const uint32_t densities[] = { 16, 16, 15, 12, 8, 4, 1 };
            density = densities[fp32_rng_next(&src.rng) % 7];
        }
        bool issue = !src.done() && (fp32_rng_next(&src.rng) >> 60) < density;
        if (issue) {
            Pending p = { src.take(), cycle };
            drive(dut, p.c);
            queue.push_back(p);
        } else {
            fp32_case_t junk;
            fp32_random(UNIT, &src.rng, &junk);   // operands with valid_i low must not matter
            drive(dut, junk);
        }
        dut.valid_i = issue;
        h.tick();

        // After this edge, an operation issued LATENCY cycles ago must be on the output.
        bool due = !queue.empty() && queue.front().issue_cycle + LATENCY == h.cycles();
        if (dut.valid_o && !due) {
            fp32_case_t none = {};
            sb.fail(none, dut.y_o, "valid_o without an operation due");
            return 1;
        }
        if (due && !dut.valid_o) {
            sb.fail(queue.front().c, dut.y_o, "valid_o missing at LATENCY");
            return 1;
        }
        if (due) {
            sb.check(queue.front().c, dut.y_o);
            queue.pop_front();
        }
    }
    return 0;
}
#else
// The comparator is combinational: drive, settle, compare the four flags.
int run(VHarness<Dut> &h, Source &src, Scoreboard &sb)
{
    Dut &dut = h.dut();
    while (!src.done()) {
        fp32_case_t c = src.take();
        dut.a_i = c.a; dut.b_i = c.b;
        dut.eval();
        uint32_t got = (uint32_t)(dut.unordered_o << 3 | dut.eq_o << 2 | dut.le_o << 1 | dut.lt_o);
        sb.check(c, got);
    }
    return 0;
}
#endif

}  // namespace

int main(int argc, char **argv)
{
    uint64_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 0) : 200000;
    uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0) : 1;
    bool sweep = argc > 3 && std::string(argv[3]) == "sweep";

    // The harness owns the model and finalises it on every return path.
    VHarness<Dut> h(argc, argv);
    if (h.trace_error()) { std::fprintf(stderr, "fp32_bench: %s\n", h.trace_error()); return 2; }

    Source src(count, seed, sweep);
    Scoreboard sb;
    int protocol_error = run(h, src, sb);

    std::printf("%s (latency %d): %zu directed + %zu sweep + %" PRIu64 " random "
                "(seed %" PRIu64 "): %" PRIu64 " checked, %" PRIu64 " mismatches%s\n",
                TOP, LATENCY, src.directed, src.swept, count, seed, sb.checked,
                sb.errors, protocol_error ? ", handshake error" : "");
    if (sb.errors || protocol_error || sb.checked != src.total) {
        std::printf("FAIL: rerun with: %s %" PRIu64 " %" PRIu64 "%s\n", argv[0], count, seed,
                    sweep ? " sweep" : "");
        return 1;
    }
    return 0;
}
