// SPDX-License-Identifier: Apache-2.0
// adiso_bench.cpp: Verilator bench for rtl/pree_adiso_rec.v against the C model adiso_model.c.
//
// For each hit-point count N: pulse start_i, then compare every cycle the RTL's addr_valid_o,
// addr_o and busy_o with adiso_eval() of the model (fed the same start and stall), until the
// pass ends. Independently of the model, every taken address (valid, stall_i low) is marked in
// a bitmap: each address of [0, N) must be taken exactly once, none outside it, and a pass
// without stalls must last exactly the largest group's size. Some passes are aborted by a
// second start in mid-pass; huge N (near 2^32) are compared over a window only.
//
// Usage: adiso_bench [--nmax M] [--random K] [--seed S] [--stall P]
//   --nmax M    every N in 0..M (default 2000)
//   --random K  K more passes with random N up to 2^20 (default 20), plus 4 huge-N windows
//   --stall P   stall probability for every other pass (default 0.2)
// Build defines: NUM_PREU, PIPE_DEPTH (must match the -G parameters). Exit 0 on pass.
#include "Vpree_adiso_rec.h"
#include "vharness.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

extern "C" {
#include "adiso_model.h"
#include "ctrl_rng.h"
}

#ifndef NUM_PREU
#define NUM_PREU 4
#endif
#ifndef PIPE_DEPTH
#define PIPE_DEPTH 12
#endif

namespace {

class Bench {
 public:
  Bench(int argc, char **argv) : top_(argc, argv) {
    adiso_init(&model_, NUM_PREU, PIPE_DEPTH);
    top_->start_i = 0;
    top_->stall_i = 0;
    top_->n_hit_i = 0;
    top_.reset(3);
  }
  const char *trace_error() const { return top_.trace_error(); }

  long errors = 0, checks = 0, cycles = 0, passes = 0, addresses = 0;

  // One pass over N hit points; abort_at > 0 restarts with the same N after that many cycles.
  // window > 0 only compares that many cycles (no coverage check).
  void pass(uint32_t n, double stall_p, uint64_t *rng, long abort_at, long window) {
    passes++;
    start(n);
    if (abort_at > 0) {
      for (long c = 0; c < abort_at && top_->busy_o; c++) cycle(ctrl_rng_unit(rng) < stall_p, n, nullptr);
      start(n);
    }
    std::vector<uint8_t> seen(window > 0 ? 0 : (size_t)n, 0);
    long c = 0, active = 0;
    while (top_->busy_o || model_busy()) {
      bool stall = ctrl_rng_unit(rng) < stall_p;
      cycle(stall, n, window > 0 ? nullptr : &seen);
      if (!stall) active++;
      if (++c > 4L * n + 100 || errors > 100) { fail(n, "pass does not end", -1, 0, 0); break; }
      if (window > 0 && c >= window) return;
    }
    cycle(false, n, &seen);  // one idle cycle: nothing may be valid after the pass
    for (uint32_t a = 0; a < n; a++)
      if (seen[a] != 1) { fail(n, "coverage: times address taken", (int)a, seen[a], 1); }
    uint32_t size = n / NUM_PREU;
    uint64_t longest = n - (uint64_t)(NUM_PREU - 1) * size;
    check(n, "cycles of the pass (not stalled)", -1, (uint64_t)active, longest);
  }

 private:
  VHarness<Vpree_adiso_rec> top_;
  adiso_model model_;

  bool model_busy() {
    adiso_out o;
    adiso_eval(&model_, &o);
    return o.busy;
  }

  void fail(uint32_t n, const char *what, int group, uint64_t got, uint64_t want) {
    if (errors < 20)
      std::fprintf(stderr, "MISMATCH N=%u cycle=%ld group/addr=%d %s: rtl=0x%" PRIx64 " expected=0x%" PRIx64 "\n",
                   n, cycles, group, what, got, want);
    errors++;
  }

