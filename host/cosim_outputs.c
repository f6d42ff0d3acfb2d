// SPDX-License-Identifier: Apache-2.0
/* cosim_outputs.c: the outputs of cosim_outputs.h. */
#include <math.h>
#include <stdio.h>
#include "compare.h"
#include "cosim_outputs.h"
#include "fp32_ops.h"
#include "image.h"
#include "radiance.h"

static void to_float(const double *rgb, size_t n, float *out)
{
    for (size_t i = 0; i < n; i++) out[i] = (float)rgb[i];
}


/* SSIM, SNR and the rest of the RTL image rgb against a double-precision render of the same
 * scene, photons and grid: 0, or -1 with a message printed (-2: the comparison alone failed). */
static int reference_metrics(const scene_t *scene, const render_options_t *opt, const double *rgb, pree_metrics_t *m)
{
    char err[1024];
    const size_t npix = (size_t)opt->width * (size_t)opt->height;
    render_options_t ropt = {.width = opt->width, .height = opt->height, .photons = opt->photons,
                             .precision = PRECISION_DOUBLE, .grid = opt->grid, .threads = opt->threads,
                             .no_skip = opt->no_skip, .preu = opt->preu, .one_rank = 1};
    render_result_t ref = {0};
    if (render_run(scene, &ropt, &ref, err, sizeof err)) {
        fprintf(stderr, "pree cosim: reference: %s\n", err);
        render_result_free(&ref);
        return -1;
    }
    pree_image_t ia = {0}, ib = {0};
    int rc = 0;
    if (pree_image_alloc(&ia, opt->width, opt->height, err, sizeof err) ||
        pree_image_alloc(&ib, opt->width, opt->height, err, sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        rc = -1;
    } else {
        to_float(ref.rgb, npix * 3, ia.rgb);
        to_float(rgb, npix * 3, ib.rgb);
        if (pree_compare(&ia, &ib, m, err, sizeof err)) { fprintf(stderr, "pree cosim: compare: %s\n", err); rc = -2; }
    }
    pree_image_free(&ia);
    pree_image_free(&ib);
    render_result_free(&ref);
    return rc;
}

int cosim_image_out(const cosim_args_t *c, const scene_t *scene, const render_options_t *opt, const uint32_t *Lr,
                    const double *emitted, double *rgb, cosim_report_t *rep)
{
    char err[1024];
    const size_t npix = (size_t)opt->width * (size_t)opt->height;
    for (size_t j = 0; j < npix * 3; j++) rgb[j] = (double)fp32_from_bits(Lr[j]);
    radiance_add_emitted(rgb, emitted, npix, PRECISION_FP32);   /* as the fp32 render adds them */
    if (c->out && pree_image_write_scaled(c->out, opt->width, opt->height, rgb, NULL, exp2(opt->exposure), err,
                                          sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        return -1;
    }
    if (c->reference) {
        const int m = reference_metrics(scene, opt, rgb, &rep->m);
        if (m == -1) return -1;
        rep->have_metrics = m == 0;
    }
    return 0;
}

int cosim_finish_report(cosim_report_t *rep, const cosim_args_t *c, int progress)
{
    char err[1024];
    cosim_report_figures(rep);
    if (rep->ops_upd != rep->ops_sent)
        fprintf(stderr, "pree cosim: %llu update operations sent, %llu counted in the RTL\n",
                (unsigned long long)rep->ops_sent, (unsigned long long)rep->ops_upd);
    if (c->stats && cosim_report_write(c->stats, rep, err, sizeof err)) {
        fprintf(stderr, "pree cosim: %s\n", err);
        return 1;
    }
    if (progress && c->model_only)
        fprintf(stderr, "pree cosim: cycle model, %d PREUs: %llu ops in %llu cycles (utilization %.4f%%)\n",
                rep->preu, (unsigned long long)rep->ops_upd, (unsigned long long)rep->cyc_upd, 100 * rep->util_upd);
    else if (progress && rep->mpi_ranks > 1) {
        for (int k = 0; k < rep->mpi_ranks; k++) {
            const cosim_rank_t *q = &rep->ranks[k];
            fprintf(stderr, "pree cosim: rank %d of %d: %d PREUs, %llu hit points: %llu ops in %llu cycles "
                    "(utilization %.4f%%); radiance %llu cycles; image words differing %llu\n", k, rep->mpi_ranks,
                    rep->preu, (unsigned long long)q->hit_points, (unsigned long long)q->ops,
                    (unsigned long long)q->cycles, 100 * q->utilization, (unsigned long long)q->radiance_cycles,
                    (unsigned long long)q->image_words_differing);
        }
        fprintf(stderr, "pree cosim: %d PREEs of %d PREUs: load imbalance %.4f (max / mean update cycles), "
                "utilization %.4f%% over the longest; differing words: hit points %llu, image %llu%s "
                "(against one PREE's radiance order, which adds a pixel's hit points in another order: %llu, at most %llu "
                "ulps)\n", rep->mpi_ranks, rep->preu, rep->imbalance, 100 * rep->util_all, rep->hp_diff, rep->img_diff,
                rep->pass ? "" : " FAIL", rep->img_diff_one_pree, rep->img_max_ulp_one_pree);
    } else if (progress)
        fprintf(stderr, "pree cosim: %d PREUs: %llu ops in %llu cycles (utilization %.4f%%), %.0f ops/CPU-s; "
                "differing words: hit points %llu, image %llu%s\n",
                rep->preu, (unsigned long long)rep->ops_upd, (unsigned long long)rep->cyc_upd, 100 * rep->util_upd,
                rep->sim_ops_per_cpu_s, rep->hp_diff, rep->img_diff, rep->pass ? "" : " FAIL");
    return rep->pass || c->model_only ? 0 : 1;
}

