# SPDX-License-Identifier: Apache-2.0
"""sections.py: the report's sections, each built from files that PREE's commands write (make run,
make bench, make sim / sim-full, make fpga-timing, make test). A missing source is shown as
"not run" with the command that makes it; no figure is typed here."""
import base64
import glob
import html
import json
import os
import re
import xml.etree.ElementTree as ET

import svg

E = html.escape


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def img(path, alt, cls=""):
    """An <img> with the file inlined as a data URI (the page needs no other file)."""
    try:
        data = open(path, "rb").read()
    except OSError:
        return not_run(path, alt)
    uri = "data:image/png;base64," + base64.b64encode(data).decode()
    return '<img class="%s" src="%s" alt="%s" title="%s" data-name="%s">' % (cls, uri, E(alt), E(path), E(os.path.basename(path)))


def run_scene(out):
    """The name of the scene the last make run rendered (out/run-scene.txt; cornell3 when absent)."""
    try:
        name = open(os.path.join(out, "run-scene.txt")).read().strip()
    except OSError:
        name = ""
    return name or "cornell3"


def not_run(path, what, cmd=""):
    return '<p class="missing">%s: not run (no %s)%s</p>' % (E(what), E(path), (" &mdash; <code>%s</code>" % E(cmd)) if cmd else "")


def table(head, rows):
    out = ["<table><tr>%s</tr>" % "".join("<th>%s</th>" % E(str(h)) for h in head)]
    for r in rows:
        out.append("<tr>%s</tr>" % "".join("<td>%s</td>" % E(str(c)) for c in r))
    out.append("</table>")
    return "\n".join(out)


def fmt(v, spec="%.6g"):
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    return spec % v


def images(out):
    """Software and RTL images side by side, and a slider over the double render."""
    names = [("double", "double (reference)"), ("fp32", "fp32, paper datapath"),
             ("fp32-stable", "fp32, stable datapath"), ("rtl", "RTL co-simulation (4 PREUs)")]
    scene = run_scene(out)
    have = [(n, t) for n, t in names if os.path.exists(os.path.join(out, "%s-%s.png" % (scene, n)))]
    if not have:
        return "<h2>Images</h2>" + not_run(os.path.join(out, "%s-double.png" % scene), "renders", "make run")
    cells = "".join('<figure>%s<figcaption>%s</figcaption></figure>'
                    % (img(os.path.join(out, "%s-%s.png" % (scene, n)), t, "px2"), E(t)) for n, t in have)
    s = ["<h2>Images (%s, <code>make run</code>)</h2>" % E(scene), '<div class="row">%s</div>' % cells]
    other = [(n, t) for n, t in have if n != "double"]
    if other and have[0][0] == "double":
        n, t = other[-1]
        s.append('<h3>Slider: double (left) against %s (right)</h3>' % E(t))
        s.append('<div class="slider" id="slider"><div class="under">%s</div><div class="over" id="over">%s</div></div>'
                 % (img(os.path.join(out, "%s-%s.png" % (scene, n)), t, "px2"),
                    img(os.path.join(out, "%s-double.png" % scene), "double", "px2")))
        s.append('<input type="range" min="0" max="100" value="50" id="cut" aria-label="slider">')
    return "\n".join(s)


