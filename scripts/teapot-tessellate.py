#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""teapot-tessellate.py: tessellate Newell's Utah teapot (32 bicubic Bezier patches) into a
triangle OBJ with analytic per-vertex normals, for the cornell-teapot scene.

Usage: teapot-tessellate.py PATCHES.txt OUT.obj[.gz] [N]
PATCHES.txt: a line with the point count, that many "x,y,z" lines (1-based), a line with the
patch count, then one line of 16 comma-separated 1-based point indices per patch (row-major 4x4).
Each patch is sampled on an (N+1) x (N+1) grid (default N = 8) and split into 2 N^2 triangles;
zero-area triangles (at the lid and bottom poles) are left out. The frame is the data's (z up).
Output is deterministic (gzip without a time stamp)."""
import gzip
import sys


def bern(t):
    s = 1.0 - t
    return (s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t)


def dbern(t):
    s = 1.0 - t
    return (-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t)


def combine(p, bu, bv):
    return tuple(sum(bu[i] * bv[j] * p[4 * i + j][k] for i in range(4) for j in range(4)) for k in range(3))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def length(a):
    return (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) ** 0.5


def normal(p, u, v):
    """Unit normal dP/du x dP/dv; at a pole (zero derivative) step slightly inside the patch."""
    for eps in (0.0, 1e-4, 1e-3, 1e-2):
        uu = min(max(u, eps), 1.0 - eps)
        vv = min(max(v, eps), 1.0 - eps)
        n = cross(combine(p, dbern(uu), bern(vv)), combine(p, bern(uu), dbern(vv)))
        ln = length(n)
        if ln > 1e-12:
            return (n[0] / ln, n[1] / ln, n[2] / ln)
    return (0.0, 0.0, 1.0)


def read_patches(path):
    lines = [ln.strip() for ln in open(path) if ln.strip()]
    npts = int(lines[0])
    pts = [tuple(float(c) for c in ln.split(",")) for ln in lines[1:1 + npts]]
    npat = int(lines[1 + npts])
    patches = []
    for ln in lines[2 + npts:2 + npts + npat]:
        idx = [int(c) for c in ln.split(",")]
        if len(idx) != 16 or min(idx) < 1 or max(idx) > npts:
            sys.exit("teapot-tessellate: bad patch line: " + ln)
        patches.append([pts[i - 1] for i in idx])
    if len(patches) != npat:
        sys.exit("teapot-tessellate: expected %d patches, found %d" % (npat, len(patches)))
    return patches


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    n = int(sys.argv[3]) if len(sys.argv) == 4 else 8
    patches = read_patches(sys.argv[1])
    out = ["# Utah teapot (Martin Newell, 1975): %d Bezier patches tessellated %dx%d by scripts/teapot-tessellate.py; z up\n"
           % (len(patches), n, n)]
    nv = 0
    ntri = 0
    written = []   # vertex positions as written (6 decimals), for the zero-area test
    for p in patches:
        base = nv
        for a in range(n + 1):
            for b in range(n + 1):
                u, v = a / n, b / n
                x = combine(p, bern(u), bern(v))
                line = "v %.6f %.6f %.6f\n" % x
                out.append(line)
                written.append(tuple(float(c) for c in line.split()[1:]))
                out.append("vn %.6f %.6f %.6f\n" % normal(p, u, v))
                nv += 1
        for a in range(n):
            for b in range(n):
                i00 = base + a * (n + 1) + b + 1
                i01, i10, i11 = i00 + 1, i00 + n + 1, i00 + n + 2
                for tri in ((i00, i10, i11), (i00, i11, i01)):
                    q = [written[k - 1] for k in tri]
                    if length(cross(sub(q[1], q[0]), sub(q[2], q[0]))) <= 1e-12:
                        continue
                    out.append("f %d//%d %d//%d %d//%d\n" % (tri[0], tri[0], tri[1], tri[1], tri[2], tri[2]))
                    ntri += 1
    text = "".join(out).encode()
    if sys.argv[2].endswith(".gz"):
        with open(sys.argv[2], "wb") as f:
            f.write(gzip.compress(text, 9, mtime=0))
    else:
        with open(sys.argv[2], "wb") as f:
            f.write(text)
    sys.stderr.write("teapot-tessellate: %d vertices, %d triangles\n" % (nv, ntri))


if __name__ == "__main__":
    main()
