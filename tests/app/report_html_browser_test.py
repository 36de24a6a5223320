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
  - hover: the time chart's points and the failure map's cells carry a <title> naming their scene.
Exit 0 pass, 1 fail (each failure printed), 77 skipped (chromium missing: CTest SKIP_RETURN_CODE).
"""
import html
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

        # figures you can hover
        check(re.search(r"<circle[^>]*data-scene=\"[^\"]+\"[^>]*><title>[^<]+</title>", page) is not None,
              "the time chart's points carry a title naming their scene")
        check(re.search(r"<rect[^>]*><title>[^<]*scene [^<]+</title>", page) is not None,
              "the failure map's cells carry a title naming the map's scene")
        return 1 if FAILS else 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
