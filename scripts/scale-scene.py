#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""scale-scene.py: a copy of a scene file with every length multiplied by S.

Usage: scale-scene.py SCENE S OUT [--epsilon]
  S        a number, or 2^K (exact in binary: the copy then renders the same bits)
  --epsilon  also scale the ray epsilon (writes `epsilon 1e-4*S`, or S times the scene's own)
Spheres (radius, centre), the camera's origin/position/lookat and near distance, point lights
(position; intensity by S^2 so the image stays the same) and meshes (a `scale S` option, paths
made absolute) are scaled. Triangle lines are refused (not handled)."""
import os
import sys


def num(t):
    """The scene format's numbers: a C literal or a sum A+B of two, evaluated in double."""
    for i in range(1, len(t)):
        if t[i] in "+-" and t[i - 1] not in "eE":
            return float(t[:i]) + float(t[i:])
    return float(t)


def main(argv):
    if len(argv) not in (4, 5) or (len(argv) == 5 and argv[4] != "--epsilon"):
        sys.exit(__doc__.split("\n\n")[1])
    src, s_arg, dst = argv[1], argv[2], argv[3]
    s = 2.0 ** int(s_arg[2:]) if s_arg.startswith("2^") else float(s_arg)
    scenes = os.path.dirname(os.path.abspath(src))
    eps = 1e-4
    out = []
    for line in open(src):
        body = line.split("#", 1)[0].split()
        if not body:
            out.append(line.rstrip("\n"))
            continue
        k = body[0]
        if k == "sphere":
            body[1:5] = [repr(num(x) * s) for x in body[1:5]]
        elif k == "camera":
            for key in ("origin", "position", "lookat"):
                if key in body:
                    i = body.index(key)
                    body[i + 1:i + 4] = [repr(num(x) * s) for x in body[i + 1:i + 4]]
            if "near" in body:
                i = body.index("near")
                body[i + 1] = repr(num(body[i + 1]) * s)
        elif k == "light" and body[1] == "point":
            body[2:5] = [repr(num(x) * s) for x in body[2:5]]
            if body[5] in ("intensity", "flux"):
                body[6:9] = [repr(num(x) * s * s) for x in body[6:9]]
        elif k == "mesh":
            body[1] = os.path.join(scenes, body[1])
            if "scale" not in body:
                body += ["scale", repr(s)]
        elif k == "epsilon":
            eps = num(body[1])
            continue
        elif k == "triangle" or (k == "light" and body[1] == "triangle"):
            sys.exit("scale-scene: %s: %s lines are not handled" % (src, k))
        out.append(" ".join(body))
    if len(argv) == 5:
        out.append("epsilon %r" % (eps * s))
    with open(dst, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(sys.argv)
