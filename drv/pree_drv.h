// SPDX-License-Identifier: Apache-2.0
/* pree_drv.h: the driver of pree_axi (rtl/pree_axi.v, docs/integration.md): open, configure, load
 * hit points, stream photons with their candidates, run the radiance pass, read hit points,
 * pixels and counters. C11; every call returns PREE_OK (0) or a negative PREE_E_* code, and
 * pree_error() says what failed in one line. The hardware is reached through a back end
 * (pree_backend_t below): drv/pree_be_verilated.c (the Verilated wrapper, for tests) and
 * drv/pree_be_uio.c (a board: the register block through Linux UIO or /dev/mem, the streams
 * through Xilinx AXI DMA engines).
 *
 * Sequence (the driver checks STATUS.IDLE before every command and ERR after every wait):
 *   pree_open(&d, &be)                     VERSION 2.x, CONFIG0/1 read into pree_config()
 *   pree_set_constants(d, &c)              NE, ALPHA, KAPPA, N_HIT (binary32 bits; N_HIT a count)
 *   pree_load_hit_points(d, 0, hp, n)      s_axis_hp from HP_PTR = first
 *   pree_counters_enable(d, 1)
 *   pree_send_photons(d, ph, cand, n)      photons on s_axis_ph, their candidates on s_axis_cand
 *   pree_end_batch(d)                      tlast, wait for the batch interrupt
 *   pree_radiance(d, n_hit, ne, 0, npix)   clear the pixels, run the pass
 *   pree_read_hit_points / pree_read_pixels / pree_read_counters
 * A driver is not thread-safe; one driver a device. */
#ifndef PREE_DRV_H
#define PREE_DRV_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    PREE_OK = 0,
    PREE_E_ARG = -1,       /* a bad argument (size, count, a photon with too many candidates) */
    PREE_E_IO = -2,        /* the back end failed (its message is in pree_error) */
    PREE_E_VERSION = -3,   /* VERSION is not 2.x: not a pree_axi, or an incompatible one */
    PREE_E_BUSY = -4,      /* a command or a constant while STATUS.IDLE is 0 */
    PREE_E_HW = -5,        /* the ERR register is set (CMD_REFUSED, PH_TOO_BIG) */
    PREE_E_TIMEOUT = -6,   /* no interrupt in time */
    PREE_E_NOMEM = -7,
    PREE_E_STREAM = -8     /* m_axis delivered fewer or other beats than asked for */
};

/* Streams of the back end. */
enum { PREE_STREAM_HP, PREE_STREAM_PH, PREE_STREAM_CAND };

/* The back end: the register block and the four streams. Words are 32-bit, little-endian, slot
 * i of a beat = word i. Every call returns 0 or -1 (then error() says why). */
typedef struct {
    void *ctx;
    int (*reg_read)(void *ctx, uint32_t offset, uint32_t *value);
    int (*reg_write)(void *ctx, uint32_t offset, uint32_t value);
    /* Queue nwords words on a stream as beats of beat_words words (the candidate stream: the
     * last beat may be partial, its missing lanes with tkeep low); last: tlast on the final beat.
     * May return before the beats are taken; the words are copied. */
    int (*submit)(void *ctx, int stream, const uint32_t *words, size_t nwords, unsigned beat_words, int last);
    /* Arm m_axis: the next nbeats beats of beat_words words go to words (and stay owned by the
     * back end until wait() returns); user: tuser expected on every beat. */
    int (*receive)(void *ctx, uint32_t *words, size_t nbeats, unsigned beat_words, int user);
    /* Wait until every submitted beat is taken and every armed beat received, and with irq also
     * until irq_o is high. 1: so; 0: timeout_ms passed first (the Verilated back end counts
     * them in cycles of a 100 MHz aclk). */
    int (*wait)(void *ctx, int irq, unsigned timeout_ms);
    const char *(*error)(void *ctx);
    void (*close)(void *ctx);
} pree_backend_t;

/* The build, from CONFIG0 and CONFIG1. */
typedef struct {
    uint32_t version;
    unsigned num_preu, hp_aw, px_aw, idx_aw, datapath, hp_bank_w, px_bank_w, cnt_w, photons_per_cycle;
    unsigned state_words;   /* words of a hit point's state: 5 (paper) or 10 (stable) */
    unsigned hp_words;      /* words of a s_axis_hp / m_axis beat: state_words + 7 */
    unsigned max_cand;      /* candidates a photon may have: 2^IdxAW - NumPreu */
} pree_config_t;

/* A hit point as on s_axis_hp (binary32 bits): the state (docs/preu_datapath.md; the first
 * state_words words), position, weight f, pixel index. */
