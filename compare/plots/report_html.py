#!/usr/bin/env python3
"""Write report.html beside report.md: the robustness report as one self-contained page.

Usage:  python3 compare/plots/report_html.py DIR

Reads   DIR/report.md          the report (written by report_figures.py): rendered as it is, the verdict first
        DIR/results.csv        one row per (scene, pipeline): the table of scenes and the charts you can hover
                               (time per run; near-miss runs per separation)
        DIR/failure_map.csv    optional: the failure map as a grid of cells you can hover
        DIR/scenes/index.json  optional (eccd report writes it): each scene's file, relative to DIR, and under
                               "pictures" the failure map's scene drawn as `eccd plot` draws it (scenes/NAME.png)
        DIR/*.png              the figures report.md shows, inlined as data: URIs
Writes  DIR/report.html        (atomically: a temporary file renamed into place)

The page loads nothing from the network: its style and script are inline, its figures data: URIs. Every
table sorts (click a column's header) and filters (the box above it). A URL hash #sort=TABLE:COLUMN[:desc]
sorts a table on load (TABLE: its number from 0, or its id such as scenes-table; COLUMN from 0; several
joined by '&'), so a test can drive the sort without a mouse. Links to
scene files are relative: they hold while the report stays where `eccd report` wrote it. Script errors are
counted in <body data-js-errors>; <body data-ready="1"> says the script ran to its end.
"""
import base64
import csv
import html
import json
import os
import re
import sys
import tempfile
import zlib

PROG = "report_html.py"


class InputError(Exception):
    pass


# --------------------------------------------------------------------------- markdown (the subset report.md uses)


def slug(text):
    """GitHub's heading anchor: lower case, punctuation dropped, spaces to '-'."""
    t = re.sub(r"<[^>]+>", "", text).strip().lower()
    t = re.sub(r"[^\w\- ]", "", t, flags=re.UNICODE)
    return t.replace(" ", "-")


def inline(text):
    """Escapes and renders `code`, **bold**, *emphasis*, [links](url) and ![images](file)."""
    out, pos = [], 0
    pattern = re.compile(r"`([^`]+)`|!\[([^\]]*)\]\(([^)\s]+)\)|\[([^\]]+)\]\(([^)\s]+)\)|\*\*(.+?)\*\*|\*(.+?)\*")
    for m in pattern.finditer(text):
        out.append(html.escape(text[pos:m.start()]))
        if m.group(1) is not None:
            out.append(f"<code>{html.escape(m.group(1))}</code>")
        elif m.group(3) is not None:
            out.append(f'<img alt="{html.escape(m.group(2))}" src="{html.escape(m.group(3))}">')
        elif m.group(5) is not None:
            out.append(f'<a href="{html.escape(m.group(5))}">{inline(m.group(4))}</a>')
        elif m.group(6) is not None:
            out.append(f"<strong>{inline(m.group(6))}</strong>")
        else:
            out.append(f"<em>{inline(m.group(7))}</em>")
        pos = m.end()
    out.append(html.escape(text[pos:]))
    return "".join(out)


def split_row(line):
    cells = line.strip().strip("|").split("|")
    return [c.strip() for c in cells]


