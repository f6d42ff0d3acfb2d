// SPDX-License-Identifier: Apache-2.0
/* cosim_outputs.h: what a co-simulation run writes: the RTL's image with its SSIM and SNR
 * against a double render, the report (--stats) and the closing line. */
#ifndef PREE_COSIM_OUTPUTS_H
#define PREE_COSIM_OUTPUTS_H

#include "cosim_args.h"
#include "cosim_report.h"
#include "scene.h"

/* The RTL's image (binary32 words Lr, widened into rgb, plus the emitted radiance the eye pass
 * met, NULL: none, as radiance_add_emitted adds it in the fp32 render) to --out, and with a
 * reference its metrics in rep: 0, or -1 with a message printed. */
int cosim_image_out(const cosim_args_t *c, const scene_t *scene, const render_options_t *opt, const uint32_t *Lr,
                    const double *emitted, double *rgb, cosim_report_t *rep);

/* The report's figures, its JSON (--stats) and the closing line: the exit status (0 when both
 * comparisons show 0 differing words, or with --model-only), or 1 when the JSON is not written. */
int cosim_finish_report(cosim_report_t *rep, const cosim_args_t *c, int progress);

#endif
