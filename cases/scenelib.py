"""Shared helpers of the case generators (make_*.py): exact number strings
as the scene format writes them, scene files with one polynomial per line,
and the small exact checker some generators run on their own scenes
(f(λ) by interpolation, Sturm count of its negative roots). Standard library only."""
import json
import os
import re
from fractions import Fraction as F


def num(q):
    """Exact string of a rational: a decimal if the denominator is 2^i 5^j, else p/q."""
    q = F(q)
    if q.denominator == 1:
        return str(q.numerator)
    d = q.denominator
    for p in (2, 5):
        while d % p == 0:
            d //= p
    if d != 1:
        return f"{q.numerator}/{q.denominator}"
    k = 0
    while (q * 10**k).denominator != 1:
        k += 1
    n = q * 10**k
    s = str(abs(n.numerator)).rjust(k + 1, "0")
    return ("-" if q < 0 else "") + s[:-k] + "." + s[-k:]


def write(s, folder):
    """Writes scene s as FOLDER/<name>.json, each polynomial (array of strings) on one line."""
    text = json.dumps(s, indent=1)
    text = re.sub(r"\[\s*((?:\"[^\"]*\",\s*)*\"[^\"]*\")\s*\]",
                  lambda m: "[" + re.sub(r",\s*", ", ", m.group(1)) + "]", text)
    with open(os.path.join(folder, s["name"] + ".json"), "w") as f:
        f.write(text + "\n")


def pev(p, t):
    r = F(0)
    for c in reversed(p):
        r = r * t + c
    return r


def det(m):
    m = [r[:] for r in m]
    n, d = len(m), F(1)
    for i in range(n):
        p = next((r for r in range(i, n) if m[r][i] != 0), None)
        if p is None:
            return F(0)
        if p != i:
            m[i], m[p], d = m[p], m[i], -d
        d *= m[i][i]
        for r in range(i + 1, n):
            f = m[r][i] / m[i][i]
            for c in range(i, n):
                m[r][c] -= f * m[i][c]
    return d


def prem(a, b):
    a = a[:]
    while len(a) >= len(b):
        c, s = a[-1] / b[-1], len(a) - len(b)
        for i, bc in enumerate(b):
            a[s + i] -= c * bc
        a.pop()
    while a and a[-1] == 0:
        a.pop()
    return a


def negative_roots(p):
    """Number of distinct real roots of p in (-inf, 0) (Sturm); p(0) != 0."""
    seq = [p, [i * p[i] for i in range(1, len(p))]]
    while True:
        r = prem(seq[-2], seq[-1])
        if not r:
            break
        seq.append([-x for x in r])

    def changes(v):
        v = [x for x in v if x != 0]
        return sum((a > 0) != (b > 0) for a, b in zip(v, v[1:]))
    return changes([q[-1] * (-1) ** (len(q) - 1) for q in seq]) - changes([q[0] for q in seq])


def charpoly(A, B):
    """Power coefficients of det(lambda A - B) for 4x4 A, B, by exact interpolation at lambda = 0..4."""
    ys = [det([[x * A[i][j] - B[i][j] for j in range(4)] for i in range(4)]) for x in range(5)]
    coef = [F(0)] * 5
    for i in range(5):
        basis, den = [F(1)], F(1)
        for j in range(5):
            if j != i:
                basis = [F(0)] + basis
                for k in range(len(basis) - 1):
                    basis[k] -= j * basis[k + 1]
                den *= i - j
        for k in range(5):
            coef[k] += ys[i] * basis[k] / den
    return coef
