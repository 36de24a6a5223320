"""The command line: SCENE CERT checks one certificate (exit 0 VALID,
1 REJECTED with the claim and why, 2 unreadable input or a format not
covered); --index FILE checks every eccd-certificate/2 an index.json of
`eccd regress --certify --keep-certificates DIR` lists."""
import json
import os
import sys
import time

from .check import check
from .errors import Rejected, Unreadable, reject
from .inputs import load_strict


def check_index(index_path):
    """--index FILE: every eccd-certificate/2 listed in an index.json of `eccd regress --certify --keep-certificates DIR`."""
    try:
        with open(index_path, encoding="utf-8") as f:
            entries = json.load(f)["certificates"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"check_certificate.py: {index_path}: not an index of certificates: {e}", file=sys.stderr)
        return 2
    base, bad, done, t0 = os.path.dirname(index_path), 0, 0, time.process_time()
    for e in entries:
        if e.get("format") != "eccd-certificate/2":
            continue
        done += 1
        code = main(["check_certificate.py", e["scene"], os.path.join(base, e["certificate"])], quiet=True)
        if code != 0:
            bad += 1
            print(f"NOT VALID ({code}): {e['certificate']}")
    print(f"check_certificate.py: {done - bad} of {done} eccd-certificate/2 certificate(s) VALID ({time.process_time() - t0:.1f} s CPU)")
    return 0 if bad == 0 and done > 0 else 1


def main(argv, quiet=False):
    if len(argv) == 3 and argv[1] == "--index":
        return check_index(argv[2])
    if len(argv) != 3:
        print("usage: check_certificate.py SCENE CERT  |  check_certificate.py --index DIR/index.json", file=sys.stderr)
        return 2
    dups = []
    try:
        scene = load_strict(argv[1], lambda k: dups.append(("scene", k)))
        if dups:
            raise Unreadable(f"{argv[1]}: duplicate key \"{dups[0][1]}\"")
        cert = load_strict(argv[2], lambda k: dups.append(("cert", k)))
        if isinstance(cert, dict) and cert.get("format") not in ("eccd-certificate/2", "eccd-certificate/1") and not dups:
            raise Unreadable(f"{argv[2]}: format {json.dumps(cert.get('format'))[:40]} is not covered (this checker covers eccd-certificate/2)")
    except Unreadable as e:
        print(f"check_certificate.py: {e}", file=sys.stderr)
        return 2
    try:
        if dups:
            reject("certificate format", f"duplicate key \"{dups[0][1]}\"")
        claims = check(scene, cert, argv[1])
    except Unreadable as e:
        print(f"check_certificate.py: {e}", file=sys.stderr)
        return 2
    except Rejected as r:
        print(f"REJECTED: {r.claim}: {r.reason}" + (f" ({argv[2]})" if quiet else ""))
        return 1
    except (ZeroDivisionError, TypeError, ValueError, KeyError, IndexError, AttributeError) as e:
        print(f"REJECTED: certificate format: the certificate cannot be checked: {type(e).__name__}: {e}")
        return 1
    if not quiet:
        print("ok  " + ", ".join(claims))
        print("VALID")
    return 0
