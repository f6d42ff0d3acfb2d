#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""wave_check.py: the timing diagrams of docs/wave against a simulation of pree_axi.

Usage: wave_check.py BENCH_OUTPUT WAVE_DIR
BENCH_OUTPUT is what tb/axi/axi_wave_tb.v prints: per diagram a line "ROWS <diagram> <row>..."
and one line "SMP <diagram> <sample>..." a cycle (a bit: 0, 1, x; a bus: x, or b<beat>). Each
recorded row becomes a WaveDrom wave (a repeated value as '.', a new bus beat as '=') and must
equal the row of WAVE_DIR/<diagram>.json with the same name (a row in a group is named
"<group>.<row>", spaces as '_'; the JSON's data colours 2..9 count as '='). A diagram's gap '|'
stands for the cycles between its first part, aligned with the first cycles recorded, and its
last part, aligned with the last. Rows of the JSON that the bench does not record are listed.
Exits 1 with one line per difference.
"""
import json
import os
import sys


def rows_of(signal, group=""):
    """(name, wave) of every row of a WaveDrom signal list, groups flattened."""
    out = []
    for item in signal:
        if isinstance(item, list):
            out += rows_of(item[1:], item[0] if isinstance(item[0], str) else "")
        elif isinstance(item, dict) and "wave" in item:
            name = item.get("name", "").replace(" ", "_")
            out.append(((group + "." if group else "") + name, item["wave"]))
    return out


def encode(samples, prev):
    """WaveDrom characters of samples; prev: the value shown before them (None at the start)."""
    out = []
    for s in samples:
        if s.startswith("b"):
            out.append("." if prev == s else "=")
        else:
            out.append("." if prev == s else s)
        prev = s
    return "".join(out)


def norm(wave):
    return "".join("=" if c in "23456789=" else c for c in wave)


def main():
    if len(sys.argv) != 3:
        print("usage: wave_check.py BENCH_OUTPUT WAVE_DIR", file=sys.stderr)
        return 2
    rows, smp = {}, {}
    with open(sys.argv[1]) as f:
        for line in f:
            w = line.split()
            if len(w) >= 2 and w[0] == "ROWS":
                rows[w[1]] = w[2:]
                smp[w[1]] = []
            elif len(w) >= 2 and w[0] == "SMP":
                if w[1] not in rows or len(w) - 2 != len(rows[w[1]]):
                    print(f"wave_check: {sys.argv[1]}: sample line does not match its ROWS: {line.strip()}")
                    return 1
                smp[w[1]].append(w[2:])
    if not rows:
        print(f"wave_check: {sys.argv[1]}: no ROWS lines (did the bench run?)")
        return 1
    bad, checked, unchecked = 0, 0, []
    for diagram, names in rows.items():
        src = os.path.join(sys.argv[2], diagram + ".json")
        try:
            with open(src) as f:
                jrows = dict(rows_of(json.load(f)["signal"]))
        except (OSError, ValueError, KeyError) as e:
            print(f"wave_check: {src}: {e}")
            return 1
        cycles = smp[diagram]
        for k, name in enumerate(names):
            if name not in jrows:
                print(f"wave_check: {src}: no row '{name}'")
                bad += 1
                continue
            want = norm(jrows[name])
            s = [c[k] for c in cycles]
            if "|" in want:
                a, b = want.split("|", 1)
                if len(s) < len(a) + len(b):
                    got = encode(s, None)
                else:
                    got = encode(s[:len(a)], None) + "|" + encode(s[len(s) - len(b):], s[len(a) - 1])
            else:
                got = encode(s, None)
            checked += 1
            if got != want:
                print(f"wave_check: {src}: row '{name}': diagram {want}, simulation {got}")
                bad += 1
        unchecked += [f"{diagram}:{n}" for n in jrows if n not in names and n != "aclk"]
    print(f"wave_check: {checked} rows compared, {bad} differ; not simulated: {', '.join(unchecked)}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
