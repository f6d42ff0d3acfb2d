// SPDX-License-Identifier: Apache-2.0
/* cosim_report.c: the co-simulation's figures and their JSON file (see cosim_report.h). */
#include "cosim_report.h"
#include <stddef.h>
#include "json_file.h"

static const char *const causes[5] = {"hazard_in_flight", "same_key_in_lanes", "bank_conflict_b",
                                      "bank_conflict_a", "starved"};

void cosim_report_figures(cosim_report_t *r)
{
    uint64_t ops_all = 0;
    r->ops_upd = 0;
    for (int l = 0; l < r->preu; l++) { r->ops_upd += r->cnt_upd[CNT_OPS0 + l]; ops_all += r->cnt_all[CNT_OPS0 + l]; }
    r->cyc_upd = r->cnt_upd[CNT_CYC_UPD];
    r->cyc_rad = r->cnt_all[CNT_CYC_RAD];
    r->ops_rad = ops_all - r->ops_upd;
    r->util_upd = r->cyc_upd ? (double)r->ops_upd / ((double)r->preu * (double)r->cyc_upd) : 0;
    r->util_rad = r->cyc_rad ? (double)r->ops_rad / ((double)r->preu * (double)r->cyc_rad) : 0;
    if (r->mpi_ranks > 1) {
        uint64_t most = 0, sum = 0, ops = 0;
        for (int k = 0; k < r->mpi_ranks; k++) {
            most = r->ranks[k].cycles > most ? r->ranks[k].cycles : most;
            sum += r->ranks[k].cycles;
            ops += r->ranks[k].ops;
        }
        r->hit_points = 0;
        for (int k = 0; k < r->mpi_ranks; k++) r->hit_points += r->ranks[k].hit_points;
        r->imbalance = sum ? (double)most * r->mpi_ranks / (double)sum : 0;
        r->util_all = most ? (double)ops / ((double)r->preu * r->mpi_ranks * (double)most) : 0;
    }
    r->ops_per_cycle = r->cyc_upd ? (double)r->ops_upd / (double)r->cyc_upd : 0;
    r->sim_ops_per_cpu_s = r->cpu_update_rtl > 0 ? (double)r->ops_upd / r->cpu_update_rtl : 0;
    r->sim_cycles_per_cpu_s = r->cpu_update_rtl > 0 ? (double)r->cyc_upd / r->cpu_update_rtl : 0;
    r->pass = !r->model_only && r->hp_diff == 0 && r->img_diff == 0;
    if (r->mpi_ranks <= 1) r->pass = r->pass && r->ops_upd == r->ops_sent && r->ops_rad == r->hit_points;
    for (int k = 0; r->mpi_ranks > 1 && k < r->mpi_ranks; k++) {   /* every PREE counted what it was sent */
        const cosim_rank_t *q = &r->ranks[k];
        if (q->ops != q->ops_sent || q->radiance_ops != q->hit_points || q->image_words_differing) r->pass = 0;
    }
}

/* {"hazard_in_flight": n, ...} from five counters (cnt[CNT_HAZ..]), less base's where given. */
static json_t *by_cause(const uint64_t *cnt, const uint64_t *base)
{
    json_t *o = json_object();
    for (int k = 0; k < 5; k++) json_set_u64(o, causes[k], cnt[CNT_HAZ + k] - (base ? base[CNT_HAZ + k] : 0));
    return o;
}

#define R(member, kind, key) JSON_FIELD_AS(cosim_report_t, member, kind, key)
#define N(a) (sizeof a / sizeof a[0])

static const json_field_t run_fields[] = {
    R(width, JF_INT, "width"), R(height, JF_INT, "height"), R(photons_emitted, JF_U64, "photons_emitted"),
    R(alpha, JF_REAL, "alpha"), R(pipe_fast, JF_INT, "pipe_fast"), R(update_window, JF_INT, "update_window"),
    R(preu, JF_INT, "preu"), R(ppc, JF_INT, "photons_per_cycle"),
    R(model_only, JF_BOOL, "model_only"), R(axi, JF_BOOL, "axi"), R(reorder, JF_BOOL, "reorder"),
    R(gap, JF_REAL, "input_gap"), R(hit_points, JF_U64, "hit_points"),
};
static const json_field_t out_fields[] = {
    R(photons_sent, JF_U64, "photon_hits_streamed"), R(photons_empty, JF_U64, "photon_hits_without_operations"),
    R(hp_diff, JF_U64, "hp_words_differing"), R(hp_diff_points, JF_U64, "hp_points_differing"),
    R(img_diff, JF_U64, "image_words_differing"),
};
/* The host's re-filters (--refilter): with --model-only too, whose radii are the model's words. */
static const json_field_t refilter_fields[] = {
    R(refilter.refilters, JF_U64, "host_refilters"), R(refilter.hit_points_read, JF_U64, "refilter_hit_points_read"),
};
static const json_field_t metric_fields[] = {
    R(m.ssim, JF_REAL, "ssim_vs_double"), R(m.snr_db, JF_REAL, "snr_db_vs_double"),
    R(m.psnr_db, JF_REAL, "psnr_db_vs_double"),
};
static const json_field_t update_fields[] = {
    R(cyc_upd, JF_U64, "cycles"), R(ops_upd, JF_U64, "operations"), R(ops_per_cycle, JF_REAL, "ops_per_cycle"),
    R(util_upd, JF_REAL, "preu_utilization"),
};
static const json_field_t radiance_fields[] = {
    R(cyc_rad, JF_U64, "cycles"), R(ops_rad, JF_U64, "operations"), R(util_rad, JF_REAL, "preu_utilization"),
};
static const json_field_t second_fields[] = {
    R(sec_engine, JF_REAL, "engine_with_rtl_wall"), R(sec_update_rtl, JF_REAL, "rtl_update_wall"),
    R(cpu_update_rtl, JF_REAL, "rtl_update_cpu"), R(sec_rad_rtl, JF_REAL, "rtl_radiance_wall"),
    R(cpu_process, JF_REAL, "process_cpu"),
};
static const json_field_t speed_fields[] = {
    R(sim_ops_per_cpu_s, JF_REAL, "simulated_ops_per_cpu_second"),
    R(sim_cycles_per_cpu_s, JF_REAL, "simulated_cycles_per_cpu_second"), R(pass, JF_BOOL, "pass"),
};

