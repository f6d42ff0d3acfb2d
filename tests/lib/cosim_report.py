# SPDX-License-Identifier: Apache-2.0
"""cosim_report.py: the checks that the co-simulation checks share on a `pree cosim --stats` report.

Each check appends what is wrong to a list; finish() prints those lines and exits 1 when there
are any. The rule they share: the RTL matches the fp32 model word for word, and the host's cycle
model predicts the RTL's stalls exactly (hazard, same key, both bank conflicts; the starved count
differs by the cycles before the first photon) and every group in the cycle it planned.
"""
import json
import sys

STALLS_PREDICTED = ("hazard_in_flight", "same_key_in_lanes", "bank_conflict_b", "bank_conflict_a")


def load(path):
    return json.load(open(path))


def words_match(d, bad):
    """0 differing hit-point and image words, and the report's pass."""
    if d["hp_words_differing"] != 0 or d["image_words_differing"] != 0 or not d["pass"]:
        bad.append("differing words: hit points %d, image %d" % (d["hp_words_differing"], d["image_words_differing"]))


def utilization_at_least(d, floor, bad):
    u = d["update"]["preu_utilization"]
    if u < floor:
        bad.append("utilization %.6f below %.6f" % (u, floor))


def model_predicts(d, bad):
    """The scheduler's cycle model against the RTL (the run must have been scheduled)."""
    u, s = d["update"], d["schedule"]
    for k in STALLS_PREDICTED:
        if s["model_short_cycles_by_cause"][k] != u["short_cycles_by_cause"][k]:
            bad.append("model %s %d, RTL %d" % (k, s["model_short_cycles_by_cause"][k], u["short_cycles_by_cause"][k]))
    if s.get("groups_late") != 0:   # the RTL took every group in the cycle the model planned
        bad.append("groups taken off the model's cycle: %s (at most %s cycles)"
                   % (s.get("groups_late"), s.get("max_lag_cycles")))


def finish(bad):
    for b in bad:
        print("FAIL:", b)
    sys.exit(1 if bad else 0)
