# SPDX-License-Identifier: Apache-2.0
"""svg.py: the report's charts as inline SVG (no plotting library, no network): a grouped bar
chart and a log-log line plot."""
import html
import math

PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"]


def bars(title, groups, series, values, unit="", width=640, height=260):
    """groups: x labels; series: bar names; values[g][s] (None: not run). One colour a series."""
    left, bottom, top = 60, 40, 30
    plot_w, plot_h = width - left - 20, height - bottom - top
    vmax = max([v for row in values for v in row if v is not None] + [1e-12])
    out = ['<svg class="chart" xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" role="img">' % (width, height),
           '<text x="%d" y="18" font-weight="bold">%s</text>' % (left, html.escape(title))]
    for k in range(5):
        v = vmax * k / 4
        y = top + plot_h - plot_h * k / 4
        out.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#ddd"/>' % (left, left + plot_w, y, y))
        out.append('<text x="%d" y="%.1f" text-anchor="end" font-size="11">%.3g%s</text>' % (left - 4, y + 4, v, unit))
    gw = plot_w / max(1, len(groups))
    bw = gw * 0.8 / max(1, len(series))
    for g, name in enumerate(groups):
        x0 = left + g * gw + gw * 0.1
        if all(v is None for v in values[g]):
            out.append('<text x="%.1f" y="%d" text-anchor="middle" font-size="11" fill="#888">not run</text>'
                       % (left + g * gw + gw / 2, top + plot_h - 4))
            continue
        for s in range(len(series)):
            v = values[g][s]
            x = x0 + s * bw
            if v is None:
                continue
            h = plot_h * v / vmax
            out.append('<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="%s"><title>%s %s: %.6g%s</title></rect>'
                       % (x, top + plot_h - h, bw - 2, h, PALETTE[s % len(PALETTE)], html.escape(name),
                          html.escape(series[s]), v, unit))
        out.append('<text x="%.1f" y="%d" text-anchor="middle" font-size="12">%s</text>'
                   % (left + g * gw + gw / 2, top + plot_h + 16, html.escape(name)))
    for s, name in enumerate(series):
        out.append('<rect x="%d" y="%d" width="10" height="10" fill="%s"/><text x="%d" y="%d" font-size="11">%s</text>'
                   % (10 + s * 125, height - 12, PALETTE[s % len(PALETTE)], 24 + s * 125, height - 3,
                      html.escape(name)))
    out.append("</svg>")
    return "\n".join(out)


def loglog(title, xlabel, ylabel, lines, width=640, height=300):
    """lines: [(name, [(x, y), ...])] with x, y > 0, drawn on log-log axes."""
    left, bottom, top, right = 70, 45, 30, 20
    pts = [p for _, ps in lines for p in ps if p[0] > 0 and p[1] > 0]
    if not pts:
        return ""
    lx = [math.log10(p[0]) for p in pts]
    ly = [math.log10(p[1]) for p in pts]
    x0, x1 = math.floor(min(lx)), math.ceil(max(lx))
    y0, y1 = math.floor(min(ly)), math.ceil(max(ly))
    x1, y1 = max(x1, x0 + 1), max(y1, y0 + 1)
    pw, ph = width - left - right, height - top - bottom
    X = lambda v: left + pw * (math.log10(v) - x0) / (x1 - x0)
    Y = lambda v: top + ph - ph * (math.log10(v) - y0) / (y1 - y0)
    out = ['<svg class="chart" xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" role="img">' % (width, height),
           '<text x="%d" y="18" font-weight="bold">%s</text>' % (left, html.escape(title))]
    for d in range(x0, x1 + 1):
        out.append('<line x1="%.1f" x2="%.1f" y1="%d" y2="%d" stroke="#ddd"/><text x="%.1f" y="%d" '
                   'text-anchor="middle" font-size="11">1e%d</text>' % (X(10 ** d), X(10 ** d), top, top + ph,
                                                                      X(10 ** d), top + ph + 14, d))
    for d in range(y0, y1 + 1):
        out.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#ddd"/><text x="%d" y="%.1f" '
                   'text-anchor="end" font-size="11">1e%d</text>' % (left, left + pw, Y(10 ** d), Y(10 ** d),
                                                                   left - 4, Y(10 ** d) + 4, d))
    out.append('<text x="%d" y="%d" text-anchor="middle" font-size="12">%s</text>'
               % (left + pw / 2, height - 8, html.escape(xlabel)))
    out.append('<text x="14" y="%d" font-size="12" transform="rotate(-90 14 %d)" text-anchor="middle">%s</text>'
               % (top + ph / 2, top + ph / 2, html.escape(ylabel)))
    for k, (name, ps) in enumerate(lines):
        c = PALETTE[k % len(PALETTE)]
        ps = [p for p in ps if p[0] > 0 and p[1] > 0]
        out.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>'
                   % (c, " ".join("%.1f,%.1f" % (X(x), Y(y)) for x, y in ps)))
        for x, y in ps:
            out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"><title>%s: %.4g, %.4g</title></circle>'
                       % (X(x), Y(y), c, html.escape(name), x, y))
        out.append('<rect x="%d" y="%d" width="10" height="10" fill="%s"/><text x="%d" y="%d" font-size="11">%s</text>'
                   % (left + 10 + k * 120, top + 4, c, left + 24 + k * 120, top + 13, html.escape(name)))
    out.append("</svg>")
    return "\n".join(out)