def markdown_blocks(md):
    """report.md as blocks: ('h', level, text), ('p', text), ('ul', [items]), ('table', head, aligns, rows),
    ('img', alt, src)."""
    lines = md.splitlines()
    blocks, i = [], 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            i += 1
            continue
        m = re.match(r"^(#{1,6})\s+(.*)$", line)
        if m:
            blocks.append(("h", len(m.group(1)), m.group(2).strip()))
            i += 1
            continue
        m = re.match(r"^!\[([^\]]*)\]\(([^)\s]+)\)\s*$", line)
        if m:
            blocks.append(("img", m.group(1), m.group(2)))
            i += 1
            continue
        if line.lstrip().startswith("|") and i + 1 < len(lines) and re.match(r"^\s*\|[\s:\-|]+\|\s*$", lines[i + 1]):
            head = split_row(line)
            aligns = ["right" if c.endswith(":") else "left" for c in split_row(lines[i + 1])]
            rows, i = [], i + 2
            while i < len(lines) and lines[i].lstrip().startswith("|"):
                rows.append(split_row(lines[i]))
                i += 1
            blocks.append(("table", head, aligns, rows))
            continue
        if re.match(r"^\s*[-*] ", line):
            items = []
            while i < len(lines) and lines[i].strip():
                if re.match(r"^\s*[-*] ", lines[i]):
                    items.append(re.sub(r"^\s*[-*] ", "", lines[i]))
                else:
                    items[-1] += " " + lines[i].strip()
                i += 1
            blocks.append(("ul", items))
            continue
        para = []
        while i < len(lines) and lines[i].strip() and not re.match(r"^(#{1,6}\s|\s*[-*] |\s*\||!\[)", lines[i]):
            para.append(lines[i].strip())
            i += 1
        if para:
            blocks.append(("p", " ".join(para)))
        else:  # a line no rule took: keep it as a paragraph rather than loop
            blocks.append(("p", line.strip()))
            i += 1
    return blocks


def verdict_first(blocks):
    """The blocks with the section '## Verdict' (up to the next heading of level <= 2) right after the title."""
    start = next((k for k, b in enumerate(blocks) if b[0] == "h" and b[1] == 2 and b[2].lower() == "verdict"), None)
    if start is None:
        return blocks
    end = next((k for k in range(start + 1, len(blocks)) if blocks[k][0] == "h" and blocks[k][1] <= 2), len(blocks))
    title = 1 if blocks and blocks[0][0] == "h" and blocks[0][1] == 1 else 0
    if start == title:
        return blocks
    return blocks[:title] + blocks[start:end] + blocks[title:start] + blocks[end:]


# --------------------------------------------------------------------------- data


def read_rows(path):
    if not os.path.exists(path):
        raise InputError(f"{path}: missing (eccd report writes it)")
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    for col in ("scene", "dim", "degree", "family", "pipeline", "arith", "outcome", "time_us"):
        if rows and col not in rows[0]:
            raise InputError(f"{path}: line 1: no column {col!r} (is this an eccd report's results.csv?)")
    return rows


def scene_index(out_dir):
    """scenes/index.json as (scene name -> its file, scene name -> its picture), both relative to out_dir; a
    picture is listed only when its file is there."""
    path = os.path.join(out_dir, "scenes", "index.json")
    if not os.path.exists(path):
        return {}, {}
    try:
        with open(path, encoding="utf-8") as fh:
            j = json.load(fh)
        files = {k: v for k, v in j["scenes"].items() if isinstance(v, str)}
        pictures = {k: v for k, v in (j.get("pictures") or {}).items()
                    if isinstance(v, str) and os.path.isfile(os.path.join(out_dir, v))}
        return files, pictures
    except (ValueError, KeyError, TypeError, AttributeError) as e:
        raise InputError(f"{path}: not an eccd-report-scenes/1 index: {e}")


def scene_cell(name, links):
    if name in links:
        return f'<a href="{html.escape(links[name])}" title="the scene file">{html.escape(name)}</a>'
    return html.escape(name)


WRONG = ("false_positive", "false_negative")


