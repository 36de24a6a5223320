"""Formatting of times and ratios, subprocesses, the machine's description, perf profiles, answer text."""

import os
import platform
import re
import shutil
import subprocess


ALLOC_SYMBOLS = re.compile(r"^(malloc|free|cfree(@.*)?|_int_malloc|_int_free|_int_realloc|realloc|calloc|"
                           r"malloc_consolidate|unlink_chunk.*|operator new.*|operator delete.*|tcache.*)$")


def fmt_time(ns):
    if ns is None:
        return "–"
    if ns < 1e3:
        return f"{ns:.1f} ns"
    if ns < 1e6:
        return f"{ns / 1e3:.2f} µs" if ns < 1e5 else f"{ns / 1e3:.1f} µs"
    if ns < 1e9:
        return f"{ns / 1e6:.3f} ms" if ns < 1e7 else f"{ns / 1e6:.1f} ms"
    return f"{ns / 1e9:.2f} s"


def fmt_ratio(r):
    if r is None:
        return "–"
    if r >= 100:
        return f"×{r:.0f}"
    if r >= 10:
        return f"×{r:.1f}"
    return f"×{r:.3g}"


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def read(path, default=""):
    try:
        with open(path) as f:
            return f.read()
    except OSError:
        return default


def machine_info(root, build_dir):
    info = {}
    cpuinfo = read("/proc/cpuinfo")
    m = re.search(r"^model name\s*:\s*(.+)$", cpuinfo, re.M)
    info["cpu"] = m.group(1).strip() if m else platform.processor() or "unknown"
    m = re.search(r"^cpu MHz\s*:\s*(.+)$", cpuinfo, re.M)
    info["mhz"] = m.group(1).strip() if m else "unknown"
    info["cores"] = os.cpu_count()
    lscpu = run(["lscpu"]).stdout if shutil.which("lscpu") else ""
    for field in ("Thread(s) per core", "Hypervisor vendor", "L2 cache", "L3 cache"):
        m = re.search(r"^" + re.escape(field) + r":\s*(.+)$", lscpu, re.M)
        if m:
            info[field] = m.group(1).strip()
    m = re.search(r"^MemTotal:\s*(\d+) kB", read("/proc/meminfo"), re.M)
    info["memory"] = f"{int(m.group(1)) / 1024 / 1024:.1f} GiB" if m else "unknown"
    osr = read("/etc/os-release")
    m = re.search(r'^PRETTY_NAME="?([^"\n]+)', osr, re.M)
    info["os"] = (m.group(1) if m else platform.system()) + ", kernel " + platform.release()
    rev = run(["git", "-C", root, "rev-parse", "--short=12", "HEAD"]).stdout.strip()
    dirty = run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"]).stdout.strip()
    info["git"] = (rev or "unknown") + (" with uncommitted changes in the working tree" if dirty else "")
    cache = read(os.path.join(build_dir, "CMakeCache.txt"))
    m = re.search(r"^CMAKE_CXX_FLAGS_RELEASE:STRING=(.*)$", cache, re.M)
    info["release_flags"] = m.group(1) if m else ""
    for pkg in ("libcgal-dev", "libbenchmark-dev", "libmps-dev", "libgmp-dev", "libmpfr-dev", "libmpfi-dev", "libflint-dev"):
        v = run(["dpkg-query", "-W", "-f=${Version}", pkg]).stdout.strip() if shutil.which("dpkg-query") else ""
        info["pkg " + pkg] = v or "?"
    return info


def loadavg():
    return " ".join(read("/proc/loadavg").split()[:3])


def perf_works():
    if not shutil.which("perf"):
        return False, "perf is not installed"
    r = run(["perf", "stat", "-e", "task-clock", "true"])
    if r.returncode != 0:
        return False, "perf does not run here: " + (r.stderr.strip().splitlines() or ["?"])[-1]
    return True, ""


def ere_escape(text):
    """A literal for Google Benchmark's filter (std::regex, POSIX extended)."""
    return "".join("\\" + c if c in ".^$*+?()[]{}|\\" else c for c in text)


def perf_profile(bench, key, work, seconds):
    """Flat profile of one row: top symbols and shared objects."""
    regex = "^" + ere_escape(key) + "(/|$)"
    data = os.path.join(work, "perf-" + re.sub(r"[^A-Za-z0-9]+", "_", key) + ".data")
    rec = run(["perf", "record", "-F", "2999", "-o", data, "--", bench, "--benchmark_filter=" + regex,
               f"--eccd_profile_seconds={seconds}"])
    if rec.returncode != 0:
        return None, "perf record failed: " + rec.stderr.strip()[-300:]
    out = {}
    for sort in ("symbol", "dso"):
        rep = run(["perf", "report", "-i", data, "--stdio", "--no-children", "--sort", sort, "--percent-limit", "1"])
        rows = []
        for line in rep.stdout.splitlines():
            m = re.match(r"\s*([\d.]+)%\s+(.*)$", line)
            if not m:
                continue
            name = m.group(2).strip()
            name = re.sub(r"^\[[.k]\]\s*", "", name)
            name = re.sub(r"\s+-\s+-\s*$", "", name).strip()
            if len(name) > 110:
                name = name[:107] + "..."
            rows.append((float(m.group(1)), name))
        out[sort] = rows[:14]
    try:
        os.remove(data)
    except OSError:
        pass
    return out, ""


def md_escape(s):
    return str(s).replace("|", "\\|")


def answer_text(res):
    if not isinstance(res, dict):
        return ""
    if "time_ms_inside" in res:
        t = "collides" if res["collides"] else "no collision"
        if "contacts" in res:  # the certified-cost set's rows count intervals only
            t += f", {res['contacts']} contact(s)"
        t += f", {res['intervals']} interval(s)"
        if res.get("decided_in"):
            t += f"; decided in {res['decided_in']} arithmetic"
            if res.get("escalated"):
                t += " (escalated: " + str(res.get("escalation_reason", "?"))[:120] + ")"
        return t
    if "collides" in res and "intervals" in res:
        parts = ["collides" if res["collides"] else "no collision"]
        if res.get("interval_list"):
            parts.append("intervals " + ", ".join("[" + x.replace("..", ", ") + "]" for x in res["interval_list"]))
        if res.get("contacts"):
            parts.append(f"{res['contacts']} contact(s)")
        if res.get("undecided"):
            parts.append(f"{res['undecided']} undecided")
        if res.get("work"):
            w = res["work"]
            keys = [k for k in ("shots", "shot_iterations", "subdivisions", "gauss_tests", "overlap_certificates") if k in w]
            if keys:
                parts.append("work: " + ", ".join(f"{k} {w[k]}" for k in keys))
        return "; ".join(parts)
    if "in_unit" in res:
        s = f"{res['in_unit']} root(s) in [0, 1]"
        if "roots" in res:
            s += f" of {res['roots']} " + ("discs" if res["roots"] == res.get("degree") and res["roots"] > 10 else "real roots")
        return s
    if "roots" in res:
        return f"{res['roots']} root(s)"
    if "built" in res:
        return "built: " + ", ".join(res["built"]) + f" ({res['interior_roots']} interior roots)"
    if "sign_evaluations" in res:
        return f"{res['sign_evaluations']} exact signs"
    if "static_tests" in res:
        return f"{res['static_tests']} exact static tests"
    if "degree" in res and len(res) == 1:
        return f"degree {res['degree']}"
    if "degree_t" in res:
        return f"F of degree {res['degree_t']} in t"
    if all(isinstance(v, int) for v in res.values()):
        return ", ".join(f"{v} {k}" for k, v in res.items())
    return ""
