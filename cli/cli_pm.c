// SPDX-License-Identifier: Apache-2.0
/* cli_pm.c: the photon-map estimator's options (see cli_pm.h). */
#include <string.h>
#include "cli_pm.h"
#include "pm_render.h"
#include "render_dist.h"

int cli_pm_option(cli_args_t *a, int id, render_options_t *opt)
{
    long long v;
    int k;
    switch (id) {
    case CLI_PM_ESTIMATOR: {
        static const char *const names[] = {"ppm", "pm"};
        if ((k = cli_keyword(a, names, 2)) < 0) return 2;
        opt->estimator = k ? ESTIMATOR_PM : ESTIMATOR_PPM;
        return 0;
    }
    case CLI_PM_K:
        if (cli_int(a, 1, 100000, &v)) return 2;
        opt->knn_k = (int)v;
        return 0;
    case CLI_PM_MAX_RADIUS: return cli_real(a, 0, 1, 1e30, &opt->max_radius);
    case CLI_PM_SEARCH: {
        static const char *const names[] = {"clustered", "naive", "kdtree"};
        if ((k = cli_keyword(a, names, 3)) < 0) return 2;
        opt->knn_search = (knn_search_t)k;
        return 0;
    }
    case CLI_PM_KERNEL: {
        static const char *const names[] = {"auto", "scalar", "avx2", "avx512"};
        if ((k = cli_keyword(a, names, 4)) < 0) return 2;
        opt->knn_kernel = k;
        return 0;
    }
    case CLI_PM_BENCH:
        if (cli_int(a, 1, PM_BENCH_MAX, &v)) return 2;
        opt->knn_bench = (int)v;
        return 0;
    case CLI_PM_BENCH_ORACLE:
        if (cli_int(a, 0, PM_BENCH_MAX, &v)) return 2;
        opt->knn_bench_oracle = v ? (int)v : -1;
        return 0;
    case CLI_PM_BUNDLE:
        if (cli_int(a, 16, 100000, &v)) return 2;
        opt->cluster_bundle = (int)v;
        return 0;
    case CLI_PM_TASK:
        if (cli_int(a, 1, 100000000, &v)) return 2;
        opt->task_photons = (int)v;
        return 0;
    case CLI_PM_SCHEDULE: {
        static const char *const names[] = {"dynamic", "static"};
        if ((k = cli_keyword(a, names, 2)) < 0) return 2;
        opt->task_static = k;
        return 0;
    }
    default: return 1;
    }
}

void cli_pm_usage(FILE *f)
{
    fprintf(f,
        "  --estimator E          ppm (default: progressive photon mapping, the PREE's) or pm (classic\n"
        "                         photon mapping: a photon map and the k nearest photons; double only)\n"
        "  --k K                  pm: neighbours per hit point (default 50)\n"
        "  --max-radius R         pm: the search radius bound (default: the PPM initial radius)\n"
        "  --knn-search S         pm: clustered (default: paper 002's clustered search), kdtree (per\n"
        "                         point, one pass over the same photon tree: the fair baseline) or\n"
        "                         naive (per point, nanoflann's kd-tree: the test oracle)\n"
        "  --knn-kernel P         pm, clustered: the prefilter's path: auto (default: the widest the\n"
        "                         processor has), avx512, avx2 or scalar\n"
        "  --knn-bench R          pm: run all three searches R times (1-15), interleaved, on the same\n"
        "                         trees; their times in the statistics (pm.bench); an error if their\n"
        "                         radiance differs in any bit\n"
        "  --knn-bench-oracle N   pm: the oracle (naive) only N of those times (0: not at all)\n"
        "  --cluster-bundle N     pm: shading points clustered together at most (default 2000)\n"
        "  --task-photons N       pm: photons per tracing task unit (default 1000)\n"
        "  --task-schedule S      pm: dynamic (default: a shared queue of task units) or static\n");
}

int cli_pm_check(cli_args_t *a, const render_options_t *opt)
{
    if (opt->knn_bench_oracle && !opt->knn_bench)
        return cli_error(a, "--knn-bench-oracle needs --knn-bench");
    if (opt->estimator == ESTIMATOR_PM && opt->precision != PRECISION_DOUBLE)
        return cli_error(a, "--estimator pm runs in double precision only (--precision fp32 is the PREE's)");
    if (opt->estimator != ESTIMATOR_PM && (opt->knn_k || opt->max_radius > 0 || opt->cluster_bundle || opt->knn_kernel ||
                                            opt->knn_bench))
        return cli_error(a, "--k, --max-radius, --cluster-bundle, --knn-kernel and --knn-bench need --estimator pm");
    return 0;
}

int cli_estimator_render(const scene_t *scene, const render_options_t *opt, render_result_t *res, char *err,
                         size_t errlen)
{
    if (opt->estimator != ESTIMATOR_PM) return render_run(scene, opt, res, err, errlen);
    if (opt->checkpoint || opt->resume || opt->time_limit > 0 || opt->write_at_n) {
        memset(res, 0, sizeof *res);
        snprintf(err, errlen, "--checkpoint, --resume, --time-limit and --write-at/--write-every apply to the PPM "
                 "estimator only");
        return -1;
    }
    if (render_dist_size() > 1) {
        memset(res, 0, sizeof *res);
        snprintf(err, errlen, "the photon-map estimator runs in one process (under MPI: one rank)");
        return -1;
    }
    return pm_render(scene, opt, res, err, errlen);
}
