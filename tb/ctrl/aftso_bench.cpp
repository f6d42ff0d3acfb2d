// SPDX-License-Identifier: Apache-2.0
// aftso_bench.cpp: Verilator bench for rtl/pree_aftso_hpuoc.v against the C model aftso_model.c.
//
// Every cycle the RTL's in_ready_o, empty_o and all lanes (valid, ref_addr, id, data, last;
// invalid lanes must be zero) are compared with aftso_eval() of the model, fed the same inputs.
// Independently of the model, a scoreboard checks that the operations taken (lanes valid with
// stall_i low) are exactly the accepted photons' candidate lists, in photon order, each list
// p_addr + N - 1 down to p_addr. Scenarios: random N^P distributions (zeros, small, around
// NumPreu, large, huge counts near 2^32), random input gaps and downstream stalls.
//
// Usage: aftso_bench [--seed S] [--scale K] [--np-file FILE]
//   --scale K       photons per scenario x K (default 1)
//   --np-file FILE  only measure utilization on these N^P values (one per line)
// Build defines: NUM_PREU, EARLY_READY, BUF_DEPTH, PPC (PhotonsPerCycle; must match the -G
// parameters). With PPC > 1 the source offers up to PPC photons side by side (fewer when it has
// fewer ready; the other slots N^P = 0). Exit 0 on pass.
#include "Vpree_aftso_hpuoc.h"
#include "vharness.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <vector>

extern "C" {
#include "aftso_model.h"
#include "ctrl_rng.h"
}

#ifndef NUM_PREU
#define NUM_PREU 4
#endif
#ifndef EARLY_READY
#define EARLY_READY 1
#endif

#ifndef BUF_DEPTH
#define BUF_DEPTH 4
#endif
#ifndef PPC
#define PPC 1
#endif

static const int kWords = 6;  // DataW = 192
static const int kBuf = BUF_DEPTH;

namespace {

// Word w (32 bits) of a port of any width: IData, QData or VlWide.
void set_word(uint32_t &port, int w, uint32_t v) { if (w == 0) port = v; }
void set_word(uint64_t &port, int w, uint32_t v) {
  const unsigned sh = 32u * (unsigned)w;
  port = (port & ~(0xffffffffull << sh)) | ((uint64_t)v << sh);
}
template <std::size_t N>
void set_word(VlWide<N> &port, int w, uint32_t v) { port[w] = v; }

struct Scenario {
  const char *name;
  int kind;          // N^P distribution, see draw_n()
  double gap;        // probability that the source offers nothing in a cycle
  double stall;      // probability of stall_i in a cycle
  long photons;
  bool drain;        // run until the buffer is empty (false: huge counts, stop after photons)
};

// One photon of the source.
struct Photon {
  uint32_t n, p_addr, id;
  uint32_t data[kWords];
};

// The operation the scoreboard expects next from one accepted photon.
struct Pending {
  uint32_t id, next_ref, left;
};

class Bench {
 public:
  Bench(int argc, char **argv) : top_(argc, argv) {}
  const char *trace_error() const { return top_.trace_error(); }

  long errors = 0, checks = 0, cycles = 0, ops = 0;

  // Reset the RTL and the model.
  void reset() {
    aftso_init(&model_, NUM_PREU, kBuf, PPC, kWords, EARLY_READY);
    sb_.clear();
    top_->in_valid_i = 0;
    top_->stall_i = 0;
    top_.reset(3);
  }

  // One cycle with the given input (np photons in slots 0..np-1, np <= PPC; np = 0: none) and
  // stall; returns whether the photons were accepted.
  bool cycle(const Photon *p, int np, bool stall, const char *scen) {
    aftso_in in;
    std::memset(&in, 0, sizeof in);
    in.valid = np > 0;
    for (int k = 0; k < np; k++) {
      in.ph[k].n = p[k].n; in.ph[k].p_addr = p[k].p_addr; in.ph[k].id = p[k].id;
      std::memcpy(in.ph[k].data, p[k].data, sizeof p[k].data);
    }
    top_->in_valid_i = in.valid;
    for (int k = 0; k < PPC; k++) {
      set_word(top_->in_n_i, k, in.ph[k].n);
      set_word(top_->in_p_addr_i, k, in.ph[k].p_addr);
      set_word(top_->in_id_i, k, in.ph[k].id);
      for (int w = 0; w < kWords; w++) top_->in_data_i[k * kWords + w] = in.ph[k].data[w];
    }
    top_->stall_i = stall;
    top_->eval();

    aftso_out exp;
    aftso_eval(&model_, stall, &exp);
    compare(exp, scen);
    bool accepted = in.valid && top_->in_ready_o;
    for (int k = 0; accepted && k < np; k++)
      if (in.ph[k].n) sb_.push_back(Pending{in.ph[k].id, in.ph[k].p_addr + in.ph[k].n - 1u, in.ph[k].n});
    if (!stall) scoreboard(scen);

    top_.tick();
    aftso_step(&model_, &in, stall);
    cycles++;
    return accepted;
  }