  void check(uint32_t n, const char *what, int group, uint64_t got, uint64_t want) {
    checks++;
    if (got != want) fail(n, what, group, got, want);
  }

  void start(uint32_t n) {
    top_->start_i = 1;
    top_->n_hit_i = n;
    top_->stall_i = 0;
    top_->eval();
    top_.tick();
    adiso_step(&model_, 1, n, 0);
    top_->start_i = 0;
    top_->eval();
    cycles++;
  }

  void cycle(bool stall, uint32_t n, std::vector<uint8_t> *seen) {
    top_->stall_i = stall;
    top_->eval();
    adiso_out exp;
    adiso_eval(&model_, &exp);
    check(n, "busy_o", -1, top_->busy_o, (uint64_t)exp.busy);
    for (int g = 0; g < NUM_PREU; g++) {
      bool v = (top_->addr_valid_o >> g) & 1u;
      uint32_t a = top_->addr_o[g];
      check(n, "addr_valid_o", g, v, (uint64_t)exp.valid[g]);
      check(n, "addr_o", g, a, exp.addr[g]);
      if (v && !stall) {
        addresses++;
        if (seen) {
          if (a >= n) fail(n, "address outside [0, N)", g, a, n);
          else if (++(*seen)[a] > 1) fail(n, "address taken twice", g, a, 0);
        }
      }
    }
    top_.tick();
    adiso_step(&model_, 0, n, stall);
    cycles++;
  }
};

}  // namespace

int main(int argc, char **argv) {
  long nmax = 2000, nrand = 20;
  double stall_p = 0.2;
  uint64_t seed = 1;
  for (int i = 1; i < argc; i++) {
    if (!std::strcmp(argv[i], "--nmax") && i + 1 < argc) nmax = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--random") && i + 1 < argc) nrand = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 0);
    else if (!std::strcmp(argv[i], "--stall") && i + 1 < argc) stall_p = std::atof(argv[++i]);
    else if (argv[i][0] == '+') continue;
    else { std::fprintf(stderr, "usage: %s [--nmax M] [--random K] [--seed S] [--stall P]\n", argv[0]); return 2; }
  }
  Bench b(argc, argv);  // the harness takes the plusargs
  if (b.trace_error()) { std::fprintf(stderr, "adiso_bench: %s\n", b.trace_error()); return 2; }
  uint64_t rng = seed;

  // Exhaustive small N, stalls on every other pass, an abort now and then.
  for (long n = 0; n <= nmax && b.errors == 0; n++) {
    long abort_at = (n % 97 == 13) ? 1 + (long)ctrl_rng_below(&rng, 8) : 0;
    b.pass((uint32_t)n, (n & 1) ? stall_p : 0.0, &rng, abort_at, 0);
  }
  long small_passes = b.passes;
  // Large random N.
  for (long k = 0; k < nrand && b.errors == 0; k++) {
    uint32_t n = 2001u + ctrl_rng_below(&rng, 1u << 20);
    b.pass(n, (k & 1) ? stall_p : 0.0, &rng, 0, 0);
  }
  // Huge N: 33-bit sums leap + lv, compared with the model over a window.
  const uint32_t huge[] = {0xffffffffu, 0xfffffffeu, 0x80000001u, 0xc0000003u};
  for (uint32_t n : huge)
    if (nrand > 0 && b.errors == 0) b.pass(n, stall_p, &rng, 0, 5000);

  std::printf("adiso rtl-vs-model preu=%d pipe=%d N=0..%ld (%ld passes) + %ld random + %d huge windows: cycles=%ld addresses=%ld checks=%ld errors=%ld %s\n",
              NUM_PREU, PIPE_DEPTH, nmax, small_passes, nrand, nrand > 0 ? 4 : 0, b.cycles, b.addresses, b.checks, b.errors,
              b.errors ? "FAIL" : "PASS");
  return b.errors ? 1 : 0;
}
