// SPDX-License-Identifier: Apache-2.0
/* cosim_args.c: pree cosim's usage and command line (cosim_args.h). */
#include <stdio.h>
#include "cli.h"
#include "cli_options.h"
#include "cosim_args.h"
#include "cosim_rtl.h"
#include "cosim_sched.h"

#define STR_(x) #x
#define STR(x) STR_(x)
#define WINDOW_16_STR STR(COSIM_SCHED_WINDOW_16)

static void cosim_usage(FILE *f)
{
    fprintf(f,
        "usage: pree cosim SCENE [options]\n"
        "  --width W --height H --photons N --grid G --no-skip --threads T   as for 'pree render'\n"
        "                         (--threads: the eye pass and the double reference render)\n"
        "  --preu P               PREUs in the RTL: 1, 2, 4, 8 or 16 (default 4)\n"
        "  --datapath D --alpha A  the PREU datapath (paper or stable) and alpha, as for 'pree render'\n"
        "  --pipe-fast            the RTL with PipeFast = 1 (the deep PREU pipeline, docs/fpga.md)\n"
        "  --eye-rays N --exposure EV --radius R   as for 'pree render' (a pbrt file's sppm\n"
        "                         \"radius\" is the default --radius)\n"
        "  --hide-lights          as for 'pree render' (the host adds the lights' emitted radiance\n"
        "                         the eye sees to the RTL's pixels for --out; the pixel words\n"
        "                         compared are the RTL's own)\n"
        "  --trace FILE.fst       write an FST waveform of the whole run (slow)\n"
        "  --trace-window A:B     only cycles A..B of it (a failing run without --trace leaves\n"
        "                         the cycles around its first mismatch in build/pree-cosim-*-fail-c*.fst)\n"
        "  --out IMAGE            the RTL image (.png, .ppm or .exr)\n"
        "  --stats FILE.json      comparison, SSIM/SNR, cycles, utilization, stalls, speed\n"
        "  --no-reference         skip the double render (no SSIM/SNR)\n"
        "  --no-reorder           stream each photon's candidates in the engine's order\n"
        "  --refilter             at the engine's re-filter points (after photon blocks 1, 2, 4,\n"
        "                         ...) read the radii back from the PREE and re-filter the grid\n"
        "                         with them: fewer operations, a read-back cycle a hit point\n"
        "                         (docs/engine.md, \"The co-simulation host's re-filter\")\n"
        "  --no-schedule          stream photons in photon order (default: the host's scheduler\n"
        "                         reorders photons that share no hit point, against stalls)\n"
        "  --window W             photons the scheduler holds pending (default 128; " WINDOW_16_STR " with\n"
        "                         16 PREUs)\n"
        "  --layout L             hit-point addresses in the PREE: spatial (the engine's spatial\n"
        "                         order, the default: a photon's candidates lie in a few address\n"
        "                         runs, which the bank hash spreads) or pixel (the eye pass's order)\n"
        "  --model-only           the scheduler's cycle model alone (the RTL not clocked, no\n"
        "                         comparison): its predicted update pass in the --stats report\n"
        "  --gap P                idle cycles on the photon input with probability P (--axi: random\n"
        "                         back-pressure and gaps on every stream and AXI4-Lite channel)\n"
        "  --axi                  run through the AXI4 wrapper rtl/pree_axi.v (build/pree-cosim-axi-*)\n"
        "  --quiet                no progress on stderr\n"
        "under mpirun -np N: N PREEs, each rank's holding its partition of the hit points (the\n"
        "distributed render's) and sent only their operations; rank 0 compares the whole and\n"
        "writes the outputs, with each rank's figures and the load imbalance (docs/scale_out.md)\n");
}

enum { OPT_GAP = CLI_OWN, OPT_NO_REFERENCE, OPT_NO_REORDER, OPT_NO_SCHEDULE, OPT_WINDOW,
       OPT_TRACE, OPT_TRACE_WINDOW, OPT_OUT, OPT_STATS, OPT_MODEL_ONLY, OPT_AXI, OPT_REFILTER };