typedef struct {
    uint32_t state[10];
    uint32_t pos[3], f[3];
    uint32_t pixel;
} pree_hit_point_t;

/* A photon: position, flux (binary32 bits) and the number of its candidates. */
typedef struct {
    uint32_t pos[3], phi[3];
    uint32_t n_cand;
} pree_photon_t;

/* The constants (binary32 bits; n_hit a count). */
typedef struct {
    uint32_t ne, alpha, kappa, n_hit;
} pree_constants_t;

typedef struct pree_drv pree_drv_t;

/* Counters (pree_top's, 48 bits): 0 update cycles, 1 radiance cycles, 2 haz, 3 dup, 4 bank,
 * 5 abank, 6 starved, 7 + l operations of PREU l. */
#define PREE_NCNT_MAX 32

/* The driver owns the back end from here on. On failure *d is still set when it could be
 * allocated (pree_error(*d) says why; pree_close it), else NULL with the back end closed. */
int pree_open(pree_drv_t **d, const pree_backend_t *be);
void pree_close(pree_drv_t *d);   /* closes the back end too */
const char *pree_error(const pree_drv_t *d);
const pree_config_t *pree_config(const pree_drv_t *d);

int pree_set_constants(pree_drv_t *d, const pree_constants_t *c);
/* on: 1 counting (CTRL.CNT_EN), 0 not; PREE_CNT_WORK: the driver counts the engine's work only,
 * switching CNT_EN on as a batch's first photons go and off once its interrupt is taken
 * (pree_send_photons .. pree_end_batch), and on around the radiance pass's command; the register
 * traffic between (loads, reads, checks) is not counted. */
#define PREE_CNT_WORK 2
int pree_counters_enable(pree_drv_t *d, int on);
/* IRQ_EN (bit 0 batch done, bit 1 command done). The driver waits through the back end's wait()
 * on irq_o, so both are on after pree_open; a mask without them leaves waits to time out. */
int pree_irq_enable(pree_drv_t *d, uint32_t mask);
/* Give up a wait after timeout_ms (default 10000). */
void pree_set_timeout(pree_drv_t *d, unsigned timeout_ms);

int pree_load_hit_points(pree_drv_t *d, uint32_t first, const pree_hit_point_t *hp, size_t n);
/* n photons and their candidates (cand: the lists concatenated, photon order, distinct hit
 * points within a photon); returns once the beats are queued. */
int pree_send_photons(pree_drv_t *d, const pree_photon_t *ph, const uint32_t *cand, size_t n);
/* Close the batch (an empty photon with tlast) and wait until all of it is applied. */
int pree_end_batch(pree_drv_t *d);

int pree_clear_pixels(pree_drv_t *d, uint32_t first, uint32_t n);
/* The radiance pass over hit points [0, n_hit) with N_emitted ne into cleared pixels
 * [first, first + npix) (cleared first). */
int pree_radiance(pree_drv_t *d, uint32_t n_hit, uint32_t ne, uint32_t first, uint32_t npix);
int pree_read_hit_points(pree_drv_t *d, uint32_t first, pree_hit_point_t *hp, size_t n);
/* rgb: 3 n words, {r, g, b} binary32 a pixel. */
int pree_read_pixels(pree_drv_t *d, uint32_t first, uint32_t *rgb, size_t n);
/* cnt[0 .. 7 + NumPreu - 1]; n at least that. */
int pree_read_counters(pree_drv_t *d, uint64_t *cnt, size_t n);
/* PH_IN, PH_DONE, CAND_IN. */
int pree_read_stream_counts(pree_drv_t *d, uint32_t *ph_in, uint32_t *ph_done, uint32_t *cand_in);

/* Raw register access (byte offsets of drv/pree_axi_regs.h). */
int pree_reg_read(pree_drv_t *d, uint32_t offset, uint32_t *value);
int pree_reg_write(pree_drv_t *d, uint32_t offset, uint32_t value);
/* Read ERR: PREE_E_HW with its bits named in pree_error() when set (and cleared), else PREE_OK. */
int pree_check_err(pree_drv_t *d);

/* The photon stream's beat layout (one place): photons packed into beats of
 * photons_per_cycle slots at the slot pitch; an unused slot is empty (N^P = 0). */
#define PREE_PH_SLOT_WORDS 8   /* 256-bit slots: pos x y z, phi r g b, N^P, reserved (0) */
size_t pree_pack_photons(const pree_config_t *cfg, const pree_photon_t *ph, size_t n, uint32_t *words);

#ifdef __cplusplus
}
#endif

#endif