def scenes_table(rows, links):
    """One row per scene: what it is, the exact answer, and how many pipelines were wrong, undecided, errors."""
    by = {}
    for r in rows:
        by.setdefault(r["scene"], []).append(r)
    head = ["scene", "source", "dim", "degree", "family", "d", "exact collides", "wrong", "undecided", "error",
            "wrong pipelines"]
    aligns = ["left", "left", "right", "right", "left", "right", "left", "right", "right", "right", "left"]
    body = []
    for name in sorted(by):
        rs = by[name]
        r0 = rs[0]
        ex = next((r for r in rs if r["arith"] == "exact"), None)
        ec = {"1": "yes", "0": "no"}.get((ex or r0).get("exact_collides", ""), "—")
        if r0["outcome"] == "no_ground_truth":
            ec = "no ground truth"
        wrong = sorted({r["pipeline"] for r in rs if r["outcome"] in WRONG})
        body.append([scene_cell(name, links), html.escape(r0.get("source", "")), r0["dim"] + "D", r0["degree"],
                     html.escape(r0["family"]), html.escape(r0.get("d", "") or "—"), ec,
                     str(sum(1 for r in rs if r["outcome"] in WRONG)),
                     str(sum(1 for r in rs if r["outcome"] == "undecided")),
                     str(sum(1 for r in rs if r["outcome"] == "error")), html.escape(", ".join(wrong)) or "—"])
    return head, aligns, body


# --------------------------------------------------------------------------- figures you can hover

OUTCOME_COLOURS = {"correct": "#1f77b4", "undecided": "#9e9e9e", "false_positive": "#d62728",
                   "false_negative": "#ff7f0e", "error": "#212121"}


def time_chart(rows, links):
    """Inline SVG: the time of each exact and double run (one input mode) per motion degree, one point per run,
    coloured by outcome (5 series); a point names its scene and pipeline and links to the scene file."""
    mode = "rounded" if any(r.get("input") == "rounded" and r["arith"] == "double" for r in rows) else "prepared"
    pts = [r for r in rows if (r["arith"] == "exact" or (r["arith"] == "double" and r.get("input", mode) == mode))
           and r["outcome"] in OUTCOME_COLOURS and r.get("time_us") not in (None, "") and float(r["time_us"]) > 0]
    if not pts:
        return ""
    import math
    dims = sorted({r["dim"] for r in pts})
    W, H, L, B, T, R = 520, 330, 62, 42, 26, 12
    ys = [math.log10(float(r["time_us"])) for r in pts]
    y0, y1 = math.floor(min(ys)), math.ceil(max(ys)) + (1 if math.ceil(max(ys)) == math.floor(min(ys)) else 0)
    panels = []
    for dim in dims:
        dp = [r for r in pts if r["dim"] == dim]
        degs = sorted({int(r["degree"]) for r in dp})
        d0, d1 = min(degs) - 0.6, max(degs) + 0.6
        sx = lambda x: L + (x - d0) / (d1 - d0) * (W - L - R)
        sy = lambda y: T + (y1 - y) / (y1 - y0) * (H - T - B)
        parts = [f'<svg class="chart" viewBox="0 0 {W} {H}" width="{W}" height="{H}" role="img" '
                 f'aria-label="{dim}D: time per query of each exact and double run">',
                 f'<text x="{W / 2}" y="16" text-anchor="middle" class="ttl">{dim}D: each exact and double run '
                 f'(input {mode}), time per query</text>',
                 f'<rect x="{L}" y="{T}" width="{W - L - R}" height="{H - T - B}" class="frame"/>']
        for e in range(y0, y1 + 1):
            parts.append(f'<line x1="{L}" x2="{W - R}" y1="{sy(e):.1f}" y2="{sy(e):.1f}" class="grid"/>'
                         f'<text x="{L - 6}" y="{sy(e) + 4:.1f}" text-anchor="end">1e{e}</text>')
        for g in degs:
            parts.append(f'<text x="{sx(g):.1f}" y="{H - B + 16}" text-anchor="middle">{g}</text>')
        parts.append(f'<text x="{(L + W - R) / 2}" y="{H - 6}" text-anchor="middle">motion degree '
                     f'(exact left of the tick, double right)</text>')
        parts.append(f'<text x="14" y="{(T + H - B) / 2}" text-anchor="middle" transform="rotate(-90 14 '
                     f'{(T + H - B) / 2})">µs per query</text>')
        for r in sorted(dp, key=lambda r: (r["scene"], r["pipeline"])):
            jitter = ((zlib.crc32((r["scene"] + "|" + r["pipeline"]).encode()) % 1000) / 1000.0 - 0.5) * 0.22
            x = sx(int(r["degree"]) + (-0.2 if r["arith"] == "exact" else 0.2) + jitter)
            y = sy(math.log10(float(r["time_us"])))
            tip = (f'{r["scene"]} · {r["pipeline"]} · {r["outcome"].replace("_", " ")} · '
                   f'{float(r["time_us"]):.4g} µs')
            parts.append(_hover_dot(x, y, r, tip, links))
        parts.append("</svg>")
        panels.append("".join(parts))
    return _hover_figure(panels, "Each point is one run; hover a point for its scene, pipeline, outcome and time; "
                                 "a click opens the scene file.")


