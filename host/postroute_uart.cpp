// SPDX-License-Identifier: Apache-2.0
// postroute_uart.cpp: a simulated ULX3S for the UART back end (drv/pree_be_uart.h): the Verilated
// board top pree_ulx3s (the RTL, or the routed netlist of docs/fpga_board.md, "Post-route
// simulation"; the make rule passes PR_MODEL, PR_MODEL_H, PR_NP, PR_PF, PR_DIV, PR_KHZ) behind a
// byte channel. A UART model bit-bangs the host's bytes onto ftdi_txd (8N1, PR_DIV clock cycles a
// bit) and decodes ftdi_rxd, sampling each bit in its middle. The simulation counts core clock
// cycles (the PLL's model passes the clock pin's edges through); the channel's milliseconds are
// those of the core clock, PR_KHZ kHz.
// PREE_POSTROUTE_RECORD=<prefix> records the link for the timing-annotated replay
// (tb/postroute/postroute_replay_tb.v; docs/fpga_board.md, "Timing-annotated run"): <prefix>.txd
// and <prefix>.rxd, a line "<cycle> <level>" at each change of ftdi_txd (set before that cycle's
// rising edge) and of ftdi_rxd (after it), cycles counted from the first, reset included; and
// <prefix>.bytes, "<cycle> tx|rx <hex>" for each byte as it starts (tx) or is decoded (rx).
// It also provides what pree cosim's AXI host (host/cosim_axi.c, cosim_axi_rtl.h) needs of its
// model: the build's constants and cosim_axi_backend, the driver's back end on this board.
#include <cstdio>
#include <cstring>
#include <deque>
#include <string>

#include "cosim_axi_rtl.h"
#include "pree_be_uart.h"
extern "C" {
#include "pree_env.h"
}
#include PR_MODEL_H
#include "vharness.h"

namespace {
const uint64_t CYCLES_PER_MS = PR_KHZ;   // the core clock
struct BoardPorts {
    static void clk(PR_MODEL &t, int v) { t.clk_25mhz = v; }
    static void rst(PR_MODEL &t, int v) { t.btn_pwr_n = v; }
};
}

struct cosim_rtl {
    VHarness<PR_MODEL, BoardPorts> h;
    PR_MODEL *top;
    cosim_in_t in;                 // alpha and kappa only (cosim_main.c sets them)
    std::deque<uint8_t> txq, rxq;  // bytes to send, bytes received
    int tx_bit = -1;               // bit of the byte being sent (-1: idle; 0 start, 1..8 data, 9 stop)
    unsigned tx_cnt = 0;
    int rx_bit = -1;               // the same for the byte being received
    unsigned rx_cnt = 0, rx_byte = 0;
    char err[128] = "";
    FILE *rec_txd = nullptr, *rec_rxd = nullptr, *rec_bytes = nullptr;   // PREE_POSTROUTE_RECORD
    int last_txd = 1, last_rxd = -1;

    explicit cosim_rtl(const char *fst) : h(0, nullptr, fst), top(&h.dut())
    {
        std::memset(&in, 0, sizeof in);
        top->ftdi_txd = 1;         // the line idles high
        h.reset(2, 64);            // the PLL locks after 16 edges, then the reset synchroniser
    }
    ~cosim_rtl()
    {
        for (FILE *f : {rec_txd, rec_rxd, rec_bytes})
            if (f) std::fclose(f);
    }
    // Opens the records (PREE_POSTROUTE_RECORD); false with err set when one cannot be written.
    bool record(const char *prefix)
    {
        FILE **files[] = {&rec_txd, &rec_rxd, &rec_bytes};
        const char *ext[] = {".txd", ".rxd", ".bytes"};
        for (int i = 0; i < 3; i++) {
            const std::string path = std::string(prefix) + ext[i];
            if (!(*files[i] = std::fopen(path.c_str(), "w"))) {
                std::snprintf(err, sizeof err, "PREE_POSTROUTE_RECORD: cannot write %s", path.c_str());
                return false;
            }
        }
        return true;
    }
    void tick()
    {
        const uint64_t cyc = h.cycles();   // this tick's rising edge
        if (tx_bit < 0 && !txq.empty()) {
            tx_bit = 0;
            tx_cnt = 0;
            if (rec_bytes) std::fprintf(rec_bytes, "%llu tx %02x\n", (unsigned long long)cyc, txq.front());
        }
        if (tx_bit >= 0) {
            const unsigned b = txq.front();
            top->ftdi_txd = tx_bit == 0 ? 0 : tx_bit == 9 ? 1 : (b >> (tx_bit - 1)) & 1u;
            if (++tx_cnt == PR_DIV) {
                tx_cnt = 0;
                if (++tx_bit == 10) { tx_bit = -1; txq.pop_front(); }
            }
        } else {
            top->ftdi_txd = 1;
        }
        if (rec_txd && top->ftdi_txd != last_txd) {
            last_txd = top->ftdi_txd;
            std::fprintf(rec_txd, "%llu %d\n", (unsigned long long)cyc, last_txd);
        }
        h.tick();
        const unsigned line = top->ftdi_rxd;
        if (rec_rxd && (int)line != last_rxd) {
            last_rxd = (int)line;
            std::fprintf(rec_rxd, "%llu %d\n", (unsigned long long)cyc, last_rxd);
        }
        if (rx_bit < 0) {
            if (!line) { rx_bit = 0; rx_cnt = 0; rx_byte = 0; }
        } else if (++rx_cnt == (rx_bit == 0 ? PR_DIV / 2 : PR_DIV)) {   // the middle of each bit
            rx_cnt = 0;
            if (rx_bit == 0 && line) rx_bit = -1;   // a glitch, not a start bit
            else if (rx_bit >= 1 && rx_bit <= 8) rx_byte |= line << (rx_bit - 1);
            if (rx_bit == 9) {
                if (!line) std::snprintf(err, sizeof err, "ftdi_rxd: a byte without its stop bit");
                rxq.push_back((uint8_t)rx_byte);
                if (rec_bytes) std::fprintf(rec_bytes, "%llu rx %02x\n", (unsigned long long)cyc, rx_byte);
                rx_bit = -1;
            } else if (rx_bit >= 0) {
                rx_bit++;
            }
        }
    }
    uint64_t now_ms() const { return h.cycles() / CYCLES_PER_MS; }
};

