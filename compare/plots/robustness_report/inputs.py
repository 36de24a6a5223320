"""Reading and checking results.csv, meta.json and failure_map.csv (InputError names file, line and column)."""

import csv
import json
import math
import os

from .common import InputError, META_KEYS, NO_TRUTH


def _convert(text, kind, where):
    if kind == "str":
        return text
    if kind == "int":
        try:
            return int(text)
        except ValueError:
            raise InputError(f"{where}: '{text}' is not an integer") from None
    try:
        v = float(text)
    except ValueError:
        raise InputError(f"{where}: '{text}' is not a number") from None
    return v


def read_csv(path, columns, optional=()):
    """Rows of a CSV file (RFC 4180 quoting, as compare/csv.hpp writes it; read with the `csv` module), converted
    per `columns`.

    `optional`: (column, kind, empty allowed, choices, default) of columns that may be absent from the header (every
    row then gets the default). Each row is a dict (plus '_line', its line number in the file)."""
    name = os.path.basename(path)
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    records = []  # (line the record starts on, fields)
    start = 1
    try:
        with open(path, encoding="utf-8", newline="") as fh:
            reader = csv.reader(fh, strict=True)
            for rec in reader:
                records.append((start, rec))
                start = reader.line_num + 1
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: cannot be read ({e})") from None
    except csv.Error as e:
        raise InputError(f"{name} line {start}: malformed CSV, a quoted field that is not closed or a stray quote "
                         f"({e})") from None
    if not records or not "".join(records[0][1]).strip():
        raise InputError(f"{name} line 1: empty, expected the header row")
    header = [h.strip() for h in records[0][1]]
    index = {}
    for i, h in enumerate(header):
        if h in index:
            raise InputError(f"{name} line 1, column {i + 1}: column '{h}' appears twice in the header")
        index[h] = i
    for col, *_ in columns:
        if col not in index:
            raise InputError(f"{name} line 1: the header lacks column '{col}'")
    present_optional = [o[:4] for o in optional if o[0] in index]
    absent_optional = [(o[0], o[4]) for o in optional if o[0] not in index]
    columns = list(columns) + present_optional
    rows = []
    for ln, fields in records[1:]:
        if not "".join(fields).strip():
            continue
        if len(fields) != len(header):
            raise InputError(f"{name} line {ln}: {len(fields)} fields, the header has {len(header)}")
        raw = {h: fields[i].strip() for h, i in index.items()}
        row = {"_line": ln}
        for col, kind, empty_ok, choices in columns:
            text = raw[col]
            where = f"{name} line {ln}, column '{col}' (column {index[col] + 1})"
            if text == "":
                if (empty_ok is True or (empty_ok == "error" and raw["outcome"] == "error") or raw["outcome"] == NO_TRUTH
                        or (empty_ok == "nodecision" and raw["outcome"] in ("error", "undecided"))):
                    row[col] = None
                    continue
                raise InputError(f"{where}: empty, a value is required")
            v = _convert(text, kind, where)
            if kind == "float" and math.isnan(v):
                v = None  # "nan": not measured
            if choices is not None and v not in choices:
                raise InputError(f"{where}: '{text}' is not one of {', '.join(map(str, choices))}")
            row[col] = v
            if col == "d" and v is not None:
                row["d_text"] = text
        for col, default in absent_optional:
            row[col] = default
        rows.append(row)
    return rows


