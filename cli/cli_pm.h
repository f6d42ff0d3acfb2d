// SPDX-License-Identifier: Apache-2.0
/* cli_pm.h: `pree render`'s options of the photon-map estimator (docs/photon_map.md). */
#ifndef PREE_CLI_PM_H
#define PREE_CLI_PM_H

#include <stdio.h>
#include "cli_options.h"

enum { CLI_PM_ESTIMATOR = 0x180, CLI_PM_K, CLI_PM_MAX_RADIUS, CLI_PM_SEARCH, CLI_PM_BUNDLE, CLI_PM_TASK,
       CLI_PM_SCHEDULE, CLI_PM_KERNEL, CLI_PM_BENCH,
       CLI_PM_BENCH_ORACLE };

#define CLI_PM_LONGOPTS                                                                \
    {"estimator", required_argument, NULL, CLI_PM_ESTIMATOR},                          \
    {"k", required_argument, NULL, CLI_PM_K},                                          \
    {"max-radius", required_argument, NULL, CLI_PM_MAX_RADIUS},                        \
    {"knn-search", required_argument, NULL, CLI_PM_SEARCH},                            \
    {"cluster-bundle", required_argument, NULL, CLI_PM_BUNDLE},                        \
    {"task-photons", required_argument, NULL, CLI_PM_TASK},                            \
    {"task-schedule", required_argument, NULL, CLI_PM_SCHEDULE},                      \
    {"knn-kernel", required_argument, NULL, CLI_PM_KERNEL},                            \
    {"knn-bench", required_argument, NULL, CLI_PM_BENCH},                              \
    {"knn-bench-oracle", required_argument, NULL, CLI_PM_BENCH_ORACLE}

/* Apply one of CLI_PM_LONGOPTS: 0 taken, 1 not one of them, 2 a bad value (printed). */
int cli_pm_option(cli_args_t *a, int id, render_options_t *opt);
/* The options' help lines; the combination check after parsing (0, or 2 printed). */
void cli_pm_usage(FILE *f);
int cli_pm_check(cli_args_t *a, const render_options_t *opt);

/* The render with the estimator opt->estimator names, the one place that chooses it: the
 * progressive session (render_run, model/ppm/render.h) or the photon-map render (pm_render,
 * model/pm/pm_render.h), which refuses the progressive render's checkpoints, time limit, series
 * and MPI ranks. Returns as render_run. */
int cli_estimator_render(const scene_t *scene, const render_options_t *opt, render_result_t *res, char *err,
                         size_t errlen);

#endif
