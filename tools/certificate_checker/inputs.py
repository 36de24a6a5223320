"""Reading the inputs strictly: JSON with duplicate keys refused and no float
taken as a number, the scene's exact numbers, the certificate's bounded
rationals "p/q", whole numbers, required keys, and decimal approximations that
must lie in their brackets. Every malformed value is a Rejected "certificate
format" (or Unreadable for the scene file)."""
import json
from fractions import Fraction as Q

from .errors import Unreadable, reject


def load_strict(path, duplicate):
    """JSON with duplicate keys refused and no float accepted as a number."""
    def pairs(kv):
        d = {}
        for k, v in kv:
            if k in d:
                duplicate(k)
            d[k] = v
        return d
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise Unreadable(f"{path}: cannot be read: {e.strerror}")
    try:
        return json.loads(text, object_pairs_hook=pairs, parse_float=lambda s: "json-float:" + s)
    except json.JSONDecodeError as e:
        raise Unreadable(f"{path}: not valid JSON: line {e.lineno}, column {e.colno}: {e.msg}")


def scene_number(x, place):
    if isinstance(x, bool):
        raise Unreadable(f"scene: {place}: expected an exact number")
    if isinstance(x, int):
        return Q(x)
    if isinstance(x, str) and not x.startswith("json-float:"):
        s = x
        try:
            if "/" in s:
                n, d = s.split("/")
                if not n.lstrip("+-").isdigit() or not d.isdigit() or int(d) == 0:
                    raise ValueError
                return Q(int(n), int(d))
            mant, _, exp = s.lower().partition("e")
            if exp and (not exp.lstrip("+-").isdigit() or abs(int(exp)) > 10000):
                raise ValueError
            body = mant.lstrip("+-")
            if body.count(".") > 1 or not body.replace(".", "").isdigit():
                raise ValueError
            return Q(mant) * Q(10) ** int(exp or 0)
        except (ValueError, ZeroDivisionError):
            pass
    raise Unreadable(f"scene: {place}: expected an exact number, got {json.dumps(x)[:40]}")


def rational(x, place, max_bits):
    if not isinstance(x, str) or len(x) > 2 * (max_bits * 30103 // 100000 + 2) + 2:
        reject("certificate format", f"{place}: expected a rational \"p/q\" of at most {max_bits} bits, got {json.dumps(x)[:40]}")
    n, _, d = x.partition("/")
    body = n[1:] if n.startswith("-") else n
    if not body.isdigit() or (d and not d.isdigit()) or (d == "" and "/" in x):
        reject("certificate format", f"{place}: expected a rational \"p/q\", got {json.dumps(x)[:40]}")
    if d and int(d) == 0:
        reject("certificate format", f"{place}: zero denominator")
    q = Q(int(n), int(d) if d else 1)
    if q.numerator.bit_length() > max_bits or q.denominator.bit_length() > max_bits:
        reject("certificate format", f"{place}: a rational of more than {max_bits} bits")
    return q


def whole(x, place, lo, hi):
    if isinstance(x, bool) or not isinstance(x, int) or not lo <= x <= hi:
        reject("certificate format", f"{place}: expected a whole number from {lo} to {hi}, got {json.dumps(x)[:40]}")
    return x


def at(obj, key, place):
    if not isinstance(obj, dict):
        reject("certificate format", f"{place}: expected an object")
    if key not in obj:
        reject("certificate format", f"{place}: missing key \"{key}\"")
    return obj[key]


def check_approx(a, lo, hi, claim, place, max_chars):
    if not isinstance(a, str) or not 0 < len(a) <= max_chars:
        reject(claim, f"{place}: approx must be a decimal string")
    mant, _, exp = a.lower().partition("e")
    body = mant.lstrip("+-")
    if (body.count(".") > 1 or not body.replace(".", "").isdigit() or len(mant) - len(body) > 1
            or (exp and (not exp.lstrip("+-").isdigit() or abs(int(exp)) > 100000))):
        reject(claim, f"{place}: approx must be a decimal string, got {json.dumps(a)[:40]}")
    places = len(body.partition(".")[2])
    v = Q(mant) * Q(10) ** int(exp or 0)
    unit = Q(10) ** (int(exp or 0) - places)
    if not (abs(v - lo) * 2 <= unit if lo == hi else lo <= v <= hi):
        reject(claim, f"{place}: approx {a} lies outside its bracket")
