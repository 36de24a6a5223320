#!/usr/bin/env python3
"""CTest report_html_browser: report.html in a real browser (Debian's chromium, headless).

Usage: python3 tests/app/report_html_browser_test.py ECCD_EXE SOURCE_DIR

Runs a small `eccd report` into a temporary folder, then checks its report.html:
  - it loads no network resource: no src/href to http(s), no stylesheet link, no @import or url(http);
  - headless chromium loads it with no script error (the page counts them in <body data-js-errors>, and
    chromium's log has no "Uncaught" console line) and runs its script to the end (data-ready="1");
  - the verdict comes first and its numbers are report.md's, in the same order;
  - a table sorts: the URL hash #sort=T:C:desc sorts table T by column C, and the DOM chromium dumps has
    that column in descending order (the first table by a number column, the scenes table, written in
    ascending order of names, by its names);
  - each scene row links to a scene file that exists (relative to the report folder);
  - hover: every point of the time chart and of the near-miss chart carries a <title> that begins with its
    scene's name (a scene of results.csv); the failure map's cells carry a title naming the map's scene;
  - a failure-map cell links to the picture of the map's scene: a PNG file under the report folder;
  - --merge: the same report run as two shards and joined writes report.html too, whose scene links and
    failure-map link resolve inside the merged folder, and chromium loads it with no script error.
Exit 0 pass, 1 fail (each failure printed), 77 skipped (chromium missing: CTest SKIP_RETURN_CODE).
"""
import csv
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

FAILS = []


def check(ok, what, detail=""):
    print(("ok    " if ok else "FAIL  ") + what + (f" ({detail})" if detail and not ok else ""))
    if not ok:
        FAILS.append(what)


def chromium():
    for name in ("chromium", "chromium-browser"):
        p = shutil.which(name)
        if p:
            return p
    return None


def dump_dom(browser, url, workdir):
    r = subprocess.run([browser, "--headless", "--disable-gpu", "--no-sandbox", "--no-first-run",
                        "--user-data-dir=" + os.path.join(workdir, "profile"), "--enable-logging=stderr", "--v=0",
                        "--proxy-server=127.0.0.1:9", "--virtual-time-budget=5000", "--dump-dom", url],
                       capture_output=True, text=True, timeout=120)
    return r.returncode, r.stdout, r.stderr


def numbers(text):
    return re.findall(r"\d+(?:\.\d+)?(?:e[-+]?\d+)?", text)


def md_verdict_text(md):
    sec = re.search(r"^## Verdict\s*$(.*?)(?=^## )", md, flags=re.M | re.S)
    t = sec.group(1) if sec else ""
    t = re.sub(r"\[([^\]]+)\]\([^)]*\)", r"\1", t)  # links: their text only (targets are not shown)
    return t


def check_hover(page, scene_names, where):
    """Every point of the hoverable charts names a scene of results.csv, first thing in its title."""
    dots = re.findall(r'<circle[^>]*data-scene="([^"]+)"[^>]*><title>([^<]*)</title>', page)
    bare = len(re.findall(r"<circle", page)) - len(dots)
    bad = [(s, t) for s, t in dots if html.unescape(s) not in scene_names or not html.unescape(t).startswith(html.unescape(s) + " ")]
    check(dots and not bad and bare == 0,
          f"{where}: every chart point carries a title beginning with its scene's name ({len(dots)} points)",
          f"{bare} without a title; first bad: {bad[:1]}")


