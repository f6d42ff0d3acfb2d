# SPDX-License-Identifier: Apache-2.0
# pairs.py DIR: the FLIP test pairs (8-bit P3 PPM, 64x48): noise (small random differences),
# edges (a checkerboard shifted by one pixel in its lower two thirds), colour (a hue change).
# Deterministic; tests/checks/compare_flip.sh and scripts/flip-reference.sh use them.
import math, sys
def lcg(seed):
    s = seed
    while True:
        s = (s * 6364136223846793005 + 1442695040888963407) % 2**64
        yield (s >> 11) / 2.0**53
def write(path, w, h, v):
    with open(path, 'w') as f:
        f.write('P3\n%d %d\n255\n' % (w, h) + ' '.join(str(x) for x in v) + '\n')
def pair(kind, w, h, seed):
    r = lcg(seed); a = []; b = []
    for y in range(h):
        for x in range(w):
            for c in range(3):
                if kind == 'noise':
                    base = 0.5 + 0.35 * math.sin(0.3 * x + 1.7 * c) * math.cos(0.2 * y)
                    va = base; vb = base + 0.12 * (next(r) - 0.5)
                elif kind == 'edges':   # squares and a line, test shifted by one pixel
                    def img(xx):
                        return (0.9 if ((xx // 8) + (y // 8)) % 2 else 0.1) * (0.5 + 0.5 * (c == (xx // 16) % 3))
                    va = img(x); vb = img(x + 1) if y > h // 3 else img(x)
                elif kind == 'colour':  # smooth hue change in the middle
                    va = 0.5 + 0.4 * math.sin(0.05 * x + 2.1 * c)
                    vb = va + (0.2 * math.cos(0.07 * y + c) if 10 < x < w - 10 else 0.0)
                a.append(min(255, max(0, int(va * 255 + 0.5)))); b.append(min(255, max(0, int(vb * 255 + 0.5))))
    return a, b
W, H = 64, 48
for k, s in (('noise', 1), ('edges', 2), ('colour', 3)):
    a, b = pair(k, W, H, s)
    write(sys.argv[1] + '/%s_a.ppm' % k, W, H, a); write(sys.argv[1] + '/%s_b.ppm' % k, W, H, b)
