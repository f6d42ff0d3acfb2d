#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""wave-view.py TRACE.fst TEMPLATE.gtkw OUT.gtkw: a GTKWave save file that opens where the action
is. Reads the trace (fst2vcd, from Debian's gtkwave), samples pree_top once a cycle (at the clock's
low phase, the cycle's inputs and combinational outputs) and finds the first photon accepted
(ph_valid_i and ph_ready_o), the first hazard stall and the first bank conflict (the stall cause
the counters count, `cause` in pree_top's u_counters (rtl/pree_counters.v): 2 hazard, 4 bank conflict in stage B, 5 stage A's
lanes left for a bank conflict). The view starts 4 cycles before the first photon, the primary
marker stands on it and markers A, B, C on the others; the cycle list is printed and written to
OUT.cycles.txt, with the number of cycles of each kind (which
the co-simulation's short-cycle counters must equal: tests/checks/wave_view.sh).
"""
import re
import subprocess
import sys

WANT = {"clk_i": "clk", "ph_valid_i": "pv", "ph_ready_o": "pr", "cause": "cause", "cnt_en_i": "en"}
EVENTS = (("first photon accepted", "photon"), ("first hazard stall", "hazard"),
          ("first bank conflict (stage B)", "bank"), ("first bank conflict (stage A lanes)", "abank"))


def scan(fst):
    """{event: (cycle, time_ps)} and the time unit, from the trace."""
    p = subprocess.Popen(["fst2vcd", fst], stdout=subprocess.PIPE, text=True, errors="replace")
    ids, scope, unit, found, counts = {}, [], "", {}, {}
    val = {}
    t, cycle, header = 0, -1, True
    def sample(at):
        nonlocal cycle
        cycle += 1
        v = lambda k: val.get(k, "x")
        checks = {"photon": v("pv") == "1" and v("pr") == "1",
                  "hazard": v("en") == "1" and v("cause") == "2",
                  "bank": v("en") == "1" and v("cause") == "4",
                  "abank": v("en") == "1" and v("cause") == "5"}
        for k, hit in checks.items():
            if hit and k not in found:
                found[k] = (cycle, at)
            counts[k] = counts.get(k, 0) + hit
    for line in p.stdout:
        line = line.strip()
        if header:
            if line.startswith("$timescale"):
                unit = line.split()[1] if len(line.split()) > 2 else next(p.stdout).strip()
            elif line.startswith("$scope"):
                scope.append(line.split()[2])
            elif line.startswith("$upscope"):
                scope.pop()
            elif line.startswith("$var") and scope in (["TOP", "pree_top"], ["TOP", "pree_top", "u_counters"]):
                f = line.split()
                name = f[4]
                if name in WANT and (name == "cause") == (scope[-1] == "u_counters"):
                    ids[f[3]] = WANT[name]
            elif line.startswith("$enddefinitions"):
                header = False
            continue
        if line.startswith("#"):
            if val.get("clk") == "0":
                sample(t)
            t = int(line[1:])
        elif line[:1] == "b":
            bits, ident = line[1:].split()
            if ident in ids:
                val[ids[ident]] = str(int(bits, 2)) if re.fullmatch("[01]+", bits) else "x"
        elif line and line[0] in "01xz" and line[1:] in ids:
            val[ids[line[1:]]] = line[0]
    p.wait()
    if p.returncode:
        raise SystemExit("wave-view: fst2vcd %s failed" % fst)
    return found, counts, unit, cycle + 1


def main(fst, template, out):
    found, counts, unit, cycles = scan(fst)
    lines = ["%s: %d cycles traced, time unit %s (8 ns a cycle)" % (fst, cycles, unit)]
    for what, key in EVENTS:
        c = found.get(key)
        lines.append("  %-36s %-26s (%d cycles in all)" % (what, "cycle %d, %.0f ns" % (c[0], c[1] / 1000.0) if c else "none",
                                                          counts.get(key, 0)))
    text = open(template).read().replace('[dumpfile] "@FST@"', '[dumpfile] "%s"' % fst)
    photon = found.get("photon", (0, 0))[1]
    text = re.sub(r"^\[timestart\] .*$", "[timestart] %d" % max(0, photon - 4 * 8000), text, flags=re.M)
    marks = [str(found[k][1]) if k in found else "-1" for k in ("hazard", "bank", "abank")]
    text = re.sub(r"^\*-?[0-9.]+ .*$", "*-15.000000 %d %s" % (photon, " ".join(marks + ["-1"] * 23)), text, flags=re.M)
    with open(out, "w") as f:
        f.write(text)
    with open(re.sub(r"\.gtkw$", "", out) + ".cycles.txt", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print("markers: primary = first photon, A = hazard stall, B = bank conflict (B), C = bank conflict (A lanes)")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
