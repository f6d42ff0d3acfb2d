#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# level: quick
# `pree compare` end to end: metrics of generated 8-bit (PPM) and float (PFM) image pairs against
# an independent pure-Python computation (SSIM by direct 11x11 windows with central moments),
# the text and JSON output, --diff maps (relative, absolute and SSIM pictures with their colour
# bars and values, the bars' maxima against Python's, a known single-pixel difference, --log;
# linear EXR), and every error
# path's exit status (1: bad image or mismatch, 2: usage) with no partial --diff file.
# Usage: tests/checks/compare_cli.sh   (PREE=path/to/pree to test another build)
set -u
cd "$(dirname "$0")/../.."
PREE=${PREE:-build/pree}
REPRO="bash tests/checks/compare_cli.sh"
tmp=$(mktemp -d /tmp/pree-compare-check-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

[ -x "$PREE" ] || { echo "FAIL: $PREE not built (make build); reproduce: $REPRO"; exit 1; }

# The independent reference: writes the test images and checks pree's figures against its own.
cat >"$tmp/ref.py" <<'PY'
import json, math, struct, sys

def lcg(seed):
    s = seed
    while True:
        s = (s * 6364136223846793005 + 1442695040888963407) % 2**64
        yield (s >> 11) / 2.0**53

def make_pair(w, h, seed, is_float):
    r = lcg(seed)
    a, b = [], []
    for y in range(h):
        for x in range(w):
            for c in range(3):
                base = 0.5 + 0.35 * math.sin(0.4 * x + c) * math.cos(0.3 * y) + 0.1 * next(r)
                other = 0.7 * base + 0.1 + 0.15 * (next(r) - 0.5)
                if is_float:   # values exactly representable in binary32
                    a.append(struct.unpack('<f', struct.pack('<f', 3.0 * base))[0])
                    b.append(struct.unpack('<f', struct.pack('<f', 3.0 * other))[0])
                else:
                    a.append(min(255, max(0, int(base * 255))))
                    b.append(min(255, max(0, int(other * 255))))
    return a, b

def write_ppm(path, w, h, v):
    with open(path, 'w') as f:
        f.write('P3\n%d %d\n255\n' % (w, h) + ''.join('%d ' % x for x in v))

def write_pfm(path, w, h, v):   # PFM stores the bottom row first
    with open(path, 'wb') as f:
        f.write(b'PF\n%d %d\n-1.0\n' % (w, h))
        for y in reversed(range(h)):
            f.write(struct.pack('<%df' % (3 * w), *v[3 * w * y:3 * w * (y + 1)]))

def ssim(a, b, w, h, L):
    g = [[math.exp(-((i - 5) ** 2 + (j - 5) ** 2) / 4.5) for j in range(11)] for i in range(11)]
    tot = sum(map(sum, g))
    g = [[v / tot for v in row] for row in g]
    C1, C2 = (0.01 * L) ** 2, (0.03 * L) ** 2
    res = 0.0
    for c in range(3):
        acc, cnt = 0.0, 0
        for y in range(h - 10):
            for x in range(w - 10):
                idx = [(g[i][j], 3 * ((y + i) * w + x + j) + c) for i in range(11) for j in range(11)]
                ma = sum(wt * a[k] for wt, k in idx)
                mb = sum(wt * b[k] for wt, k in idx)
                va = sum(wt * (a[k] - ma) ** 2 for wt, k in idx)
                vb = sum(wt * (b[k] - mb) ** 2 for wt, k in idx)
                cov = sum(wt * (a[k] - ma) * (b[k] - mb) for wt, k in idx)
                acc += (2 * ma * mb + C1) * (2 * cov + C2) / ((ma * ma + mb * mb + C1) * (va + vb + C2))
                cnt += 1
        res += acc / cnt
    return res / 3

def metrics(a, b, w, h, L):
    d2 = sum((x - y) ** 2 for x, y in zip(a, b))
    mse = d2 / len(a)
    return {'width': w, 'height': h, 'peak': L, 'ssim': ssim(a, b, w, h, L),
            'snr_db': 10 * math.log10(sum(x * x for x in a) / d2),
            'psnr_db': 10 * math.log10(L * L / mse), 'rmse': math.sqrt(mse),
            'max_abs': max(abs(x - y) for x, y in zip(a, b))}

def read_ppm(path):
    t = open(path).read().split()
    assert t[0] == 'P3' and t[3] == '255', path
    w, h = int(t[1]), int(t[2])
    return w, h, [int(x) for x in t[4:4 + 3 * w * h]]

def colour(t):   # the documented colour map: black, red, yellow, white
    return [int(min(1.0, max(0.0, 3 * t - c)) * 255 + 0.5) for c in range(3)]

def ssim_map(a, b, w, h, L):   # per-window SSIM, mean over channels: Python's own windows
    g = [[math.exp(-((i - 5) ** 2 + (j - 5) ** 2) / 4.5) for j in range(11)] for i in range(11)]
    tot = sum(map(sum, g)); g = [[v / tot for v in row] for row in g]
    C1, C2 = (0.01 * L) ** 2, (0.03 * L) ** 2
    out = []
    for y in range(h - 10):
        for x in range(w - 10):
            s = 0.0
            for c in range(3):
                idx = [(g[i][j], 3 * ((y + i) * w + x + j) + c) for i in range(11) for j in range(11)]
                ma = sum(wt * a[k] for wt, k in idx); mb = sum(wt * b[k] for wt, k in idx)
                va = sum(wt * (a[k] - ma) ** 2 for wt, k in idx); vb = sum(wt * (b[k] - mb) ** 2 for wt, k in idx)
                cov = sum(wt * (a[k] - ma) * (b[k] - mb) for wt, k in idx)
                s += (2 * ma * mb + C1) * (2 * cov + C2) / ((ma * ma + mb * mb + C1) * (va + vb + C2))
            out.append(s / 3)
    return out

def check_maps(d, figfile, kind):
    figs = dict(l.split() for l in open(figfile))
    stem = {'u8': 'd', 'one': 'one', 'log': 'l'}[kind]
    if kind == 'one':
        a, b = read_ppm(d + '/one_a.ppm')[2], read_ppm(d + '/one_b.ppm')[2]
    else:
        a, b = make_pair(W, H, 1, False)
    L = 255.0
    rel = [max(abs(a[3 * p + c] - b[3 * p + c]) / (abs(a[3 * p + c]) + 0.01 * L) for c in range(3)) for p in range(W * H)]
    ab = [max(abs(a[3 * p + c] - b[3 * p + c]) for c in range(3)) for p in range(W * H)]
    sm = ssim_map(a, b, W, H, L)
    bad = 0
    def need(cond, what):
        nonlocal bad
        print(('ok: ' if cond else 'FAIL: ') + what); bad += not cond
    def close(x, y): return abs(x - y) <= 1e-9 * max(1.0, abs(y))
    need(close(float(figs['rel_max']), max(rel)), 'rel_max %s = Python max relative error %r' % (figs['rel_max'], max(rel)))
    need(close(float(figs['max_abs']), max(ab)), 'max_abs %s = Python max |a - b| %r' % (figs['max_abs'], max(ab)))
    need(close(float(figs['ssim_min']), min(sm)), 'ssim_min %s = Python SSIM map minimum %r' % (figs['ssim_min'], min(sm)))
    if kind == 'one':
        need(close(max(rel), 10 / (100 + 2.55)), 'known pair: relative error 10 / (100 + 0.01 * 255)')
    for suffix, field in (('', rel), ('-abs', ab), ('-ssim', None)):
        cw, ch, px = read_ppm('%s/%s%s.ppm' % (d, stem, suffix))
        name = stem + suffix + '.ppm'
        need((cw, ch) == (max(W, 240), H + 42), '%s: canvas %dx%d' % (name, cw, ch))
        at = lambda x, y: px[3 * (y * cw + x):3 * (y * cw + x) + 3]
        x0, x1, by = 6, cw - 7, H + 6
        bar = all(at(x, by + 6) == colour((x - x0) / (x1 - x0)) for x in range(x0, x1 + 1))
        need(bar, '%s: colour bar from black to white across columns %d..%d' % (name, x0, x1))
        ink = sum(1 for y in range(H + 22, ch) for x in range(cw) if at(x, y) == [255, 255, 255])
        need(ink > 100, '%s: values drawn under the bar (%d white pixels)' % (name, ink))
        if field is not None and kind != 'log':
            m = max(field)
            want = [c for v in field for c in colour(v / m if m > 0 else 0.0)]
            got = [c for y in range(H) for c in px[3 * y * cw:3 * (y * cw + W)]]
            need(got == want, '%s: picture = colour(value / max) for every pixel (max white)' % name)
        if field is not None and kind == 'log':
            m = max(field); lo = m / 1e4   # four decades, or the smallest value's decade if higher
            dec = 10.0 ** math.floor(math.log10(min(v for v in field if v > 0)))
            lo = dec if lo < dec < m else lo
            pos = lambda v: 0.0 if v <= 0 else min(1.0, max(0.0, math.log(v / lo) / math.log(m / lo)))
            want = [c for v in field for c in colour(pos(v))]
            got = [c for y in range(H) for c in px[3 * y * cw:3 * (y * cw + W)]]
            need(got == want, '%s: picture = colour(log(value / lo) / log(max / lo)), lo %.3g' % (name, lo))
        if field is None:
            ms = sm.index(min(sm)); x, y = ms % (W - 10) + 5, ms // (W - 10) + 5
            need(at(x, y) == [255, 255, 255], '%s: the lowest SSIM (%d, %d) white' % (name, x, y))
            need(at(2, 2) == [48, 48, 48], '%s: the border without an SSIM window grey' % name)
    return 1 if bad else 0

cmd, d = sys.argv[1], sys.argv[2]
W, H = 29, 23
if cmd == 'make':
    a, b = make_pair(W, H, 1, False)
    write_ppm(d + '/a.ppm', W, H, a); write_ppm(d + '/b.ppm', W, H, b)
    write_ppm(d + '/small.ppm', 10, 23, a[:10 * 23 * 3])
    fa, fb = make_pair(W, H, 2, True)
    write_pfm(d + '/a.pfm', W, H, fa); write_pfm(d + '/b.pfm', W, H, fb)
    write_pfm(d + '/absdiff.pfm', W, H, [abs(x - y) for x, y in zip(fa, fb)])
    one = [100] * (3 * W * H)
    write_ppm(d + '/one_a.ppm', W, H, one)
    one[3 * (7 * W + 12) + 1] = 110   # one green sample 10% up at pixel (12, 7)
    write_ppm(d + '/one_b.ppm', W, H, one)
elif cmd == 'maps':   # maps DIR FIGURES KIND: the --diff pictures against the documented layout
    sys.exit(check_maps(d, sys.argv[3], sys.argv[4]))
elif cmd == 'check':   # check FILE.json KIND
    got = json.load(open(sys.argv[3]))
    if sys.argv[4] == 'u8':
        a, b = make_pair(W, H, 1, False); L = 255.0
    else:
        a, b = make_pair(W, H, 2, True); L = max(a) - min(a)
    want = metrics(a, b, W, H, L)
    bad = 0
    for k, v in want.items():
        g = got.get(k)
        ok = isinstance(g, (int, float)) and abs(g - v) <= 1e-12 * max(1.0, abs(v))
        print('%-8s pree %-22r python %-22r %s' % (k, g, v, 'ok' if ok else 'MISMATCH'))
        bad += not ok
    sys.exit(1 if bad else 0)
PY

python3 "$tmp/ref.py" make "$tmp" || { echo "FAIL: image generation; reproduce: $REPRO"; exit 1; }

# 1. 8-bit and float pairs: JSON figures against Python's, and text output carrying the same keys.
for kind in u8 float; do
  ext=ppm; [ $kind = float ] && ext=pfm
  if "$PREE" compare "$tmp/a.$ext" "$tmp/b.$ext" --json >"$tmp/$kind.json" 2>"$tmp/err"; then
    python3 "$tmp/ref.py" check "$tmp" "$tmp/$kind.json" $kind || fail "$kind metrics differ from the Python reference"
  else
    fail "$kind compare exited non-zero: $(cat "$tmp/err")"
  fi
done
"$PREE" compare "$tmp/a.ppm" "$tmp/b.ppm" >"$tmp/text" || fail "text output exited non-zero"
keys=$(cut -d' ' -f1 "$tmp/text" | tr '\n' ' ')
[ "$keys" = "width height peak ssim snr_db psnr_db rmse max_abs " ] || fail "text keys are '$keys'"
python3 - "$tmp/text" "$tmp/u8.json" <<'PY' || fail "text and JSON figures disagree"
import json, sys
text = dict(l.split() for l in open(sys.argv[1]))
js = json.load(open(sys.argv[2]))
assert all(abs(float(text[k]) - js[k]) <= 1e-9 * max(1, abs(js[k])) for k in text), (text, js)
PY

# 2. Identical images: SSIM 1, no difference, SNR and PSNR "inf" in text and JSON.
"$PREE" compare "$tmp/a.ppm" "$tmp/a.ppm" >"$tmp/same" || fail "identical compare exited non-zero"
grep -qx 'ssim 1' "$tmp/same" && grep -qx 'snr_db inf' "$tmp/same" && grep -qx 'psnr_db inf' "$tmp/same" \
  && grep -qx 'rmse 0' "$tmp/same" && grep -qx 'max_abs 0' "$tmp/same" || fail "identical images: $(tr '\n' ' ' <"$tmp/same")"
"$PREE" compare "$tmp/a.ppm" "$tmp/a.ppm" --json | python3 -c '
import json, sys; j = json.load(sys.stdin); assert j["snr_db"] == "inf" and j["psnr_db"] == "inf" and j["ssim"] == 1, j' \
  || fail "identical images: JSON"

# 3. --diff: three maps, each a false-colour picture with a colour bar and its values below;
# the absolute-error picture is the documented heat map byte for byte, every bar's top is its
# map's printed maximum (checked against Python's), and a known single-pixel difference.
"$PREE" compare "$tmp/a.ppm" "$tmp/b.ppm" --diff "$tmp/d.ppm" >"$tmp/dtext" || fail "--diff d.ppm exited non-zero"
python3 "$tmp/ref.py" maps "$tmp" "$tmp/dtext" u8 || fail "--diff maps (above)"
"$PREE" compare "$tmp/a.ppm" "$tmp/b.ppm" --diff="$tmp/d.png" >/dev/null || fail "--diff=d.png exited non-zero"
for m in "" -abs -ssim; do
  "$PREE" compare "$tmp/d$m.png" "$tmp/d$m.ppm" >"$tmp/dpng" 2>&1 && grep -qx 'max_abs 0' "$tmp/dpng" \
    || fail "--diff PNG d$m.png differs from d$m.ppm: $(tr '\n' ' ' <"$tmp/dpng")"
done
"$PREE" compare "$tmp/one_a.ppm" "$tmp/one_b.ppm" --diff "$tmp/one.ppm" >"$tmp/onetext" || fail "--diff one.ppm exited non-zero"
python3 "$tmp/ref.py" maps "$tmp" "$tmp/onetext" one || fail "--diff maps of the known pair (above)"
"$PREE" compare "$tmp/a.ppm" "$tmp/b.ppm" --diff "$tmp/l.ppm" --log >"$tmp/ltext" || fail "--diff --log exited non-zero"
python3 "$tmp/ref.py" maps "$tmp" "$tmp/ltext" log || fail "--diff --log maps (above)"
"$PREE" compare "$tmp/a.pfm" "$tmp/b.pfm" --diff "$tmp/d.exr" >/dev/null || fail "--diff d.exr exited non-zero"
"$PREE" compare "$tmp/absdiff.pfm" "$tmp/d.exr" >"$tmp/dexr" 2>&1 && grep -qx 'max_abs 0' "$tmp/dexr" \
  || fail "--diff EXR is not |a - b|: $(tr '\n' ' ' <"$tmp/dexr")"

# 4. Errors: exit status, one line on stderr naming the problem, no --diff file left behind.
expect() {   # expect STATUS PATTERN ARGS...: exit status and a one-line message matching PATTERN
  local want=$1 pat=$2; shift 2
  timeout 60 "$PREE" compare "$@" >"$tmp/out" 2>"$tmp/err"; local rc=$?
  if [ $rc -ne "$want" ]; then fail "pree compare $*: exit $rc, want $want"; return; fi
  [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "pree compare $*: stderr is not one line: $(cat "$tmp/err")"
  grep -q -- "$pat" "$tmp/err" || fail "pree compare $*: message '$(cat "$tmp/err")' lacks '$pat'"
  [ ! -s "$tmp/out" ] || fail "pree compare $*: printed figures on failure"
}
expect 1 'sizes differ' "$tmp/a.ppm" "$tmp/small.ppm"
expect 1 'sample types differ' "$tmp/a.ppm" "$tmp/a.pfm"
expect 1 "$tmp/missing.png" "$tmp/a.ppm" "$tmp/missing.png"
expect 1 'at least 11x11' "$tmp/small.ppm" "$tmp/small.ppm"
expect 1 '/dev/zero: not a regular file' "$tmp/a.ppm" /dev/zero   # once an endless read
mkfifo "$tmp/fifo"
expect 1 'fifo: not a regular file' "$tmp/fifo" "$tmp/a.ppm"         # once a wait for a writer
expect 1 'is a directory' "$tmp/a.ppm" "$tmp"
cp "$tmp/a.ppm" "$tmp/keep.ppm"
expect 1 'the same file as IMAGE_A' "$tmp/a.ppm" "$tmp/b.ppm" --diff "$tmp/a.ppm"   # once overwrote a.ppm
expect 1 'the same file as IMAGE_B' "$tmp/a.ppm" "$tmp/b.ppm" --diff "$tmp/./b.ppm"
cmp -s "$tmp/a.ppm" "$tmp/keep.ppm" || fail "--diff a.ppm changed the input"
expect 1 '/dev/null: not a regular file' "$tmp/a.ppm" "$tmp/b.ppm" --diff /dev/null
expect 1 "$tmp/nodir/d.png" "$tmp/a.ppm" "$tmp/b.ppm" --diff "$tmp/nodir/d.png"
expect 1 'unknown 8-bit image extension' "$tmp/a.ppm" "$tmp/b.ppm" --diff "$tmp/d.tif"
expect 1 'sizes differ' "$tmp/a.ppm" "$tmp/small.ppm" --diff "$tmp/never.png"
[ ! -e "$tmp/never.png" ] && [ ! -e "$tmp/d.tif" ] || fail "a failed compare left a --diff file"
ls -a "$tmp" | grep -q '\.tmp-' && fail "a temporary file was left behind"
expect 2 'unknown option' "$tmp/a.ppm" "$tmp/b.ppm" --bogus
expect 2 'needs two images' "$tmp/a.ppm"
expect 2 'needs two images'
expect 2 'too many images' "$tmp/a.ppm" "$tmp/b.ppm" "$tmp/b.ppm"
expect 2 '--diff needs a value' "$tmp/a.ppm" "$tmp/b.ppm" --diff
"$PREE" compare --help | grep -q '^usage: pree compare' || fail "--help"

if [ $fails -ne 0 ]; then echo "$fails failure(s); reproduce: $REPRO"; exit 1; fi
echo "compare_cli: all checks passed"