def check_map_links(page, out, where):
    """A failure-map cell links to the picture of the map's scene: a PNG under the report folder."""
    fmap = "".join(re.findall(r'<svg class="fmap".*?</svg>', page, flags=re.S))
    cells = len(re.findall(r"<rect", fmap))
    hrefs = set(re.findall(r'<a href="([^"]+)"><rect', fmap))
    check(cells > 0 and len(re.findall(r'<a href="[^"]+"><rect', fmap)) == cells,
          f"{where}: each failure-map cell is a link ({cells} cells)")
    for h in sorted(hrefs):
        path = os.path.join(out, html.unescape(h))
        inside = os.path.realpath(path).startswith(os.path.realpath(out) + os.sep)
        is_png = os.path.isfile(path) and open(path, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
        check(h.endswith(".png") and inside and is_png,
              f"{where}: a failure-map cell links to the map scene's picture, a PNG in the report folder ({h})")
    check(bool(hrefs), f"{where}: the failure map links somewhere")


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    exe, src = argv[1], argv[2]
    browser = chromium()
    if browser is None:
        print("SKIP: chromium is not installed (apt-get install chromium; scripts/bootstrap.sh installs it)")
        return 77
    work = tempfile.mkdtemp(prefix="eccd-html-")
    try:
        out = os.path.join(work, "r")
        cmd = [exe, "report", "--out-dir", out, "--dims", "2", "--degrees", "2", "--families", "touch,free,near-miss",
               "--separations", "2", "--count", "1", "--mpfr-bits", "64", "--cases", os.path.join(src, "cases", "spheres"),
               "--map-size", "2", "--no-fcl", "--budget", "2", "--jobs", "2", "--quiet"]
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
        check(r.returncode == 0, "eccd report exits 0", f"exit {r.returncode}; stderr: {r.stderr[-400:]}")
        page_path = os.path.join(out, "report.html")
        check(os.path.exists(page_path), "report.html is written beside report.md")
        if FAILS:
            return 1
        page = open(page_path, encoding="utf-8").read()
        md = open(os.path.join(out, "report.md"), encoding="utf-8").read()

        # no network
        check(not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:)?//""", page, flags=re.I),
              "no src or href points to the network")
        check("<link" not in page.lower() and "@import" not in page and not re.search(r"url\(\s*['\"]?https?:", page),
              "no stylesheet link, @import or url(http...)")
        check(all(s.startswith("data:") for s in re.findall(r'<img[^>]*\ssrc="([^"]*)"', page)),
              "every image is inline (a data: URI)")

        rc, dom, log = dump_dom(browser, "file://" + page_path + "#sort=0:2:desc&sort=scenes-table:0:desc", work)
        check(rc == 0 and "<body" in dom, f"chromium loads the page (exit {rc})")
        body = re.search(r"<body([^>]*)>", dom)
        attrs = body.group(1) if body else ""
        check('data-js-errors="0"' in attrs, f"no script error in the page ({attrs.strip()})")
        check('data-ready="1"' in attrs, "the page's script ran to its end")
        console = [l for l in log.splitlines() if "CONSOLE" in l and ("Uncaught" in l or "rror" in l)]
        check(not console, "no console error in chromium's log" + (": " + console[0][:300] if console else ""))
        check(not re.search(r"net::ERR_|Failed to load resource", log), "no resource failed to load (nothing is fetched)")

        # the verdict first, with report.md's numbers
        first_h2 = re.search(r"<h2[^>]*>(.*?)</h2>", dom, flags=re.S)
        check(first_h2 is not None and "Verdict" in first_h2.group(1), "the first section is the verdict")
        sec = re.search(r'<section id="verdict-section">(.*?)</section>', dom, flags=re.S)
        html_text = html.unescape(re.sub(r"<[^>]+>", " ", sec.group(1))) if sec else ""
        a, b = numbers(md_verdict_text(md)), numbers(html_text)
        first_diff = next((f"{x} vs {y}" for x, y in zip(a, b) if x != y), f"{len(a)} vs {len(b)} numbers")
        check(bool(a) and a == b, f"the verdict's numbers equal report.md's ({len(a)} numbers)", first_diff)

        # a table sorts
        t0 = re.search(r'<table class="data"[^>]*data-sorted="2:desc"[^>]*>(.*?)</table>', dom, flags=re.S)
        check(t0 is not None, "#sort=0:2:desc sorted the first table (data-sorted=\"2:desc\")")
        if t0:
            col = []
            for row in re.findall(r"<tr>(.*?)</tr>", t0.group(1).split("</thead>")[-1], flags=re.S):
                cells = re.findall(r"<td[^>]*>(.*?)</td>", row, flags=re.S)
                if len(cells) > 2:
                    m = re.match(r"\s*([-+]?\d+(?:\.\d+)?)", re.sub(r"<[^>]+>", "", cells[2]))
                    if m:
                        col.append(float(m.group(1)))
            check(len(col) >= 2 and col == sorted(col, reverse=True),
                  f"column 2 of the first table is in descending order ({col[:8]})")
            th = re.search(r"<thead>.*?</thead>", t0.group(1), flags=re.S)
            check(th is not None and 'aria-sort="descending"' in th.group(0), "the sorted column's header says so")

        st = re.search(r'<table class="data" id="scenes-table"[^>]*data-sorted="0:desc"[^>]*>(.*?)</table>', dom, flags=re.S)
        names = [html.unescape(re.sub(r"<[^>]+>", "", c)).strip() for c in
                 re.findall(r"<tr[^>]*>\s*<td[^>]*>(.*?)</td>", st.group(1))] if st else []
        check(len(set(names)) >= 2 and names == sorted(names, key=str.lower, reverse=True),
              f"the scenes table sorted by name, descending ({len(names)} rows; written ascending)")

        # scene rows link to scene files that exist
        scenes = re.search(r'<table class="data" id="scenes-table".*?</table>', page, flags=re.S)
        hrefs = re.findall(r'<a href="([^"]+)"', scenes.group(0)) if scenes else []
        rows = len(re.findall(r"<tr>", scenes.group(0))) - 1 if scenes else 0
        check(rows > 0 and len(hrefs) == rows, f"each scene row links to its scene file ({len(hrefs)} links, {rows} rows)")
        missing = [h for h in hrefs if not os.path.exists(os.path.join(out, html.unescape(h)))]
        check(not missing, "every scene link resolves to a file" + (f" (missing: {missing[:3]})" if missing else ""))
        # the scene files the report writes keep the scene format's key order (docs/scene-format.md), not sorted keys
        order = ["format", "name", "dim", "parameters", "a", "b", "note", "answer"]
        own = [h for h in hrefs if html.unescape(h).startswith("scenes/")]
        unordered = []
        for h in own:
            keys = [k for k in json.load(open(os.path.join(out, html.unescape(h)), encoding="utf-8")) if k in order]
            if keys != sorted(keys, key=order.index) or keys[:1] != ["format"]:
                unordered.append((h, keys))
        check(own and not unordered, f"the report's own scene files keep the scene format's key order ({len(own)} files)",
              f"first: {unordered[:1]}")

        # figures you can hover
        with open(os.path.join(out, "results.csv"), newline="", encoding="utf-8") as fh:
            scene_names = {r["scene"] for r in csv.DictReader(fh)}
        check_hover(page, scene_names, "the report")
        for label in ("time per query", "near-miss runs"):
            fig = re.search(r'<svg class="chart"[^>]*aria-label="[^"]*' + label + r'.*?</svg>', page, flags=re.S)
            n = len(re.findall(r"<circle", fig.group(0))) if fig else 0
            check(n > 0, f"the chart of {label} has points you can hover ({n})")
        check(re.search(r"<rect[^>]*><title>[^<]*scene [^<]+</title>", page) is not None,
              "the failure map's cells carry a title naming the map's scene")
        check_map_links(page, out, "the report")

        # --merge writes report.html too (the same small run as two shards, joined)
        parts = []
        for i in range(2):
            part = os.path.join(work, f"part{i}")
            r = subprocess.run(cmd[:3] + [part, "--shard", f"{i}/2"] + cmd[4:], capture_output=True, text=True, timeout=900)
            check(r.returncode == 0, f"eccd report --shard {i}/2 exits 0", f"exit {r.returncode}; stderr: {r.stderr[-400:]}")
            parts.append(part)
        merged = os.path.join(work, "merged")
        r = subprocess.run([exe, "report", "--out-dir", merged, "--merge"] + parts + ["--quiet"],
                           capture_output=True, text=True, timeout=900)
        check(r.returncode == 0, "eccd report --merge exits 0", f"exit {r.returncode}; stderr: {r.stderr[-400:]}")
        mpath = os.path.join(merged, "report.html")
        check(os.path.exists(mpath), "--merge writes report.html beside report.md")
        if os.path.exists(mpath):
            mpage = open(mpath, encoding="utf-8").read()
            scenes = re.search(r'<table class="data" id="scenes-table".*?</table>', mpage, flags=re.S)
            hrefs = re.findall(r'<a href="([^"]+)"', scenes.group(0)) if scenes else []
            rows = len(re.findall(r"<tr>", scenes.group(0))) - 1 if scenes else 0
            missing = [h for h in hrefs if not os.path.isfile(os.path.join(merged, html.unescape(h)))]
            check(rows > 0 and len(hrefs) == rows and not missing,
                  f"merged: each scene row links to a file that exists ({len(hrefs)} links, {rows} rows)",
                  f"missing: {missing[:3]}")
            check(rows == len(names), f"merged: as many scenes as the unsharded run ({rows} and {len(names)})")
            check_hover(mpage, scene_names, "merged")
            check_map_links(mpage, merged, "merged")
            rc, dom, log = dump_dom(browser, "file://" + mpath, work)
            body = re.search(r"<body([^>]*)>", dom)
            check(rc == 0 and body is not None and 'data-js-errors="0"' in body.group(1) and 'data-ready="1"' in body.group(1),
                  "merged: chromium loads report.html with no script error")
        return 1 if FAILS else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