  bool empty() const { return top_->empty_o; }
  size_t pending() const { return sb_.size(); }
  int lanes_valid() const { return __builtin_popcount((unsigned)top_->lane_valid_o); }

 private:
  VHarness<Vpree_aftso_hpuoc> top_;
  aftso_model model_;
  std::deque<Pending> sb_;

  void fail(const char *scen, const char *what, int lane, uint64_t got, uint64_t want) {
    if (errors < 20)
      std::fprintf(stderr, "MISMATCH scenario=%s cycle=%ld lane=%d %s: rtl=0x%" PRIx64 " expected=0x%" PRIx64 "\n",
                   scen, cycles, lane, what, got, want);
    errors++;
  }

  void check(const char *scen, const char *what, int lane, uint64_t got, uint64_t want) {
    checks++;
    if (got != want) fail(scen, what, lane, got, want);
  }

  void compare(const aftso_out &exp, const char *scen) {
    check(scen, "in_ready_o", -1, top_->in_ready_o, (uint64_t)exp.ready);
    check(scen, "busy_o", -1, top_->busy_o, (uint64_t)!exp.ready);
    check(scen, "empty_o", -1, top_->empty_o, (uint64_t)exp.empty);
    uint64_t want_valid = exp.nvalid >= 64 ? ~0ull : ((1ull << exp.nvalid) - 1);
    check(scen, "lane_valid_o", -1, top_->lane_valid_o, want_valid);
    for (int l = 0; l < NUM_PREU; l++) {
      bool v = l < exp.nvalid;
      check(scen, "ref_addr", l, top_->lane_ref_addr_o[l], v ? exp.ref_addr[l] : 0);
      check(scen, "id", l, top_->lane_id_o[l], v ? exp.id[l] : 0);
      check(scen, "last", l, (top_->lane_last_o >> l) & 1u, v ? (uint64_t)exp.last[l] : 0);
      for (int w = 0; w < kWords; w++)
        check(scen, "data", l, top_->lane_data_o[l * kWords + w], v ? exp.data[l][w] : 0);
    }
  }

  // The taken lanes must continue the photon-ordered operation sequence.
  void scoreboard(const char *scen) {
    for (int l = 0; l < NUM_PREU; l++) {
      if (!((top_->lane_valid_o >> l) & 1u)) break;
      ops++;
      if (sb_.empty()) { fail(scen, "scoreboard: operation with no pending photon", l, 0, 0); continue; }
      Pending &p = sb_.front();
      checks++;
      if (top_->lane_id_o[l] != p.id || top_->lane_ref_addr_o[l] != p.next_ref) {
        fail(scen, "scoreboard id<<32|ref", l, ((uint64_t)top_->lane_id_o[l] << 32) | top_->lane_ref_addr_o[l],
             ((uint64_t)p.id << 32) | p.next_ref);
      }
      p.next_ref--;
      if (--p.left == 0) sb_.pop_front();
    }
  }
};

// Draw N^P for scenario kind k.
uint32_t draw_n(int kind, uint64_t *rng) {
  switch (kind) {
    case 0: return ctrl_rng_geometric(rng, 32.0);                    // realistic, mean 32
    case 1: return ctrl_rng_geometric(rng, 2.0);                     // many zeros and ones
    case 2: {                                                        // mixture
      uint32_t r = ctrl_rng_below(rng, 100);
      if (r < 20) return 0;
      if (r < 30) return 1000 + ctrl_rng_below(rng, 4000);
      if (r < 50) return NUM_PREU - 1 + ctrl_rng_below(rng, 3);
      return 1 + ctrl_rng_below(rng, 2 * NUM_PREU);
    }
    case 3: return 1;                                                // one hit point each
    case 4: return NUM_PREU;                                         // exactly one full cycle
    case 5: return 0;                                                // nothing at all
    case 6: return 0x80000000u + ctrl_rng_below(rng, 0x7fffffffu);   // huge: accuHP > 2^32
    default: return 1 + ctrl_rng_below(rng, 4 * NUM_PREU * kBuf);     // above the whole buffer's lanes
  }
}

Photon make_photon(int kind, uint64_t *rng, uint32_t id) {
  Photon p;
  p.n = draw_n(kind, rng);
  // Addresses near the top of the range exercise the modulo-2^32 wrap of ref_addr.
  p.p_addr = (ctrl_rng_below(rng, 8) == 0) ? 0xffffffffu - ctrl_rng_below(rng, 64) : (uint32_t)ctrl_rng_next(rng);
  p.id = id;
  for (int w = 0; w < kWords; w++) p.data[w] = (uint32_t)ctrl_rng_next(rng);
  return p;
}

// Run one scenario; returns the utilization (ops / (NUM_PREU * cycles)) of the run.
double run(Bench &b, const Scenario &s, const std::vector<uint32_t> *np_list, uint64_t seed) {
  uint64_t rng = seed;
  b.reset();
  long n_phot = np_list ? (long)np_list->size() : s.photons;
  long next = 0, made = 0, c0 = b.cycles, o0 = b.ops;
  int have = 0;
  Photon cur[PPC];
  long guard = 0;
  while (next < n_phot || (s.drain && !b.empty())) {
    // Fill the free slots, each with probability 1 - gap (a source that is not always ready).
    while (have < PPC && made < n_phot && ctrl_rng_unit(&rng) >= s.gap) {
      cur[have] = make_photon(s.kind, &rng, (uint32_t)made);
      if (np_list) cur[have].n = (*np_list)[made];
      have++;
      made++;
    }
    bool stall = ctrl_rng_unit(&rng) < s.stall;
    if (b.cycle(cur, have, stall, s.name)) { next += have; have = 0; }
    if (++guard > 200000000L || b.errors > 100) break;
    if (!s.drain && b.cycles - c0 >= 3000) break;  // huge counts never drain: check a window
  }
  if (s.drain && b.errors == 0 && b.pending() != 0) {
    std::fprintf(stderr, "MISMATCH scenario=%s: %zu photons not fully dispatched after the drain\n", s.name, b.pending());
    b.errors++;
  }
  long cyc = b.cycles - c0;
  return cyc ? (double)(b.ops - o0) / ((double)NUM_PREU * (double)cyc) : 0.0;
}

std::vector<uint32_t> read_np(const char *path) {
  std::vector<uint32_t> v;
  FILE *f = std::fopen(path, "r");
  if (!f) { std::perror(path); std::exit(2); }
  char line[128];
  while (std::fgets(line, sizeof line, f)) {
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '#' || *p == '\n' || *p == '\0') continue;
    v.push_back((uint32_t)std::strtoul(p, nullptr, 10));
  }
  std::fclose(f);
  return v;
}

}  // namespace