namespace {
int ch_send(void *ctx, const uint8_t *b, size_t n)
{
    cosim_rtl *r = static_cast<cosim_rtl *>(ctx);
    r->txq.insert(r->txq.end(), b, b + n);
    return 0;
}
long ch_recv(void *ctx, uint8_t *b, size_t n, uint64_t deadline_ms)
{
    cosim_rtl *r = static_cast<cosim_rtl *>(ctx);
    size_t got = 0;
    for (;;) {
        while (got < n && !r->rxq.empty()) { b[got++] = r->rxq.front(); r->rxq.pop_front(); }
        if (r->err[0]) return -1;
        if (got == n || r->now_ms() >= deadline_ms) return (long)got;
        r->tick();
    }
}
uint64_t ch_now(void *ctx) { return static_cast<cosim_rtl *>(ctx)->now_ms(); }
const char *ch_error(void *ctx) { return static_cast<cosim_rtl *>(ctx)->err; }
void ch_close(void *) {}   // the model stays cosim_main's (cosim_rtl_free)
}

extern "C" {

cosim_rtl_t *cosim_rtl_new(int preu, int datapath, int pipefast, const char *fst, char *err, size_t errlen)
{
    if (preu != PR_NP || datapath != 0 || pipefast != PR_PF) {
        std::snprintf(err, errlen, "this program simulates the board top with %d PREU(s), the paper's datapath and "
                      "%s stages (--preu %d%s)", PR_NP, PR_PF ? "the deep" : "the paper's", PR_NP,
                      PR_PF ? " --pipe-fast" : "");
        return nullptr;
    }
    cosim_rtl_t *r = new cosim_rtl(fst);
    if (const char *te = r->h.trace_error()) {
        std::snprintf(err, errlen, "%s", te);
        delete r;
        return nullptr;
    }
    const char *rec = pree_env(PREE_ENV_POSTROUTE_RECORD);
    if (rec && rec[0] && !r->record(rec)) {
        std::snprintf(err, errlen, "%s", r->err);
        delete r;
        return nullptr;
    }
    return r;
}
void cosim_rtl_free(cosim_rtl_t *r)
{
    if (r) std::fprintf(stderr, "board: %llu clock cycles run (%llu ms at %.3f MHz)\n", (unsigned long long)r->h.cycles(),
                        (unsigned long long)r->now_ms(), PR_KHZ / 1000.0);
    delete r;
}
cosim_in_t *cosim_rtl_in(cosim_rtl_t *r) { return &r->in; }
int cosim_rtl_hp_bank_w(cosim_rtl_t *) { return PR_HPB; }
int cosim_rtl_update_window(cosim_rtl_t *) { return PREE_UPDATE_WINDOW(0, PR_PF); }
int cosim_rtl_reg_flow(cosim_rtl_t *) { return PR_PF ? 1 : 0; }
int cosim_rtl_ppc(cosim_rtl_t *) { return 1; }
int cosim_rtl_radiance_depth(cosim_rtl_t *) { return PREE_RADIANCE_DEPTH(PR_PF); }
uint64_t cosim_rtl_cycle(cosim_rtl_t *r) { return r->h.trace_cycle(); }
void cosim_rtl_trace_window(cosim_rtl_t *r, uint64_t from, uint64_t to) { r->h.set_trace_window(from, to); }
int cosim_rtl_config(int, int *, int *) { return -1; }

int cosim_axi_backend(pree_backend_t *be, cosim_rtl_t *r, const cosim_drv_opts_t *opt, char *err, size_t errlen)
{
    (void)opt;   // no gaps: the UART paces every stream
    const pree_uart_chan_t ch = {r, ch_send, ch_recv, ch_now, ch_error, ch_close};
    return pree_be_uart_open(be, &ch, err, errlen);
}

}  // extern "C"
