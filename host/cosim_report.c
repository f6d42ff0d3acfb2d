/* cosim_report.c: the co-simulation's figures and their JSON file (see cosim_report.h). */
#include "cosim_report.h"
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
    r->sim_ops_per_cpu_s = r->cpu_update_rtl > 0 ? (double)r->ops_upd / r->cpu_update_rtl : 0;
    r->pass = r->hp_diff == 0 && r->img_diff == 0 && r->ops_upd == r->ops_sent && r->ops_rad == r->hit_points;
}

/* {"hazard_in_flight": n, ...} from five counters (cnt[CNT_HAZ..]), less base's where given. */
static json_t *by_cause(const uint64_t *cnt, const uint64_t *base)
{
    json_t *o = json_object();
    for (int k = 0; k < 5; k++) json_set_u64(o, causes[k], cnt[CNT_HAZ + k] - (base ? base[CNT_HAZ + k] : 0));
    return o;
}

static json_t *schedule(const cosim_report_t *r)
{
    if (!r->have_sched) return json_null();
    json_t *o = json_object();
    json_set_u64(o, "window", (uint64_t)r->window);
    json_set_u64(o, "photons", r->sched.photons);
    json_set_u64(o, "photons_moved", r->sched.moved);
    json_set_u64(o, "model_cycles", r->sched.cnt[CNT_CYC_UPD]);
    json_object_set_new(o, "model_short_cycles_by_cause", by_cause(r->sched.cnt, NULL));
    return o;
}

static json_t *update_pass(const cosim_report_t *r)
{
    json_t *o = json_object(), *per = json_array();
    json_set_u64(o, "cycles", r->cyc_upd);
    json_set_u64(o, "operations", r->ops_upd);
    json_set_real(o, "ops_per_cycle", r->cyc_upd ? (double)r->ops_upd / (double)r->cyc_upd : 0);
    json_set_real(o, "preu_utilization", r->util_upd);
    for (int l = 0; l < r->preu; l++) json_array_append_new(per, json_integer((json_int_t)r->cnt_upd[CNT_OPS0 + l]));
    json_object_set_new(o, "ops_per_preu", per);
    json_object_set_new(o, "short_cycles_by_cause", by_cause(r->cnt_upd, NULL));
    return o;
}

static json_t *radiance_pass(const cosim_report_t *r)
{
    json_t *o = json_object();
    json_set_u64(o, "cycles", r->cyc_rad);
    json_set_u64(o, "operations", r->ops_rad);
    json_set_real(o, "preu_utilization", r->util_rad);
    json_object_set_new(o, "short_cycles_by_cause", by_cause(r->cnt_all, r->cnt_upd));
    return o;
}

static json_t *seconds(const cosim_report_t *r)
{
    json_t *o = json_object();
    json_set_real(o, "engine_with_rtl_wall", r->sec_engine);
    json_set_real(o, "rtl_update_wall", r->sec_update_rtl);
    json_set_real(o, "rtl_update_cpu", r->cpu_update_rtl);
    json_set_real(o, "rtl_radiance_wall", r->sec_rad_rtl);
    json_set_real(o, "process_cpu", r->cpu_process);
    return o;
}

int cosim_report_write(const char *path, const cosim_report_t *r, char *err, size_t errlen)
{
    json_t *o = json_object();
    json_set_str(o, "scene", r->scene);
    json_set_u64(o, "width", (uint64_t)r->width);
    json_set_u64(o, "height", (uint64_t)r->height);
    json_set_u64(o, "photons_emitted", r->photons_emitted);
    json_set_str(o, "datapath", r->datapath ? "stable" : "paper");
    json_set_real(o, "alpha", r->alpha);
    json_set_u64(o, "preu", (uint64_t)r->preu);
    json_set_bool(o, "reorder", r->reorder);
    json_set_real(o, "input_gap", r->gap);
    json_set_u64(o, "hit_points", r->hit_points);
    json_object_set_new(o, "schedule", schedule(r));
    json_set_u64(o, "photon_hits_streamed", r->photons_sent);
    json_set_u64(o, "photon_hits_without_operations", r->photons_empty);
    json_set_u64(o, "hp_words_differing", r->hp_diff);
    json_set_u64(o, "hp_points_differing", r->hp_diff_points);
    json_set_u64(o, "image_words_differing", r->img_diff);
    if (r->have_metrics) {
        json_set_real(o, "ssim_vs_double", r->m.ssim);
        json_set_real(o, "snr_db_vs_double", r->m.snr_db);
        json_set_real(o, "psnr_db_vs_double", r->m.psnr_db);
    }
    json_object_set_new(o, "update", update_pass(r));
    json_object_set_new(o, "radiance", radiance_pass(r));
    json_object_set_new(o, "seconds", seconds(r));
    json_set_real(o, "simulated_ops_per_cpu_second", r->sim_ops_per_cpu_s);
    json_set_real(o, "simulated_cycles_per_cpu_second",
                  r->cpu_update_rtl > 0 ? (double)r->cyc_upd / r->cpu_update_rtl : 0);
    json_set_bool(o, "pass", r->pass);
    return json_file_write(path, o, err, errlen);
}
