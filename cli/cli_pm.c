/* cli_pm.c: the photon-map estimator's options (see cli_pm.h). */
#include "cli_pm.h"

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
        static const char *const names[] = {"clustered", "naive"};
        if ((k = cli_keyword(a, names, 2)) < 0) return 2;
        opt->knn_search = k ? KNN_NAIVE : KNN_CLUSTERED;
        return 0;
    }
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
        "  --knn-search S         pm: clustered (default: paper 002's clustered, factorized search) or\n"
        "                         naive (per point, nanoflann's kd-tree: the oracle)\n"
        "  --cluster-bundle N     pm: shading points clustered together at most (default 2000)\n"
        "  --task-photons N       pm: photons per tracing task unit (default 1000)\n"
        "  --task-schedule S      pm: dynamic (default: a shared queue of task units) or static\n");
}

int cli_pm_check(cli_args_t *a, const render_options_t *opt)
{
    if (opt->estimator == ESTIMATOR_PM && opt->precision != PRECISION_DOUBLE)
        return cli_error(a, "--estimator pm runs in double precision only (--precision fp32 is the PREE's)");
    if (opt->estimator != ESTIMATOR_PM && (opt->knn_k || opt->max_radius > 0 || opt->cluster_bundle))
        return cli_error(a, "--k, --max-radius and --cluster-bundle need --estimator pm");
    return 0;
}