static const struct option cosim_longopts[] = {
    CLI_RENDER_LONGOPTS,
    {"gap", required_argument, NULL, OPT_GAP},
    {"no-reference", no_argument, NULL, OPT_NO_REFERENCE},
    {"no-reorder", no_argument, NULL, OPT_NO_REORDER},
    {"no-schedule", no_argument, NULL, OPT_NO_SCHEDULE},
    {"window", required_argument, NULL, OPT_WINDOW},
    {"trace", required_argument, NULL, OPT_TRACE},
    {"trace-window", required_argument, NULL, OPT_TRACE_WINDOW},
    {"out", required_argument, NULL, OPT_OUT},
    {"stats", required_argument, NULL, OPT_STATS},
    {"model-only", no_argument, NULL, OPT_MODEL_ONLY},
    {"axi", no_argument, NULL, OPT_AXI},
    {"refilter", no_argument, NULL, OPT_REFILTER},
    {NULL, 0, NULL, 0}
};

int cosim_parse_args(int argc, char **argv, int axi_program, render_options_t *opt, cosim_args_t *c)
{
    *c = (cosim_args_t){.reference = 1, .reorder = 1, .schedule = 1, .win_to = UINT64_MAX};
    cli_args_t a;
    cli_begin(&a, argc, argv, "cosim", cosim_longopts, opt, 11);
    for (int id; (id = cli_next(&a)) != 0;) {
        long long v;
        if (id < 0) return 2;
        switch (id) {
        case CLI_HELP: cosim_usage(stdout); return 0;
        case OPT_GAP:
            if (cli_real(&a, 0, 0, 1, &c->gap)) return 2;
            if (c->gap == 1) return cli_error(&a, "--gap: '%s' is not in [0, 1)", a.val);
            break;
        case OPT_NO_REFERENCE: c->reference = 0; break;
        case OPT_NO_REORDER: c->reorder = 0; break;
        case OPT_NO_SCHEDULE: c->schedule = 0; break;
        case OPT_REFILTER: c->refilter = 1; break;
        case OPT_WINDOW: if (cli_int(&a, 1, 4096, &v)) return 2; c->window = (int)v; break;
        case OPT_TRACE: c->trace = a.val; break;
        case OPT_TRACE_WINDOW: {
            unsigned long long w0, w1;
            char end;
            if (sscanf(a.val, "%llu:%llu%c", &w0, &w1, &end) != 2 || w1 < w0)
                return cli_error(&a, "--trace-window: '%s' is not FIRST:LAST (cycles)", a.val);
            c->win_from = w0;
            c->win_to = w1;
            break;
        }
        case OPT_OUT: if (cli_image_ext(&a, a.val)) return 2; c->out = a.val; break;
        case OPT_STATS: c->stats = a.val; break;
        case OPT_MODEL_ONLY: c->model_only = 1; break;
        case OPT_AXI: c->axi = 1; break;
        }
    }
    if (!(c->scene = cli_scene(&a))) return 2;
    c->pipefast = opt->pipe_fast;
    c->pixel_layout = opt->layout == HP_LAYOUT_PIXEL;
    if (!c->window) c->window = cosim_sched_default_window(opt->preu);
    if (c->model_only && !c->schedule) return cli_error(&a, "--model-only needs the scheduler (drop --no-schedule)");
    if (c->win_to != UINT64_MAX && !c->trace) return cli_error(&a, "--trace-window needs --trace");
    if (c->axi != axi_program)
        return cli_error(&a, c->axi ? "--axi: this program drives pree_top (run 'pree cosim --axi', build/pree-cosim-axi-*)"
                                    : "this program drives pree_axi: give --axi");
    if ((size_t)opt->width * (size_t)opt->height > (1u << COSIM_PXAW))
        return cli_error(&a, "%dx%d has more pixels than the RTL's pixel memory (%u)", opt->width, opt->height,
                         1u << COSIM_PXAW);
    return -1;
}