def near_miss_chart(rows, links):
    """Inline SVG per dimension: each near-miss run of the floating pipelines as published (guard none; rounded
    input when the run has it), one row per pipeline, one column per separation d (largest left), coloured by
    outcome (5 series); a point names its scene, pipeline, outcome and d, and links to the scene file. The
    per-scene view of misclassification_vs_d.png, whose points are counts."""
    flo = [r for r in rows if r["family"] == "near-miss" and r.get("d") and r["arith"] in ("double", "mpfr")
           and r["outcome"] in OUTCOME_COLOURS]
    if any(r.get("guard") == "none" for r in flo):
        flo = [r for r in flo if r.get("guard") == "none"]
    mode = "rounded" if any(r.get("input") == "rounded" for r in flo) else "prepared"
    flo = [r for r in flo if r.get("input", mode) in (mode, "")]
    if not flo:
        return ""
    panels = []
    for dim in sorted({r["dim"] for r in flo}):
        dp = [r for r in flo if r["dim"] == dim]
        pipes = list(dict.fromkeys(r["pipeline"] for r in dp))
        try:
            ds = sorted({r["d"] for r in dp}, key=lambda d: -float(d))
        except ValueError:
            ds = sorted({r["d"] for r in dp})
        L, R, T, B, rh = 200, 12, 26, 40, 18
        W = max(420, L + R + 46 * len(ds))
        H = T + B + rh * len(pipes)
        cw = (W - L - R) / len(ds)
        parts = [f'<svg class="chart" viewBox="0 0 {W} {H}" width="{W}" height="{H}" role="img" '
                 f'aria-label="{dim}D: near-miss runs as published, per pipeline and separation">',
                 f'<text x="{W / 2}" y="16" text-anchor="middle" class="ttl">{dim}D: near-miss runs as published '
                 f'(input {mode})</text>',
                 f'<rect x="{L}" y="{T}" width="{W - L - R}" height="{H - T - B}" class="frame"/>']
        for k, p in enumerate(pipes):
            y = T + rh * (k + 0.5)
            parts.append(f'<line x1="{L}" x2="{W - R}" y1="{y:.1f}" y2="{y:.1f}" class="grid"/>'
                         f'<text x="{L - 6}" y="{y + 4:.1f}" text-anchor="end">{html.escape(p)}</text>')
        for k, d in enumerate(ds):
            parts.append(f'<text x="{L + cw * (k + 0.5):.1f}" y="{H - B + 16}" text-anchor="middle">{html.escape(d)}</text>')
        parts.append(f'<text x="{(L + W - R) / 2}" y="{H - 6}" text-anchor="middle">separation d at the closest '
                     f'approach</text>')
        for r in sorted(dp, key=lambda r: (r["outcome"] != "correct", r["scene"], r["pipeline"])):  # wrong on top
            jitter = ((zlib.crc32(r["scene"].encode()) % 1000) / 1000.0 - 0.5) * 0.7  # a scene: one x per column
            x = L + cw * (ds.index(r["d"]) + 0.5 + jitter)
            y = T + rh * (pipes.index(r["pipeline"]) + 0.5)
            tip = f'{r["scene"]} · {r["pipeline"]} · {r["outcome"].replace("_", " ")} · d = {r["d"]}'
            parts.append(_hover_dot(x, y, r, tip, links))
        parts.append("</svg>")
        panels.append("".join(parts))
    return _hover_figure(panels, "Each point is one near-miss run of a floating pipeline as published; hover a "
                                 "point for its scene, pipeline, outcome and d; a click opens the scene file.")