int main(int argc, char **argv) {
  uint64_t seed = 1;
  long scale = 1;
  const char *np_file = nullptr;
  for (int i = 1; i < argc; i++) {
    if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 0);
    else if (!std::strcmp(argv[i], "--scale") && i + 1 < argc) scale = std::atol(argv[++i]);
    else if (!std::strcmp(argv[i], "--np-file") && i + 1 < argc) np_file = argv[++i];
    else if (argv[i][0] == '+') continue;  // Verilator plusargs
    else { std::fprintf(stderr, "usage: %s [--seed S] [--scale K] [--np-file FILE]\n", argv[0]); return 2; }
  }
  Bench b(argc, argv);  // the harness takes the plusargs
  if (b.trace_error()) { std::fprintf(stderr, "aftso_bench: %s\n", b.trace_error()); return 2; }

  if (np_file) {
    std::vector<uint32_t> np = read_np(np_file);
    Scenario s{"np-file", 0, 0.0, 0.0, 0, true};
    double u = run(b, s, &np, seed);
    std::printf("aftso rtl np-file=%s preu=%d buf=%d ppc=%d early_ready=%d photons=%zu ops=%ld cycles=%ld utilization=%.6f%% checks=%ld errors=%ld\n",
                np_file, NUM_PREU, BUF_DEPTH, PPC, EARLY_READY, np.size(), b.ops, b.cycles, 100.0 * u, b.checks, b.errors);
    return b.errors ? 1 : 0;
  }

  const Scenario scen[] = {
      {"geo32", 0, 0.0, 0.0, 4000, true},
      {"geo32-gaps-stalls", 0, 0.3, 0.2, 2000, true},
      {"geo2-gaps-stalls", 1, 0.2, 0.3, 3000, true},
      {"mixture", 2, 0.1, 0.1, 1000, true},
      {"ones", 3, 0.0, 0.0, 500, true},
      {"ones-gaps", 3, 0.5, 0.5, 500, true},
      {"exact-numpreu", 4, 0.0, 0.1, 500, true},
      {"zeros", 5, 0.0, 0.0, 300, true},
      {"beyond-buffer", 7, 0.05, 0.05, 1000, true},
      {"huge-counts", 6, 0.0, 0.1, 200, false},
  };
  double util_geo = 0.0;
  for (size_t i = 0; i < sizeof scen / sizeof scen[0]; i++) {
    Scenario s = scen[i];
    s.photons *= scale;
    long c0 = b.cycles, o0 = b.ops;
    double u = run(b, s, nullptr, seed * 1000003u + i);
    if (i == 0) util_geo = u;
    std::printf("  %-20s cycles=%-8ld ops=%-8ld utilization=%.4f%%\n", s.name, b.cycles - c0, b.ops - o0, 100.0 * u);
  }
  std::printf("aftso rtl-vs-model preu=%d buf=%d ppc=%d early_ready=%d seed=%" PRIu64 " cycles=%ld ops=%ld checks=%ld errors=%ld geo32_utilization=%.4f%% %s\n",
              NUM_PREU, BUF_DEPTH, PPC, EARLY_READY, seed, b.cycles, b.ops, b.checks, b.errors, 100.0 * util_geo,
              b.errors ? "FAIL" : "PASS");
  return b.errors ? 1 : 0;
}
