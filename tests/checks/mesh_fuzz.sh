#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Mutated OBJ and MTL files (seeded, 60 cases from CornellBox-Original: replaced, deleted and
# inserted bytes, NaN, huge numbers, bad indices, NUL bytes, unknown materials) never crash the
# loader: pree exits 0 (with an image) or 1 with exactly one error line on stderr, never by a
# signal or another status.
set -u
cd "$(dirname "$0")/../.."
[ -x build/pree ] || make -s build/pree >/dev/null || { echo "FAIL: cannot build build/pree"; exit 1; }
d=build/checks/mesh_fuzz; rm -rf "$d"; mkdir -p "$d"
python3 - "$PWD/build/pree" "$d" <<'PY'
import os, random, subprocess, sys
pree, d = sys.argv[1], sys.argv[2]
base = open("scenes/data/cornell-box/CornellBox-Original.obj", "rb").read()
mtl = open("scenes/data/cornell-box/CornellBox-Original.mtl", "rb").read()
rng = random.Random(20261125)
inserts = [b"nan", b"1e39", b"-0", b"//", b" 99999", b"\x00", b"inf", b"f 1 1 1\n", b"usemtl zz\n",
           b"Kd -1\n", b"illum 99\n", b"f -999 1 2\n", b"v 1e38 1e38 1e38\n"]
bad = 0
for k in range(60):
    o, m = bytearray(base), bytearray(mtl)
    t = o if k % 3 else m
    for _ in range(rng.randint(1, 8)):
        r, i = rng.random(), rng.randrange(len(t))
        if r < 0.4: t[i] = rng.choice(b"0123456789-.e/ \nnaNfvx#\t+")
        elif r < 0.7: del t[i:i + rng.randint(1, 20)]
        else: t[i:i] = rng.choice(inserts)
    c = os.path.join(d, "case%02d" % k); os.makedirs(c)
    open(os.path.join(c, "m.obj"), "wb").write(bytes(o))
    open(os.path.join(c, "CornellBox-Original.mtl"), "wb").write(bytes(m))
    open(os.path.join(c, "s"), "w").write("camera position 0 1 4 lookat 0 1 0 up 0 1 0 fov 60\n"
                                          "mesh m.obj\nlight point 0 1.5 0 intensity 1 1 1\n")
    cmd = [pree, "render", os.path.join(c, "s"), "--width", "16", "--height", "12", "--photons", "1000",
           "--quiet", "--out", os.path.join(c, "o.png")]
    p = subprocess.run(cmd, capture_output=True)
    err = [l for l in p.stderr.decode(errors="replace").splitlines() if not l.startswith("pree: warning")]
    ok = (p.returncode == 0 and os.path.exists(os.path.join(c, "o.png"))) or \
         (p.returncode == 1 and len(err) == 1 and not os.path.exists(os.path.join(c, "o.png")))
    if not ok:
        bad += 1
        print("FAIL case%02d: exit %d, stderr %r" % (k, p.returncode, err[:3]))
        print("  reproduce: " + " ".join(cmd))
print("%d cases, %d failed" % (60, bad))
sys.exit(1 if bad else 0)
PY