def _hover_dot(x, y, r, tip, links):
    """One point of a hover chart: a circle coloured by the run's outcome, its tooltip naming the scene,
    wrapped in a link to the scene file when the report has one."""
    dot = (f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3.2" fill="{OUTCOME_COLOURS[r["outcome"]]}" '
           f'data-scene="{html.escape(r["scene"])}"><title>{html.escape(tip)}</title></circle>')
    if r["scene"] in links:
        dot = f'<a href="{html.escape(links[r["scene"]])}">{dot}</a>'
    return dot


def _hover_figure(panels, caption):
    """A hover chart's panels with the outcome legend and a caption (plain text, escaped by the caller)."""
    legend = " ".join(f'<span class="key"><span class="sw" style="background:{c}"></span>{o.replace("_", " ")}</span>'
                      for o, c in OUTCOME_COLOURS.items())
    return ('<figure class="hover"><div class="panels">' + "".join(panels) + "</div><figcaption>" + legend +
            "<br>" + caption + "</figcaption></figure>")


FM_COLOURS = {"separate": "#9ecae1", "touching": "#fdd835", "colliding": "#e53935", "undecided": "#9e9e9e",
              "error": "#212121"}


def failure_map_svg(out_dir, meta, links, pictures):
    """Inline SVG: the failure map's cells per pipeline; a cell names its perturbation and answers, and links to
    the picture of the map's scene (scenes/NAME.png; its scene file when there is no picture)."""
    path = os.path.join(out_dir, "failure_map.csv")
    if not os.path.exists(path):
        return ""
    with open(path, newline="", encoding="utf-8") as fh:
        cells = list(csv.DictReader(fh))
    if not cells:
        return ""
    fm = (meta or {}).get("failure_map") or {}
    scene = fm.get("scene", "")
    href = pictures.get(scene) or links.get(scene)
    nx = max(int(c["ix"]) for c in cells) + 1
    ny = max(int(c["iy"]) for c in cells) + 1
    size = max(6, min(18, 220 // max(nx, ny)))
    out = []
    for p in dict.fromkeys(c["pipeline"] for c in cells):
        W, H = nx * size + 2, ny * size + 22
        parts = [f'<svg class="fmap" viewBox="0 0 {W} {H}" width="{W}" height="{H}" role="img" '
                 f'aria-label="failure map of {html.escape(p)}"><text x="1" y="13" class="ttl">{html.escape(p)}</text>']
        for c in cells:
            if c["pipeline"] != p:
                continue
            ix, iy = int(c["ix"]), int(c["iy"])
            x, y = 1 + ix * size, 20 + (ny - 1 - iy) * size
            differs = c["answer"] != c["exact"]
            tip = (f'{p}: x {int(float(c["dx_ulps"])):+d} ulps, y {int(float(c["dy_ulps"])):+d} ulps: {c["answer"]}'
                   f' (exact: {c["exact"]})' + (" — differs" if differs else "") + (f"; scene {scene}" if scene else "")
                   + ("; a click opens its picture" if scene in pictures else ""))
            rect = (f'<rect x="{x}" y="{y}" width="{size - 1}" height="{size - 1}" '
                    f'fill="{FM_COLOURS.get(c["answer"], "#ffffff")}"' + (' class="differs"' if differs else "") +
                    f'><title>{html.escape(tip)}</title></rect>')
            out_rect = f'<a href="{html.escape(href)}">{rect}</a>' if href else rect
            parts.append(out_rect)
        parts.append("</svg>")
        out.append("".join(parts))
    legend = " ".join(f'<span class="key"><span class="sw" style="background:{c}"></span>{a}</span>'
                      for a, c in FM_COLOURS.items())
    return ('<figure class="hover"><div class="panels">' + "".join(out) + "</div><figcaption>" + legend +
            " (outlined: differs from exact). Hover a cell for its perturbation and answers"
            + ("; a click opens the picture of the map's scene (each cell is that scene with its two inputs moved by "
               "the cell's ulps)" if scene in pictures else "; a click opens the map's scene file" if href else "")
            + ".</figcaption></figure>")


def data_uri(out_dir, src):
    path = os.path.join(out_dir, os.path.basename(src))
    if not os.path.exists(path):
        return None
    with open(path, "rb") as fh:
        return "data:image/png;base64," + base64.b64encode(fh.read()).decode("ascii")


# --------------------------------------------------------------------------- the page

STYLE = """
body{font:15px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:0 auto;max-width:1200px;padding:0 18px 40px;color:#222}
h1{margin:18px 0 8px}h2{margin-top:34px;border-bottom:1px solid #ddd;padding-bottom:3px}
#verdict-section{background:#f5f8fc;border:1px solid #cfdcec;border-radius:6px;padding:4px 18px 10px;margin:10px 0 24px}
table{border-collapse:collapse;margin:6px 0 4px;font-size:13px}
th,td{border:1px solid #ddd;padding:3px 7px;vertical-align:top}
th{background:#f2f2f2;cursor:pointer;user-select:none;position:sticky;top:0}
th[aria-sort=ascending]::after{content:" ▲"}th[aria-sort=descending]::after{content:" ▼"}
td.num,th.num{text-align:right}tr:nth-child(even) td{background:#fafafa}
.tablewrap{overflow-x:auto;max-width:100%}
input.filter{margin:10px 0 2px;padding:3px 6px;width:280px;font-size:13px}
.count{color:#666;font-size:12px;margin-left:8px}
img{max-width:100%;height:auto}figure{margin:10px 0}
figcaption{font-size:13px;color:#444}
.panels{display:flex;flex-wrap:wrap;gap:10px}
svg text{font-size:11px;fill:#333}svg .ttl{font-size:12px;font-weight:600}
svg .frame{fill:none;stroke:#999}svg .grid{stroke:#eee}
svg circle:hover,svg rect:hover{stroke:#000;stroke-width:1.5}
svg rect.differs{stroke:#000;stroke-width:1}
.key{margin-right:12px;white-space:nowrap}.sw{display:inline-block;width:10px;height:10px;margin-right:4px;border:1px solid #888}
code{background:#f3f3f3;padding:0 3px;border-radius:3px}
nav.toc{font-size:13px;columns:2}
"""

SCRIPT = r"""
(function () {
  function cellValue(td) {
    var t = (td.getAttribute('data-sort') || td.textContent).trim();
    var m = t.match(/^[-+]?(\d+(\.\d*)?|\.\d+)([eE][-+]?\d+)?/);
    return m && m[0].length > 0 ? {n: parseFloat(m[0]), s: t} : {n: null, s: t.toLowerCase()};
  }
  function sortTable(table, col, desc) {
    var body = table.tBodies[0];
    var rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (a, b) {
      var x = cellValue(a.cells[col] || a.cells[0]), y = cellValue(b.cells[col] || b.cells[0]);
      var r;
      if (x.n !== null && y.n !== null) r = x.n - y.n;
      else if (x.n !== null) r = -1;
      else if (y.n !== null) r = 1;
      else r = 0;
      if (r === 0) {  // equal numbers ("2d-deg2-free", "2d-deg2-touch"): by the text
        var p = x.s.toLowerCase(), q = y.s.toLowerCase();
        r = p < q ? -1 : p > q ? 1 : 0;
      }
      return desc ? -r : r;
    });
    rows.forEach(function (r) { body.appendChild(r); });
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (th, k) {
      if (k === col) th.setAttribute('aria-sort', desc ? 'descending' : 'ascending');
      else th.removeAttribute('aria-sort');
    });
    table.setAttribute('data-sorted', col + (desc ? ':desc' : ':asc'));
  }
  function filterTable(table, text, counter) {
    var words = text.toLowerCase().split(/\s+/).filter(function (w) { return w.length > 0; });
    var shown = 0, rows = table.tBodies[0].rows;
    for (var i = 0; i < rows.length; i++) {
      var t = rows[i].textContent.toLowerCase();
      var ok = words.every(function (w) { return t.indexOf(w) >= 0; });
      rows[i].style.display = ok ? '' : 'none';
      if (ok) shown++;
    }
    counter.textContent = shown + ' of ' + rows.length + ' rows';
  }
  var tables = document.querySelectorAll('table.data');
  Array.prototype.forEach.call(tables, function (table, ti) {
    table.id = table.id || ('table-' + ti);
    Array.prototype.forEach.call(table.tHead.rows[0].cells, function (th, col) {
      th.title = 'Sort by this column (again: reverse)';
      th.addEventListener('click', function () {
        sortTable(table, col, th.getAttribute('aria-sort') === 'ascending');
      });
    });
    var box = document.createElement('input');
    box.type = 'search';
    box.className = 'filter';
    box.placeholder = 'Filter rows (words, all must match)';
    box.setAttribute('aria-label', 'Filter the rows of this table');
    var counter = document.createElement('span');
    counter.className = 'count';
    counter.textContent = table.tBodies[0].rows.length + ' rows';
    box.addEventListener('input', function () { filterTable(table, box.value, counter); });
    var wrap = table.parentNode;
    wrap.parentNode.insertBefore(box, wrap);
    wrap.parentNode.insertBefore(counter, wrap);
  });
  // #sort=T:C[:desc], T a table's number (from 0) or id; several joined by '&'
  location.hash.replace(/sort=([\w-]+):(\d+)(:desc)?/g, function (all, t, c, d) {
    var table = /^\d+$/.test(t) ? tables[+t] : document.getElementById(t);
    if (table) sortTable(table, +c, !!d);
    return all;
  });
  var f = location.hash.match(/filter=(\d+):([^&]*)/);
  if (f && tables[+f[1]]) {
    var inputs = document.querySelectorAll('input.filter');
    inputs[+f[1]].value = decodeURIComponent(f[2]);
    filterTable(tables[+f[1]], inputs[+f[1]].value, inputs[+f[1]].nextSibling);
  }
  document.body.setAttribute('data-ready', '1');
})();
"""

# First in <head>: counts script errors into <body data-js-errors> for the browser test.
ERROR_TRAP = r"""
window.__eccdErrors = 0;
window.addEventListener('error', function () { window.__eccdErrors++; mark(); });
function mark() { if (document.body) document.body.setAttribute('data-js-errors', String(window.__eccdErrors)); }
document.addEventListener('DOMContentLoaded', mark);
"""


def render_table(head, aligns, rows, raw=False, table_id=None):
    nums = [a == "right" for a in aligns] + [False] * max(0, len(head) - len(aligns))
    cell = (lambda c: c) if raw else inline
    out = [f'<div class="tablewrap"><table class="data"' + (f' id="{table_id}"' if table_id else "") + "><thead><tr>"]
    out += [f'<th class="num">{cell(h)}</th>' if nums[k] else f"<th>{cell(h)}</th>" for k, h in enumerate(head)]
    out.append("</tr></thead><tbody>")
    for r in rows:
        out.append("<tr>" + "".join(f'<td class="num">{cell(c)}</td>' if k < len(nums) and nums[k] else f"<td>{cell(c)}</td>"
                                    for k, c in enumerate(r)) + "</tr>")
    out.append("</tbody></table></div>")
    return "".join(out)


def build_page(out_dir):
    md_path = os.path.join(out_dir, "report.md")
    if not os.path.exists(md_path):
        raise InputError(f"{md_path}: missing (report_figures.py writes it first)")
    with open(md_path, encoding="utf-8") as fh:
        md = fh.read()
    rows = read_rows(os.path.join(out_dir, "results.csv"))
    meta = None
    if os.path.exists(os.path.join(out_dir, "meta.json")):
        with open(os.path.join(out_dir, "meta.json"), encoding="utf-8") as fh:
            meta = json.load(fh)
    links, pictures = scene_index(out_dir)
    blocks = verdict_first(markdown_blocks(md))
    title = next((b[2] for b in blocks if b[0] == "h" and b[1] == 1), "Robustness report")
    body, toc, section_open = [], [], False
    for b in blocks:
        kind = b[0]
        if kind == "h":
            level, text = b[1], b[2]
            sid = slug(text)
            if level <= 2 and section_open:
                body.append("</section>")
                section_open = False
            if level == 2:
                sec_id = "verdict-section" if sid == "verdict" else f"sec-{sid}"
                body.append(f'<section id="{sec_id}">')
                section_open = True
                toc.append(f'<a href="#{sid}">{inline(text)}</a>')
            body.append(f'<h{level} id="{sid}">{inline(text)}</h{level}>')
            if level == 2 and sid == "failure-map":
                body.append(failure_map_svg(out_dir, meta, links, pictures))
            if level == 2 and sid == "near-miss-scenes":
                body.append(near_miss_chart(rows, links))
            if level == 2 and sid == "time":
                body.append(time_chart(rows, links))
        elif kind == "p":
            body.append(f"<p>{inline(b[1])}</p>")
        elif kind == "ul":
            body.append("<ul>" + "".join(f"<li>{inline(it)}</li>" for it in b[1]) + "</ul>")
        elif kind == "table":
            body.append(render_table(b[1], b[2], b[3]))
        elif kind == "img":
            uri = data_uri(out_dir, b[2])
            if uri:
                body.append(f'<figure><img alt="{html.escape(b[1])}" src="{uri}"></figure>')
            else:
                body.append(f"<p><em>(figure {html.escape(b[2])} is missing from the report folder)</em></p>")
    if section_open:
        body.append("</section>")
    head, aligns, srows = scenes_table(rows, links)
    body.append('<section id="sec-scenes"><h2 id="scenes">Scenes</h2><p>One row per scene of results.csv: the exact '
                "answer and how many pipelines were confidently wrong, undecided or failed on it"
                + ("; the scene's name opens its file" if links else "") + ".</p>"
                + render_table(head, aligns, srows, raw=True, table_id="scenes-table") + "</section>")
    toc.append('<a href="#scenes">Scenes</a>')
    # the title first, then the contents, then the sections (the verdict first of them)
    first = body.index(next(x for x in body if x.startswith("<section")))
    page = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
            '<meta name="viewport" content="width=device-width, initial-scale=1">',
            f"<title>{html.escape(re.sub(r'[*`]', '', title))}</title>",
            f"<script>{ERROR_TRAP}</script>", f"<style>{STYLE}</style></head>",
            '<body data-js-errors="0">'] + body[:first] + \
           ['<nav class="toc">' + " · ".join(toc) + "</nav>"] + body[first:] + \
           [f"<script>{SCRIPT}</script>", "</body></html>"]
    return "\n".join(page) + "\n"


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 0 if len(argv) == 2 else 2
    out_dir = argv[1]
    if not os.path.isdir(out_dir):
        raise InputError(f"{out_dir}: not a directory")
    page = build_page(out_dir)
    fd, tmp = tempfile.mkstemp(prefix=".report_html-", suffix=".html", dir=out_dir)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(page)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)  # as an ordinary file (mkstemp makes it private)
        os.replace(tmp, os.path.join(out_dir, "report.html"))
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise
    print(f"{PROG}: wrote report.html in {out_dir}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except InputError as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        sys.exit(2)