def comparisons(out):
    """fp32-, stable- and RTL-against-double figures and their difference maps."""
    rows, maps, scene = [], [], run_scene(out)
    for name, what in (("fp32", "fp32 (paper) vs double"), ("fp32-stable", "fp32 stable vs double"),
                       ("rtl", "RTL vs double (8-bit)")):
        c = load_json(os.path.join(out, "%s-%s-vs-double.json" % (scene, name)))
        if not c:
            rows.append([what] + ["not run"] * 7)
            continue
        rows.append([what, fmt(c.get("ssim"), "%.9f"), fmt(c.get("psnr_db"), "%.2f"), fmt(c.get("snr_db"), "%.2f"),
                     fmt(c.get("rmse")), fmt(c.get("flip"), "%.4g"), fmt(c.get("max_abs")), fmt(c.get("rel_max"))])
        base = os.path.join(out, "%s-%s-vs-double-diff" % (scene, name))
        cells = "".join("<figure>%s<figcaption>%s</figcaption></figure>" % (img(base + suf + ".png", what + " " + cap), cap)
                        for suf, cap in (("", "relative error"), ("-abs", "absolute error"), ("-ssim", "SSIM map"),
                                         ("-flip", "FLIP map")) if os.path.exists(base + suf + ".png"))
        maps.append("<h3>%s</h3><div class=\"row\">%s</div>" % (E(what), cells))
    s = ["<h2>Against the double render</h2>",
         table(["pair", "SSIM", "PSNR dB", "SNR dB", "RMSE", "FLIP", "max |diff|", "max relative"], rows)]
    r = load_json(os.path.join(out, "%s-rtl.json" % scene))
    if r:
        s.append("<p>RTL against the fp32 model: %s differing hit-point words, %s differing image words (%s).</p>"
                 % (E(str(r.get("hp_words_differing"))), E(str(r.get("image_words_differing"))),
                    "pass" if r.get("pass") else "FAIL"))
    return "\n".join(s + ["<h2>Difference maps</h2>"] + maps)


def convergence(out, docs_images):
    """Run time against error from make bench's table (out/bench/convergence.txt)."""
    tab = os.path.join(out, "bench", "convergence.txt")
    s = ["<h2>Run time against error (<code>make bench</code>)</h2>"]
    try:
        lines = [l.split() for l in open(tab) if l.strip()]
    except OSError:
        s.append(not_run(tab, "make bench's convergence table", "make bench"))
        s.append("<p>The plot of the last measurement kept in the docs:</p>" + img(os.path.join(docs_images, "convergence.png"), "convergence (docs)"))
        return "\n".join(s)
    head, rows = lines[0], lines[1:]
    s.append(table(head, rows))
    col = {h: i for i, h in enumerate(head)}
    series = []
    for prec in ("double", "fp32"):
        pts = [(float(r[col["cpu_s"]]), float(r[col["rmse_linear"]])) for r in rows if r[col["precision"]] == prec]
        series.append((prec, pts))
    s.append(svg.loglog("RMSE (linear radiance) against CPU seconds", "CPU seconds", "RMSE", series))
    return "\n".join(s)


def utilization(out, build):
    """Utilization and short-cycle causes for 4, 8 and 16 PREUs, from the co-simulation's stats."""
    cfgs = []
    for p in (4, 8, 16):
        src = None
        for cand in (os.path.join(build, "cosim", "full_p%d.json" % p), os.path.join(build, "cosim", "small_p%d.json" % p),
                     os.path.join(out, "%s-rtl.json" % run_scene(out)) if p == 4 else ""):
            d = load_json(cand) if cand else None
            if d and d.get("preu") == p:
                src = (cand, d)
                break
        cfgs.append((p, src))
    causes = ["hazard_in_flight", "same_key_in_lanes", "bank_conflict_a", "bank_conflict_b", "starved"]
    rows = []
    for p, src in cfgs:
        if not src:
            rows.append([p, "not run"] + [""] * (4 + len(causes)))
            continue
        path, d = src
        u = d.get("update", {})
        sc = u.get("short_cycles_by_cause", {})
        rows.append([p, "%sx%s, %s photons" % (d.get("width"), d.get("height"), d.get("photons_emitted")),
                     u.get("operations"), u.get("cycles"), "%.3f%%" % (100 * u.get("preu_utilization", 0)),
                     os.path.relpath(path)] + [sc.get(c, "-") for c in causes])
    s = ["<h2>PREU utilization and short cycles (update mode)</h2>",
         table(["PREUs", "run", "operations", "cycles", "utilization", "source"] + causes, rows)]
    if not any(src for _, src in cfgs):
        s.append(not_run(os.path.join(build, "cosim"), "co-simulation statistics", "make run, make sim or make sim-full"))
        return "\n".join(s)
    s.append(svg.bars("PREU utilization, update mode", ["%d PREUs" % p for p, _ in cfgs], ["utilization"],
                      [[100 * src[1]["update"]["preu_utilization"] if src else None] for _, src in cfgs], "%"))
    s.append(svg.bars("Short cycles by cause, update mode", ["%d PREUs" % p for p, _ in cfgs], causes,
                      [[src[1]["update"]["short_cycles_by_cause"].get(c, 0) if src else None for c in causes]
                       for _, src in cfgs]))
    return "\n".join(s)


