"""Square matrices of rationals and of polynomials: determinant (Gaussian
elimination), evaluation at t, the primitive adjugate N of a motion matrix M
(adj M over the gcd of its entries), the moving quadric N^T Q N, the pencil
det(lambda A - B), the subresultant coefficients s(j, i) of (f, f') and the
discriminant of a cubic."""
from fractions import Fraction as Q

from .polynomials import divmod_poly, ev, gcd, interpolate, scale


def det(m):
    m = [list(r) for r in m]
    n, d = len(m), Q(1)
    for c in range(n):
        p = next((r for r in range(c, n) if m[r][c] != 0), None)
        if p is None:
            return Q(0)
        if p != c:
            m[p], m[c], d = m[c], m[p], -d
        d *= m[c][c]
        for r in range(c + 1, n):
            if m[r][c]:
                k = m[r][c] / m[c][c]
                for j in range(c, n):
                    m[r][j] -= k * m[c][j]
    return d


def at_point(M, t):
    return [[ev(e, t) for e in row] for row in M]


def mdeg(M):
    return max(len(e) - 1 for row in M for e in row)


def primitive_inverse(M):
    """adj(M) over the gcd of its entries, by values at integers."""
    H = len(M)
    D = (H - 1) * max(mdeg(M), 0)
    vals = [[[] for _ in range(H)] for _ in range(H)]
    for k in range(D + 1):
        m = at_point(M, Q(k))
        for i in range(H):
            for j in range(H):
                minor = [[m[r][c] for c in range(H) if c != i] for r in range(H) if r != j]
                vals[i][j].append((-1) ** (i + j) * det(minor))
    N = [[interpolate(vals[i][j]) for j in range(H)] for i in range(H)]
    g = []
    for row in N:
        for e in row:
            if e:
                g = gcd(g, e) if g else scale(1 / e[-1], e)
    if len(g) > 1:
        N = [[divmod_poly(e, g)[0] for e in row] for row in N]
    return N


def moving_quadric(Q_, N, t):
    n, H = at_point(N, t), len(Q_)
    qn = [[sum(Q_[i][k] * n[k][j] for k in range(H)) for j in range(H)] for i in range(H)]
    return [[sum(n[k][i] * qn[k][j] for k in range(H)) for j in range(H)] for i in range(H)]


def pencil(A, B):
    H = len(A)
    v = [det([[l * A[i][j] - B[i][j] for j in range(H)] for i in range(H)]) for l in range(H + 1)]
    c = interpolate(v)
    return c + [Q(0)] * (H + 1 - len(c))


def subresultant(c, j, i):
    """s(j, i) of S_j(f, f') for f with coefficients c (lowest first), deg f = n."""
    n = len(c) - 1
    m, d = n - 1, [k * c[k] for k in range(1, n + 1)]
    rows, top = n + m - 2 * j, n + m - j - 1
    sq = []
    for r in range(rows):
        is_f = r < m - j
        p = c if is_f else d
        shift = (m - j - 1 - r) if is_f else (n - j - 1 - (r - (m - j)))
        coeff = lambda power: p[power - shift] if 0 <= power - shift < len(p) else Q(0)
        sq.append([coeff(top - col) for col in range(rows - 1)] + [coeff(i)])
    return det(sq)


def cubic_disc(g):
    a, b, c, d = g[3], g[2], g[1], g[0]
    return 18 * a * b * c * d - 4 * b ** 3 * d + b * b * c * c - 4 * a * c ** 3 - 27 * a * a * d * d
