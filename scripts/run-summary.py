#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""run-summary.py OUT RTL: the closing summary of `make run` (scripts/make-run.sh): where the
images, maps and report are, and the figures, all read from the JSON files the run wrote.
RTL is 1 when the co-simulation ran."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "report"))
from sections import load_json as load, run_scene  # noqa: E402


def find(obj, key):
    """The first value of key anywhere in a JSON tree."""
    if isinstance(obj, dict):
        if key in obj:
            return obj[key]
        for v in obj.values():
            r = find(v, key)
            if r is not None:
                return r
    return None


def main(out, rtl):
    scene = run_scene(out)
    p = lambda name: os.path.join(out, name)
    print("== summary (%s)" % scene)
    try:
        first = open(p("first-image-seconds.txt")).read().strip()
    except OSError:
        first = "?"
    print("images      %s (double, the reference; first image after %s s)" % (p(scene + "-double.png"), first))
    print("            %s, %s" % (p(scene + "-fp32.png"), p(scene + "-fp32-stable.png"))
          + (", %s" % p(scene + "-rtl.png") if rtl else ""))
    print("diff maps   %s-diff{,-abs,-ssim,-flip}.png (relative, absolute, SSIM, FLIP; colour bars)"
          % p(scene + "-fp32-vs-double"))
    print("report      make report  ->  %s" % p("report/index.html"))
    d = load(p(scene + "-double.json"))
    if d:
        print("render      %dx%d, %s photons, double %.2f s" % (d["width"], d["height"], d["photons_emitted"],
                                                               d["seconds"]["total"]))
    for name, what in (("fp32", "fp32 (paper)"), ("fp32-stable", "fp32 stable"), ("rtl", "RTL (PNG)")):
        c = load(p(scene + "-%s-vs-double.json" % name))
        if c:
            print("%-11s vs double: SSIM %.7f, PSNR %.2f dB, FLIP %.3g, largest relative error %.3g"
                  % (what, c["ssim"], float(c["psnr_db"]), c["flip"], c["rel_max"]))
    r = load(p(scene + "-rtl.json")) if rtl else None
    if r:
        print("RTL         %s: %s differing hit-point words, %s differing image words against the fp32 model; "
              "%s cycles, PREU utilization %.3f%%" % (
                  "pass" if find(r, "pass") else "FAIL", find(r, "hp_words_differing"),
                  find(r, "image_words_differing"), find(r, "cycles"), 100 * (find(r, "preu_utilization") or 0)))
    elif not rtl:
        print("RTL         not run (no co-simulation program)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2] == "1"))
