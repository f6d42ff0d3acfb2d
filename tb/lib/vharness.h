// SPDX-License-Identifier: Apache-2.0
// vharness.h: the one Verilator harness of every bench (tb/) and of the co-simulation host
// (host/cosim_rtl.cpp), in the shape of ZipCPU's testb.h. It owns the context, the model, the
// optional FST trace and the cycle counter. tick() is one clock cycle evaluated once per edge
// through Verilator's public API only: clock low, eval, dump; clock high, eval, dump. A traced
// run does exactly the evaluations of an untraced one, plus the dumps (tests/checks/vharness_trace.sh).
// C++ and header-only because Verilated models are C++ classes of the bench's choosing.
//
//   VHarness<Vtop> h(argc, argv);   plusargs for the model; +trace=FILE opens an FST trace;
//                                   +trace_window=A:B dumps only cycles A..B of it
//   VHarness<Vtop> h(0, 0, path, hp);  a trace into path (NULL: none), hp time units per edge
//   h.trace_error()                 NULL, or "FILE: why the requested trace is not written"
//   h->port = v; h.eval();          settle new inputs without an edge (read combinational outputs)
//   h.tick();                       one cycle; h.cycles() counts them (reset cycles included)
//   h.trace_cycle()                 the cycles run since the first reset, which the trace's time
//                                   shows (a bench's cycle numbers, and a trace window's)
//   h.set_trace_window(a, b)        dump only cycles a..b (inclusive) of the open trace
//   h.tick(between);                the same, calling between() after the falling edge's eval
//                                   (a bench samples the handshakes of the cycle there)
//   h.reset(n[, settle]);           rst_ni low for n cycles, then high and settled (and settle
//                                   more cycles, for a reset synchroniser); these cycles are
//                                   neither dumped nor timed, so the trace starts at time 0
//                                   with the first cycle after reset
//   VHarness<Vtop, Ports>           Ports names the clock and reset (default clk_i, rst_ni):
//                                   struct with static clk(V &, int) and rst(V &, int)
// The clock rests high between ticks. Every module here uses the rising edge only (and
// asynchronous active-low resets), so inputs changed between ticks are sampled at the next
// rising edge, whichever edge the bench's previous clocking rested on. The trace's time advances
// half_period units per edge (default 1; the context's time, which $time in the RTL reads).
#ifndef PREE_VHARNESS_H
#define PREE_VHARNESS_H

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "verilated.h"
#if VM_TRACE_FST
#include "verilated_fst_c.h"
#endif

// The ports of the benches and pree_top: clk_i and an active-low rst_ni.
struct VHarnessPorts {
    template <class V> static void clk(V &t, int v) { t.clk_i = v; }
    template <class V> static void rst(V &t, int v) { t.rst_ni = v; }
};

template <class V, class Ports = VHarnessPorts>
class VHarness {
 public:
    explicit VHarness(int argc = 0, char **argv = nullptr, const char *trace = nullptr, uint64_t half_period = 1)
        : ctx_(new VerilatedContext), half_period_(half_period)
    {
        if (argc > 0) ctx_->commandArgs(argc, argv);
        if (!trace && argc > 0) {
            const char *m = ctx_->commandArgsPlusMatch("trace=");
            if (m && m[0]) trace = m + 7;   // past "+trace="
        }
        if (trace) ctx_->traceEverOn(true);   // must precede the model's construction
        top_.reset(new V{ctx_.get()});
        if (trace) open_trace(trace);
        if (argc > 0) {
            const char *w = ctx_->commandArgsPlusMatch("trace_window=");
            unsigned long long a, b;
            if (w && w[0] && std::sscanf(w + 14, "%llu:%llu", &a, &b) == 2) set_trace_window(a, b);
        }
    }
    ~VHarness()
    {
#if VM_TRACE_FST
        if (tfp_) tfp_->close();
#endif
        top_->final();
    }
    VHarness(const VHarness &) = delete;
    VHarness &operator=(const VHarness &) = delete;

    V *operator->() { return top_.get(); }
    const V *operator->() const { return top_.get(); }
    V &dut() { return *top_; }
    const char *trace_error() const { return trace_error_.empty() ? nullptr : trace_error_.c_str(); }
    uint64_t cycles() const { return cycles_; }
    uint64_t trace_cycle() const { return ctx_->time() / (2 * half_period_); }
    void set_trace_window(uint64_t from, uint64_t to) { win_from_ = from; win_to_ = to; }

    void eval() { top_->eval(); }

    void tick() { tick([] {}); }

    template <class F>
    void tick(F &&between)
    {
        Ports::clk(*top_, 0);
        top_->eval();
        between();
        dump();
        Ports::clk(*top_, 1);
        top_->eval();
        dump();
        cycles_++;
    }

    void reset(int n, int settle = 0)
    {
        Ports::rst(*top_, 0);
        in_reset_ = true;
        for (int i = 0; i < n; i++) tick();
        Ports::rst(*top_, 1);
        top_->eval();
        for (int i = 0; i < settle; i++) tick();
        in_reset_ = false;
    }

 private:
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<V> top_;
    uint64_t half_period_;
    uint64_t cycles_ = 0;
    bool in_reset_ = false;
    uint64_t win_from_ = 0, win_to_ = UINT64_MAX;   // the cycles the trace dumps
    std::string trace_error_;
#if VM_TRACE_FST
    std::unique_ptr<VerilatedFstC> tfp_;

    void open_trace(const char *path)
    {
        tfp_.reset(new VerilatedFstC);
        top_->trace(tfp_.get(), 99);
        tfp_->open(path);
        if (!tfp_->isOpen()) {
            tfp_.reset();
            trace_error_ = std::string(path) + ": cannot open the FST trace";
        }
    }
    void dump()
    {
        if (in_reset_) return;
        const uint64_t c = trace_cycle();
        if (tfp_ && c >= win_from_ && c <= win_to_) tfp_->dump(ctx_->time());
        ctx_->timeInc(half_period_);
    }
#else
    void open_trace(const char *path) { trace_error_ = std::string(path) + ": this model is built without --trace-fst"; }
    void dump()
    {
        if (!in_reset_) ctx_->timeInc(half_period_);
    }
#endif
};

#endif
