"""Univariate polynomials over the rationals, as lists of Fractions, lowest
coefficient first: arithmetic, exact division, gcd, Newton interpolation at
0, 1, 2, ..., and root counting: Descartes' rule of signs on an interval
(through a Moebius map onto (0, inf)) and Sturm sequences."""
import math
from fractions import Fraction as Q


def trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def ev(p, x):
    """p(x), in integers: sum c_i n^i d^(m-i) over (L d^m), x = n/d, L the common denominator of p."""
    if not p:
        return Q(0)
    x = Q(x)
    n, d, m = x.numerator, x.denominator, len(p) - 1
    l = 1
    for c in p:
        l = l * c.denominator // math.gcd(l, c.denominator)
    v, dk = 0, 1
    for c in reversed(p):  # Horner on the homogenised polynomial: v = v * n + c * L * d^k
        v = v * n + c.numerator * (l // c.denominator) * dk
        dk *= d
    return Q(v, l * dk // d)


def add(a, b):
    r = [Q(0)] * max(len(a), len(b))
    for i, c in enumerate(a):
        r[i] += c
    for i, c in enumerate(b):
        r[i] += c
    return trim(r)


def scale(k, a):
    return trim([k * c for c in a])


def mul(a, b):
    if not a or not b:
        return []
    r = [Q(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return trim(r)


def divmod_poly(a, b):
    r, q = trim(a), [Q(0)] * max(len(a) - len(b) + 1, 1)
    while r and len(r) >= len(b):
        s, k = len(r) - len(b), r[-1] / b[-1]
        q[s] = k
        for i, c in enumerate(b):
            r[i + s] -= k * c
        r = trim(r[:-1])
    return trim(q), r


def deriv(p):
    return trim([i * p[i] for i in range(1, len(p))])


def gcd(a, b):
    a, b = trim(a), trim(b)
    while b:
        a, b = b, divmod_poly(a, b)[1]
    return scale(1 / a[-1], a) if a else a


def interpolate(values):
    """The polynomial through (k, values[k]), k = 0, 1, ..., n - 1 (Newton's forward form, in integers):
    p(x) = sum_j Delta^j v(0) / j! * x (x - 1) ... (x - j + 1), over the common denominator L (n - 1)!."""
    n = len(values)
    if n == 0:
        return []
    l = 1
    for v in values:
        v = Q(v)
        l = l * v.denominator // math.gcd(l, v.denominator)
    d = [Q(v).numerator * (l // Q(v).denominator) for v in values]
    for j in range(1, n):  # forward differences: d[i] = Delta^i v(0) (times l), integers
        for i in range(n - 1, j - 1, -1):
            d[i] -= d[i - 1]
    fact = math.factorial(n - 1)
    acc, falling = [0] * n, [1]  # falling = x (x - 1) ... (x - j + 1), integer coefficients
    for j in range(n):
        w = d[j] * (fact // math.factorial(j))
        for i, c in enumerate(falling):
            acc[i] += w * c
        nxt = [0] * (len(falling) + 1)  # falling * (x - j)
        for i, c in enumerate(falling):
            nxt[i + 1] += c
            nxt[i] -= j * c
        falling = nxt
    return trim([Q(c, l * fact) for c in acc])


def variations(seq):
    v, last = 0, 0
    for x in seq:
        s = (x > 0) - (x < 0)
        if s:
            v += last != 0 and s != last
            last = s
    return v


def taylor_shift(a, s):
    a = list(a)
    for i in range(len(a) - 1):
        for j in range(len(a) - 2, i - 1, -1):
            a[j] += s * a[j + 1]
    return a


def descartes(p, lo, hi):
    """Sign variations of p on (lo, hi) mapped onto (0, inf): 0 = no root, 1 = one simple root."""
    p = trim(p)
    if len(p) <= 1:
        return 0
    n, w = len(p) - 1, hi - lo
    l = 1
    for c in p:
        l = l * c.denominator // math.gcd(l, c.denominator)
    D, A, B = lo.denominator * w.denominator, lo.numerator * w.denominator, w.numerator * lo.denominator
    a = [int(p[i] * l) * D ** (n - i) for i in range(n + 1)]
    a = taylor_shift(a, A)
    a = [x * B ** i for i, x in enumerate(a)]
    return variations(taylor_shift(list(reversed(a)), 1))


def sturm(p):
    seq = [trim(p), deriv(p)]
    while seq[-1]:
        r = divmod_poly(seq[-2], seq[-1])[1]
        if not r:
            break
        seq.append(scale(Q(-1), r))
    return seq


def negative_roots(p):
    """Distinct real roots in (-inf, 0) (p(0) != 0)."""
    if len(trim(p)) <= 1:
        return 0
    seq = sturm(p)
    return variations([q[-1] * (1 if (len(q) - 1) % 2 == 0 else -1) for q in seq]) - variations([q[0] for q in seq])


def roots_between(p, a, b):
    seq = sturm(p)
    return variations([ev(q, a) for q in seq]) - variations([ev(q, b) for q in seq])