static json_t *schedule(const cosim_report_t *r)
{
    if (!r->have_sched) return json_null();
    json_t *o = json_object();
    json_set_u64(o, "window", (uint64_t)r->window);
    json_set_u64(o, "photons", r->sched.photons);
    json_set_u64(o, "photons_moved", r->sched.moved);
    json_set_u64(o, "model_cycles", r->sched.cnt[CNT_CYC_UPD]);
    json_object_set_new(o, "model_short_cycles_by_cause", by_cause(r->sched.cnt, NULL));
    if (r->sched.lag_known) {
        json_set_u64(o, "groups_late", r->sched.groups_late);
        json_set_u64(o, "max_lag_cycles", r->sched.max_lag);
    }
    return o;
}

static json_t *update_pass(const cosim_report_t *r)
{
    json_t *o = json_fields(r, update_fields, N(update_fields)), *per = json_array();
    for (int l = 0; l < r->preu; l++) json_array_append_new(per, json_integer((json_int_t)r->cnt_upd[CNT_OPS0 + l]));
    json_object_set_new(o, "ops_per_preu", per);
    json_object_set_new(o, "short_cycles_by_cause", by_cause(r->cnt_upd, NULL));
    return o;
}

static json_t *radiance_pass(const cosim_report_t *r)
{
    json_t *o = json_fields(r, radiance_fields, N(radiance_fields));
    json_object_set_new(o, "short_cycles_by_cause", by_cause(r->cnt_all, r->cnt_upd));
    return o;
}

static json_t *mpi_ranks(const cosim_report_t *r)
{
    json_t *o = json_object(), *a = json_array();
    json_set_u64(o, "ranks", (uint64_t)r->mpi_ranks);
    for (int k = 0; k < r->mpi_ranks; k++) {
        const cosim_rank_t *q = &r->ranks[k];
        json_t *e = json_object();
        json_set_u64(e, "rank", (uint64_t)k);
        json_set_u64(e, "hit_points", q->hit_points);
        json_set_u64(e, "photons_sent", q->photons_sent);
        json_set_u64(e, "photons_other_ranks", q->photons_other);
        json_set_u64(e, "update_operations", q->ops);
        json_set_u64(e, "update_cycles", q->cycles);
        json_set_real(e, "update_preu_utilization", q->utilization);
        json_set_u64(e, "radiance_cycles", q->radiance_cycles);
        json_set_u64(e, "image_words_differing", q->image_words_differing);
        json_array_append_new(a, e);
    }
    json_object_set_new(o, "per_rank", a);
    json_set_real(o, "load_imbalance", r->imbalance);
    json_set_real(o, "update_preu_utilization", r->util_all);
    json_set_u64(o, "image_words_differing_vs_one_pree", r->img_diff_one_pree);
    json_set_u64(o, "image_max_ulps_vs_one_pree", r->img_max_ulp_one_pree);
    return o;
}

int cosim_report_write(const char *path, const cosim_report_t *r, char *err, size_t errlen)
{
    json_t *o = json_object();
    json_set_str(o, "scene", r->scene);
    json_set_str(o, "datapath", r->datapath ? "stable" : "paper");
    json_set_str(o, "hp_layout", r->pixel_layout ? "pixel" : "spatial");
    json_set_fields(o, r, run_fields, N(run_fields));
    json_object_set_new(o, "schedule", schedule(r));
    if (!r->model_only) json_set_fields(o, r, out_fields, N(out_fields));   /* nothing compared */
    json_set_fields(o, r, refilter_fields, N(refilter_fields));
    if (r->have_metrics) json_set_fields(o, r, metric_fields, N(metric_fields));
    json_object_set_new(o, "update", update_pass(r));
    if (!r->model_only) json_object_set_new(o, "radiance", radiance_pass(r));
    if (r->mpi_ranks > 1) json_object_set_new(o, "mpi", mpi_ranks(r));
    json_object_set_new(o, "seconds", json_fields(r, second_fields, N(second_fields)));
    json_set_fields(o, r, speed_fields, N(speed_fields));
    return json_file_write(path, o, err, errlen);
}
