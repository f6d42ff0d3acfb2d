#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""build.py: `make report`: one self-contained HTML page, OUT/report/index.html, from the JSON and
images PREE's commands already wrote (sections.py says which). Every image is inlined, so the
page opens without a network or any file beside it. A script marks the page when every image has
loaded (body data-images="ok", or "broken: NAMES"), which tests/checks/report_browser.sh reads
through headless Chromium.

Usage: build.py ROOT OUT BUILD   (the repository, the run's output folder, the build folder)
"""
import datetime
import html
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sections  # noqa: E402

STYLE = """
body { font-family: sans-serif; margin: 1.5em; color: #222; max-width: 1400px; }
h2 { border-bottom: 2px solid #ccc; margin-top: 1.6em; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 13px; }
td, th { border: 1px solid #bbb; padding: 3px 7px; text-align: right; }
th { background: #eee; }
.row { display: flex; flex-wrap: wrap; gap: 12px; }
figure { margin: 0; } figcaption { font-size: 12px; color: #555; }
img.px2 { width: 480px; image-rendering: pixelated; }
img.wide { max-width: 640px; }
.missing { color: #a60; } .ok { color: #070; font-weight: bold; } .bad { color: #b00; font-weight: bold; }
.slider { position: relative; width: 480px; }
.slider .over { position: absolute; top: 0; left: 0; overflow: hidden; width: 50%; height: 100%; }
.slider .over img { max-width: none; }
#cut { width: 480px; }
.src { font-size: 12px; color: #666; }
"""

SCRIPT = """
(function () {
  var cut = document.getElementById('cut'), over = document.getElementById('over');
  if (cut && over) cut.oninput = function () { over.style.width = cut.value + '%'; };
  var imgs = Array.prototype.slice.call(document.images), left = imgs.length;
  function done() {
    var bad = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); })
                  .map(function (i) { return i.getAttribute('data-name'); });
    document.body.setAttribute('data-images', bad.length ? 'broken: ' + bad.join(' ') : 'ok');
    document.body.setAttribute('data-image-count', String(imgs.length));
  }
  if (!left) { done(); return; }
  imgs.forEach(function (i) {
    if (i.complete) { if (--left === 0) done(); return; }
    i.addEventListener('load', function () { if (--left === 0) done(); });
    i.addEventListener('error', function () { if (--left === 0) done(); });
  });
})();
"""


def version(root):
    try:
        return subprocess.run(["git", "-C", root, "describe", "--always", "--dirty", "--tags"], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main(root, out, build):
    docs_images = os.path.join(root, "docs", "images")
    body = [
        "<h1>PREE report</h1>",
        "<p>%s, tree %s. Every figure below is read from the files the commands wrote; a missing one says "
        "&ldquo;not run&rdquo; with its command.</p>" % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
                                                          html.escape(version(root))),
        sections.tests(os.path.join(build, "test-results.xml")),
        sections.images(out),
        sections.comparisons(out),
        sections.utilization(out, build),
        sections.convergence(out, docs_images),
        sections.fpga(root, build),
        sections.numerics(docs_images),
    ]
    page = ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>PREE report</title>"
            "<style>%s</style></head>\n<body>\n%s\n<script>%s</script>\n</body></html>\n"
            % (STYLE, "\n".join(body), SCRIPT))
    dest = os.path.join(out, "report")
    os.makedirs(dest, exist_ok=True)
    tmp = os.path.join(dest, ".index.html.tmp")
    with open(tmp, "w") as f:
        f.write(page)
    os.replace(tmp, os.path.join(dest, "index.html"))
    print("report: %s (%d KiB)" % (os.path.join(dest, "index.html"), len(page) // 1024))
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