def md_tables(text):
    """Markdown pipe tables in text as HTML tables."""
    rows = [l.strip() for l in text.splitlines() if l.strip().startswith("|")]
    rows = [[c.strip().strip("`") for c in r.strip("|").split("|")] for r in rows]
    rows = [r for r in rows if not all(re.fullmatch(r":?-+:?", c) for c in r)]
    return table(rows[0], rows[1:]) if rows else ""


def fpga(root, build):
    """Synthesis and timing: the generated tables (build/ after make fpga-timing, else the copies
    make fpga-timing put into docs/fpga.md between its markers)."""
    s = ["<h2>Synthesis and timing</h2>"]
    doc = open(os.path.join(root, "docs", "fpga.md")).read() if os.path.exists(os.path.join(root, "docs", "fpga.md")) else ""
    for name, built, what in (("fpga-timing", os.path.join(build, "fpga", "timing.md"), "nextpnr-ecp5 timing, LFE5U-85F speed 6"),
                              ("synth-xilinx", os.path.join(build, "fp32", "synth", "resources.md"), "Yosys synth_xilinx resources")):
        if os.path.exists(built):
            text, src = open(built).read(), built
        else:
            m = re.search(r"<!-- %s:begin -->\n(.*?)<!-- %s:end -->" % (name, name), doc, re.S)
            text, src = (m.group(1), "docs/fpga.md (written by make fpga-timing)") if m else ("", "")
        s.append("<h3>%s</h3>" % E(what))
        s.append(("<p class=\"src\">source: %s</p>" % E(os.path.relpath(src) if os.path.exists(src) else src)) + md_tables(text)
                 if text else not_run(built, what, "make fpga-timing"))
    return "\n".join(s)


def numerics(docs_images):
    files = sorted(glob.glob(os.path.join(docs_images, "numerics-*.png"))) + \
        [f for f in (os.path.join(docs_images, "engine.png"),) if os.path.exists(f)]
    if not files:
        return "<h2>Numerics</h2>" + not_run(docs_images, "numerics plots", "make stress")
    return "<h2>Numerics and engine plots (docs/images)</h2>" + "".join(
        "<figure>%s<figcaption>%s</figcaption></figure>" % (img(f, os.path.basename(f), "wide"), E(os.path.basename(f))) for f in files)


def tests(xml_path):
    """The last make test / make check: counts, failing cases with their rerun, slowest checks."""
    s = ["<h2>Regression (<code>%s</code>)</h2>" % E(os.path.relpath(xml_path))]
    try:
        root = ET.parse(xml_path).getroot()
    except (OSError, ET.ParseError):
        return "\n".join(s + [not_run(xml_path, "regression results", "make test")])
    cases = list(root.iter("testcase"))
    failing = [c for c in cases if c.find("failure") is not None]
    s.append('<p class="%s">%d passed, %d failed (%s)</p>' % ("ok" if not failing else "bad", len(cases) - len(failing),
                                                             len(failing), E(root.find("testsuite").get("timestamp", "") if root.find("testsuite") is not None else "")))
    rows = []
    for c in failing:
        outtext = (c.findtext("system-out") or "")
        rerun = re.search(r"^rerun: (.*)$", outtext, re.M)
        log = re.search(r"^log: (.*)$", outtext, re.M)
        rows.append([c.get("classname"), c.get("name"), c.find("failure").get("message", ""),
                     rerun.group(1) if rerun else "", log.group(1) if log else ""])
    if rows:
        s.append(table(["suite", "case", "message", "rerun", "log"], rows))
    checks = sorted((c for c in cases if c.get("classname") == "checks"), key=lambda c: -float(c.get("time", 0)))[:10]
    s.append("<h3>Slowest checks</h3>" + table(["check", "seconds"], [[c.get("name"), c.get("time")] for c in checks]))
    return "\n".join(s)