def check_results(rows):
    """Contract checks that the aggregates rely on. Returns pipeline -> (arith, bits, basis, method)."""
    if not rows:
        raise InputError("results.csv: no data rows after the header")
    seen = {}
    scene_attr = {}
    pinfo = {}
    for r in rows:
        ln = r["_line"]
        key = (r["scene"], r["pipeline"])
        if key in seen:
            raise InputError(f"results.csv line {ln}, column 'pipeline': a second row for scene '{r['scene']}' and "
                             f"pipeline '{r['pipeline']}' (the first is on line {seen[key]})")
        seen[key] = ln
        attrs = (r["dim"], r["degree"], r["family"], r["d"])
        if r["scene"] in scene_attr and scene_attr[r["scene"]][0] != attrs:
            first_attrs, first_ln = scene_attr[r["scene"]]
            for col, a, b in zip(("dim", "degree", "family", "d"), attrs, first_attrs):
                if a != b:
                    raise InputError(f"results.csv line {ln}, column '{col}': scene '{r['scene']}' has {col} {a} here "
                                     f"but {b} on line {first_ln}")
        scene_attr.setdefault(r["scene"], (attrs, ln))
        if r["family"] == "near-miss" and r["d"] is None:
            raise InputError(f"results.csv line {ln}, column 'd': empty, a near-miss scene needs its separation d")
        # exact's method is cd-disc in 2D and the projection in 3D
        info = (r["arith"], r["bits"], r["basis"], r["method"] if r["pipeline"] != "exact" else "exact")
        if r["pipeline"] in pinfo and pinfo[r["pipeline"]][0] != info:
            raise InputError(f"results.csv line {ln}, column 'pipeline': '{r['pipeline']}' has arith/bits/basis/method "
                             f"{'/'.join(map(str, info))} here but {'/'.join(map(str, pinfo[r['pipeline']][0]))} "
                             f"on line {pinfo[r['pipeline']][1]}")
        pinfo.setdefault(r["pipeline"], (info, ln))
        o, c, e = r["outcome"], r["collides"], r["exact_collides"]
        expect = {"correct": (c == e), "false_positive": (c == 1 and e == 0), "false_negative": (c == 0 and e == 1)}
        if o in expect and not expect[o]:
            raise InputError(f"results.csv line {ln}, column 'outcome': '{o}' contradicts collides={c}, "
                             f"exact_collides={e}")
    return {p: v[0] for p, v in pinfo.items()}


def read_meta(path):
    if not os.path.isfile(path):
        raise InputError(f"{path}: not found")
    try:
        with open(path, encoding="utf-8") as fh:
            meta = json.load(fh)
    except json.JSONDecodeError as e:
        raise InputError(f"meta.json line {e.lineno}, column {e.colno}: {e.msg}") from None
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: cannot be read ({e})") from None
    if not isinstance(meta, dict):
        raise InputError("meta.json line 1: the top level must be a JSON object")
    for k in META_KEYS:
        if k not in meta:
            raise InputError(f"meta.json: missing key '{k}'")
    for k in ("mpfr_bits", "degrees", "families", "pipelines"):
        if not isinstance(meta[k], list):
            raise InputError(f"meta.json: key '{k}' must be a list")
    if not all(isinstance(b, int) and not isinstance(b, bool) for b in meta["mpfr_bits"]):
        raise InputError("meta.json: key 'mpfr_bits' must be a list of integers")
    if not isinstance(meta["machine"], dict):
        raise InputError("meta.json: key 'machine' must be an object with cpu, cores, os")
    if meta["failure_map"] is not None and not isinstance(meta["failure_map"], dict):
        raise InputError("meta.json: key 'failure_map' must be an object or null")
    return meta


def check_failure_map(rows):
    if not rows:
        raise InputError("failure_map.csv: no data rows after the header")
    seen = {}
    exact_at = {}
    ulps_x, ulps_y = {}, {}
    for r in rows:
        ln = r["_line"]
        for col in ("ix", "iy"):
            if r[col] < 0:
                raise InputError(f"failure_map.csv line {ln}, column '{col}': {r[col]} is negative")
        key = (r["pipeline"], r["ix"], r["iy"])
        if key in seen:
            raise InputError(f"failure_map.csv line {ln}, column 'iy': a second row for pipeline '{r['pipeline']}' "
                             f"cell ({r['ix']}, {r['iy']}) (the first is on line {seen[key]})")
        seen[key] = ln
        cell = (r["ix"], r["iy"])
        if cell in exact_at and exact_at[cell][0] != r["exact"]:
            raise InputError(f"failure_map.csv line {ln}, column 'exact': cell ({r['ix']}, {r['iy']}) is "
                             f"'{r['exact']}' here but '{exact_at[cell][0]}' on line {exact_at[cell][1]}")
        exact_at.setdefault(cell, (r["exact"], ln))
        for idx, col, table in (("ix", "dx_ulps", ulps_x), ("iy", "dy_ulps", ulps_y)):
            i = r[idx]
            if i in table and table[i][0] != r[col]:
                raise InputError(f"failure_map.csv line {ln}, column '{col}': {idx}={i} has {col} {r[col]:g} here "
                                 f"but {table[i][0]:g} on line {table[i][1]}")
            table.setdefault(i, (r[col], ln))
    return {k: v[0] for k, v in exact_at.items()}, {k: v[0] for k, v in ulps_x.items()}, \
        {k: v[0] for k, v in ulps_y.items()}


# --------------------------------------------------------------------------- formatting
