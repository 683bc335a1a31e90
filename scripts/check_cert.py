#!/usr/bin/env python3
"""Independent checker of subdlab certificate documents (spectral and
characteristic-map parts).

    python3 scripts/check_cert.py CERTIFICATE.json

Exit status: 0 when every check holds (CERTIFICATE ACCEPTED), 1 when one
fails (CERTIFICATE REJECTED: the first failed check), 2 when the file cannot
be read or is not a certificate document of a version this checker knows.

Python 3.11 standard library only, and on purpose no code shared with
subdlab: the document's exact rows of the local subdivision matrix S are the
definition of S, and everything else is recomputed here.

- Premises, exactly (fractions.Fraction; cyclotomic elements reduced modulo
  the cyclotomic polynomial Φ_L, computed here from x^L − 1, in the one field
  Q(ζ_L) that holds every entry, so equal elements have equal coefficients):
  every entry real, every row sums to 1, the orbits are free (g members each;
  fixed points' rows invariant), every row is its representative's row
  rotated, the reflection is an involution with QPQ = P⁻¹ that S commutes
  with off the centre.
- Enclosures, rigorously: real intervals in midpoint-radius form on the
  dyadic grid 2^-P (integer midpoint and radius, so the endpoints are dyadic
  fractions, rounded outward after every operation that leaves the grid);
  complex intervals as rectangles (a real and an imaginary interval);
  cos and sin of 2πk/N exact where rational, else by Taylor series with a
  remainder bound on an enclosure of π (Machin's formula, alternating-series
  remainder). From the rows: the Fourier blocks B_m, then with the
  document's floating-point V and R (taken as exact numbers: any V, R with
  ‖I − RV‖∞ < 1 give valid discs) M ⊇ R·(B_m·V), ε ≥ ‖I − RV‖∞,
  δ = ε‖M‖∞/(1 − ε), and for every claimed disc the radius it needs,
  |M_ii − c_i| + Σ_{j≠i} |M_ij| + δ about the claimed centre c_i.
- Everything about the claimed discs afterwards (disjointness, moduli, real
  parts, holding 1) is decided exactly on the discs' binary64 values.
- The verdict's logic: for PROVED, λ0's and λ1's components and the gap; for
  DISPROVED, the witness inequality.
- The characteristic-map part (Checker.charmap): λ1's eigenvector enclosed
  from block 1's V and the discs recomputed above, the net refined by the
  document's exact stencils in the interval arithmetic above, every claimed
  Jacobian sign, the half-planes and the winding number (exactly); for the
  non-box S_3^1 windows (regular part `non-box-s31`), from each face's
  lattice layout, which differences and hull points the spline's bounds
  need (non_box_window: its own support tests). Trusted:
  the stencils being the scheme's rules, the box-spline Jacobian and hull
  bounds over a window, the covering of the neighbourhood, the windows'
  lattice layout and the chain (listed in the document's `trusted`).
- The sector map at a boundary vertex (the `sector` part beside `tagged`,
  Checker.sector; subdlab's lemmas B1–B6): λ1's and λ2's eigenvectors by
  Krawczyk's test on the reflection blocks rebuilt from the rows (the
  document's x̃, μ̃, R and Y, K(Y) recomputed here), μ inside its named
  disc; the normal coordinate's vanishing on the sharp curve (invariance
  exactly, the curve block's characteristic polynomial and a Sturm count
  over Q); the net by the exact stencils; per the document's host the
  window's positions and ghost points (bicubic B-spline, Catmull–Clark:
  4 × 4 windows, 2b − p through the ray point b; three-direction quartic
  box spline, Loop: 12-point triangle windows, a + b − p through the
  midpoint of the sharp edge a–b) and every face's det(u_i, v_j); the sharp
  rows on the line and monotone; the chain doubled by the mirror here and
  its winding number counted exactly. Trusted: the rules (the scheme's,
  the ghost-extended host box spline's over the windows), the windows'
  layout, the covering and the chain.
- Lemma C9 (regular part `difference-scheme`, DifferenceLattice), from the
  document's exact mask, windows and second-difference bases alone:
  re-derived exactly (Fractions, integers) — every mask class an affine
  rule (weights sum to 1, Σ w·δ = 0), the windows hold their corners and
  are closed (each child's window computed from its parent's; the D²
  children of each type found here), the basis rows vanish on affine data
  and are |W| − 3 independent ones; S_c from the mask, M_c from
  Δ2_child·S_c = M_c·Δ2_parent (solved by this checker's own Gauss–Jordan
  left inverse and checked on every column), K_edge and K_pos (max ‖κ‖₁ of
  D·edge(child) − edge(parent) and of a child's corner minus the parent's
  interpolant), the word norms P_j = max D^j‖M_w‖∞ over all type-consistent
  words of j ≤ L children (exact integer products, L the document's word,
  P_L < 1 required), and the factors ε/N = K_edge·Σ_{j<L}P_j/(1 − P_L) and
  δ/N = K_pos·Σ_{j<L}P_j D^-j/(1 − P_L D^-L). Rigorously, per face (balls
  above): N(p) from the window's values, det(u, v) ± (ε(|u| + |v|) + ε²),
  refined with the S_c on the face's own window up to the document's depth
  where its sign is undecided (a face's Jacobian lies in D² times the hull
  of its children's), and for the winding the face's corners with radius
  δ (d·p − δ|d| > 0). The document's k_edge, k_pos, word_norms and
  constants are only reported, never used. Trusted in addition: the rules
  over the windows being the exported mask, and each face's `window`
  layout (W_up on the net, the face's corners at (0,0), (1,0), (0,1)).
"""

import json
import math
import re
import sys
from fractions import Fraction
from operator import mul

# the grid of the interval endpoints: 2^-P (fine enough that exact dyadic
# data, e.g. a 1×1 block with entry 1/4, stays exact, as it does in subdlab)
P = 160
UNIT = 1 << P
# guard bits of the trigonometric series
GUARD = 64
# the largest cyclotomic field accepted (subdlab's own bound is 1024)
MAX_FIELD = 4096


class Rejected(Exception):
    """A check failed: exit 1."""


class Malformed(Exception):
    """Not a readable certificate document: exit 2."""


class PremiseFails(Exception):
    """An identity of S does not hold: fatal only for a verdict that uses it
    (a NOT PROVED document may rest on a failing premise, and say so)."""


def reject(msg):
    raise Rejected(msg)


# ---------------------------------------------------------------- parsing


def get(obj, key, what):
    if not isinstance(obj, dict) or key not in obj:
        raise Malformed(f"{what}: missing '{key}'")
    return obj[key]


def as_int(x, what, bound=None):
    if isinstance(x, bool) or not isinstance(x, int):
        raise Malformed(f"{what}: {x!r} is not an integer")
    if x < 0 or (bound is not None and x >= bound):
        reject(f"{what}: index {x} out of range 0..{'' if bound is None else bound - 1}")
    return x


def as_float(x, what):
    """A binary64 value of the document (exact)."""
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        raise Malformed(f"{what}: {x!r} is not a number")
    x = float(x)
    if not math.isfinite(x):
        raise Malformed(f"{what}: not finite")
    return x


def as_list(x, what, length=None):
    if not isinstance(x, list):
        raise Malformed(f"{what}: not a list")
    if length is not None and len(x) != length:
        reject(f"{what}: {len(x)} entries, expected {length}")
    return x


RATIO = re.compile(r"^(-?[0-9]+)(?:/([0-9]+))?$")


def as_ratio(s, what):
    if not isinstance(s, str):
        raise Malformed(f"{what}: {s!r} is not a 'p/q' string")
    m = RATIO.match(s)
    if not m:
        raise Malformed(f"{what}: {s!r} is not a 'p/q' string")
    den = int(m.group(2)) if m.group(2) is not None else 1
    if den == 0:
        raise Malformed(f"{what}: zero denominator")
    return Fraction(int(m.group(1)), den)


# ------------------------------------------------------ cyclotomic fields


def poly_divide_exactly(p, q):
    """p / q for a monic integer polynomial q dividing p (lowest first)."""
    p = list(p)
    e = len(q) - 1
    quotient = [0] * (len(p) - e)
    for i in range(len(p) - 1, e - 1, -1):
        c = p[i]
        if c:
            for j in range(e + 1):
                p[i - e + j] -= c * q[j]
            quotient[i - e] = c
    if any(p):
        raise AssertionError("inexact polynomial division")
    return quotient


_PHI = {}


def cyclotomic_polynomial(n):
    """Φ_n, integer coefficients lowest first: x^n − 1 over Φ_d, d | n, d < n."""
    if n not in _PHI:
        p = [-1] + [0] * (n - 1) + [1]
        for d in range(1, n):
            if n % d == 0:
                p = poly_divide_exactly(p, cyclotomic_polynomial(d))
        _PHI[n] = tuple(p)
    return _PHI[n]


class Field:
    """Q(ζ_L): elements as tuples of Fractions, the coefficients of
    1, ζ, ..., ζ^{φ(L)−1} after reduction modulo Φ_L, trailing zeros dropped.
    Φ_L is irreducible, so this form is unique: equal elements, equal tuples."""

    def __init__(self, order):
        self.order = order
        self.phi = cyclotomic_polynomial(order)
        self.degree = len(self.phi) - 1
        # x^d ≡ −Σ a_j x^j modulo Φ_L: the nonzero a_j only
        self.low = [(j, a) for j, a in enumerate(self.phi[: self.degree]) if a]
        self._value = {}
        self._real = {}

    def reduce(self, dense):
        d = self.degree
        p = list(dense)
        for i in range(len(p) - 1, d - 1, -1):
            c = p[i]
            if c:
                for j, a in self.low:
                    p[i - d + j] -= c * a
                p[i] = 0
        p = p[:d]
        while p and p[-1] == 0:
            p.pop()
        return tuple(p)

    def element(self, order, terms):
        """Σ c ζ_order^i for (i, c) in terms, written in Q(ζ_L)."""
        if self.order % order:
            raise AssertionError("element outside the field")
        if order == 1:
            c = sum((c for _, c in terms), Fraction(0))
            return (c,) if c else ()
        step = self.order // order
        dense = [Fraction(0)] * self.order
        for i, c in terms:
            dense[(i % order) * step % self.order] += c
        return self.reduce(dense)

    def conj(self, x):
        dense = [Fraction(0)] * self.order
        for i, c in enumerate(x):
            dense[(-i) % self.order] += c
        return self.reduce(dense)

    def is_real(self, x):
        if len(x) <= 1:
            return True
        if x not in self._real:
            self._real[x] = self.conj(x) == x
        return self._real[x]

    def add(self, x, y):
        n = max(len(x), len(y))
        s = [(x[i] if i < len(x) else 0) + (y[i] if i < len(y) else 0) for i in range(n)]
        while s and s[-1] == 0:
            s.pop()
        return tuple(s)

    def value(self, x):
        """A ball (scale 2^-P) enclosing the real element x = Σ x_i cos(2πi/L)."""
        if x not in self._value:
            mid, rad = 0, 0
            for i, c in enumerate(x):
                if c == 0:
                    continue
                cm, cr, _, _ = cos_sin(i, self.order)
                m, r = scale_ball(c, cm, cr)
                mid += m
                rad += r
            self._value[x] = (mid, rad)
        return self._value[x]


# ------------------------------------------------------ interval arithmetic
#
# A real ball (m, r) of integers at scale 2^-s is the interval
# [(m − r)/2^s, (m + r)/2^s]: dyadic endpoints, exact sums, and after a
# product (scale 2^-2s) the midpoint is floored back to 2^-s and the radius
# grows by one unit when the floor dropped anything, the product's own error
# term rounded up.


def shift_ball(m, r, bits):
    """A ball at scale 2^-(s+bits) as one at scale 2^-s (outward)."""
    if bits == 0:
        return m, r
    mid = m >> bits
    lost = 1 if m - (mid << bits) else 0
    return mid, -((-r) >> bits) + lost


def ball_mul(a, b, s):
    am, ar = a
    bm, br = b
    return shift_ball(am * bm, abs(am) * br + ar * abs(bm) + ar * br, s)


def ball_div_int(a, d):
    m, r = a
    mid, rem = divmod(m, d)
    return mid, -((-r) // d) + (1 if rem else 0)


def ball_of_fraction(q, s):
    num = q.numerator << s
    mid, rem = divmod(num, q.denominator)
    return mid, (1 if rem else 0)


def ball_of_float(x):
    """The binary64 x at scale 2^-P (a point when it lies on the grid)."""
    p, q = x.as_integer_ratio()
    mid, rem = divmod(p << P, q)
    return mid, (1 if rem else 0)


def scale_ball(c, m, r):
    """The rational c times the ball (m, r), same scale."""
    num = c.numerator * m
    mid, rem = divmod(num, c.denominator)
    rad = -((-abs(c.numerator) * r) // c.denominator) + (1 if rem else 0)
    return mid, rad


def _pi_ball(s):
    """π at scale 2^-s: Machin, π = 16 atan(1/5) − 4 atan(1/239), each
    alternating series cut where its first omitted term bounds the rest."""

    def atan_inv(x):
        total, k, err = Fraction(0), 0, None
        while True:
            term = Fraction(1, (2 * k + 1) * x ** (2 * k + 1))
            if term < Fraction(1, 1 << (s + 8)):
                err = term
                break
            total += term if k % 2 == 0 else -term
            k += 1
        return total, err

    a, ea = atan_inv(5)
    b, eb = atan_inv(239)
    value, err = 16 * a - 4 * b, 16 * ea + 4 * eb
    mid, rad = ball_of_fraction(value, s)
    return mid, rad + math.ceil(err * (1 << s))


_PI = None


def _series(x, s, sine):
    """cos x or sin x for a ball x (scale 2^-s, |x| ≤ 4) by Horner's scheme
    on the Taylor polynomial in ball arithmetic, plus the remainder bound
    4^(2N+2)/(2N+2)! (cos) or 4^(2N+3)/(2N+3)! (sin)."""
    one = (1 << s, 0)
    x2 = ball_mul(x, x, s)

    def tail(n):
        e = 2 * n + 3 if sine else 2 * n + 2
        return Fraction(4**e, math.factorial(e))

    n = 1
    while tail(n) >= Fraction(1, 1 << (s + 4)):
        n += 1
    acc = one
    for j in range(n, 0, -1):
        d = (2 * j) * (2 * j + 1) if sine else (2 * j - 1) * (2 * j)
        t = ball_div_int(ball_mul(x2, acc, s), d)
        acc = (one[0] - t[0], t[1])
    if sine:
        acc = ball_mul(x, acc, s)
    return acc[0], acc[1] + math.ceil(tail(n) * (1 << s))


# cos(2πf) for the fractions f where it is rational
_EXACT_COS = {
    Fraction(0): Fraction(1),
    Fraction(1, 4): Fraction(0),
    Fraction(1, 2): Fraction(-1),
    Fraction(3, 4): Fraction(0),
    Fraction(1, 6): Fraction(1, 2),
    Fraction(5, 6): Fraction(1, 2),
    Fraction(1, 3): Fraction(-1, 2),
    Fraction(2, 3): Fraction(-1, 2),
}

_TRIG = {}


def _cos_turn(f):
    """A ball (scale 2^-P) enclosing cos(2πf), f a fraction in [0, 1)."""
    if f in _EXACT_COS:
        return ball_of_fraction(_EXACT_COS[f], P)
    global _PI
    s = P + GUARD
    if _PI is None:
        _PI = _pi_ball(s)
    g = f - 1 if f > Fraction(1, 2) else f  # |2πg| ≤ π < 4
    x = ball_div_int((_PI[0] * 2 * g.numerator, _PI[1] * 2 * abs(g.numerator)), g.denominator)
    m, r = _series(x, s, sine=False)
    return shift_ball(m, r, GUARD)


def cos_sin(k, n):
    """Balls (cm, cr, sm, sr) at scale 2^-P enclosing cos and sin of 2πk/n."""
    f = Fraction(k % n, n)
    if f not in _TRIG:
        cm, cr = _cos_turn(f)
        # sin(2πf) = cos(2π(1/4 − f))
        sm, sr = _cos_turn((Fraction(1, 4) - f) % 1)
        _TRIG[f] = (cm, cr, sm, sr)
    return _TRIG[f]


# complex interval matrices: four integer matrices (real midpoints,
# imaginary midpoints, real radii, imaginary radii), scale 2^-P


def imat(x, y):
    cols = list(zip(*y))
    return [[sum(map(mul, row, col)) for col in cols] for row in x]


def is_zero(m):
    return all(not v for row in m for v in row)


def absm(m):
    return [[abs(v) for v in row] for row in m]


def cmatmul(a, b):
    """A rectangle enclosure of every product of matrices in a and b: the
    midpoints' product exactly (scale 2^-2P), and per real product the error
    |x y − x_m y_m| ≤ |x_m| y_r + x_r |y_m| + x_r y_r, summed; then back to
    2^-P outward."""
    amr, ami, arr, ari = a
    bmr, bmi, brr, bri = b
    k, n = len(amr), len(bmr[0])
    pre = imat(amr, bmr)
    pim = imat(ami, bmr)
    if not is_zero(ami) and not is_zero(bmi):
        t = imat(ami, bmi)
        pre = [[x - y for x, y in zip(r1, r2)] for r1, r2 in zip(pre, t)]
    if not is_zero(bmi):
        t = imat(amr, bmi)
        pim = [[x + y for x, y in zip(r1, r2)] for r1, r2 in zip(pim, t)]
    # radii: the real part's terms are x_re y_re and x_im y_im, the
    # imaginary part's x_re y_im and x_im y_re
    zero = [[0] * n for _ in range(k)]
    rre = [row[:] for row in zero]
    rim = [row[:] for row in zero]

    def acc(target, xm, xr, ym, yr):
        for xa, ya, use in ((absm(xm), yr, not is_zero(yr)), (xr, absm(ym), not is_zero(xr))):
            if use:
                t = imat(xa, ya)
                for i in range(k):
                    ti, ri = t[i], target[i]
                    for j in range(n):
                        ri[j] += ti[j]
        if not is_zero(xr) and not is_zero(yr):
            t = imat(xr, yr)
            for i in range(k):
                for j in range(n):
                    target[i][j] += t[i][j]

    acc(rre, amr, arr, bmr, brr)
    acc(rre, ami, ari, bmi, bri)
    acc(rim, amr, arr, bmi, bri)
    acc(rim, ami, ari, bmr, brr)
    out = ([[0] * n for _ in range(k)], [[0] * n for _ in range(k)], [[0] * n for _ in range(k)], [[0] * n for _ in range(k)])
    for i in range(k):
        for j in range(n):
            out[0][i][j], out[2][i][j] = shift_ball(pre[i][j], rre[i][j], P)
            out[1][i][j], out[3][i][j] = shift_ball(pim[i][j], rim[i][j], P)
    return out


def scale_matrix(c, a):
    """The positive rational c times a complex ball matrix (outward)."""
    out = ([], [], [], [])
    for part, rad in ((0, 2), (1, 3)):
        for mrow, rrow in zip(a[part], a[rad]):
            balls = [scale_ball(c, x, r) for x, r in zip(mrow, rrow)]
            out[part].append([b[0] for b in balls])
            out[rad].append([b[1] for b in balls])
    return out


def ceil_sqrt(n):
    r = math.isqrt(n)
    return r if r * r == n else r + 1


def mag(mr, mi, rr, ri):
    """Upper bound (scale 2^-P) of |z| over the rectangle."""
    a, b = abs(mr) + rr, abs(mi) + ri
    return ceil_sqrt(a * a + b * b)


def point_matrix(rows, k, what):
    """A k×k matrix of [re, im] binary64 pairs as a (point-when-exact) ball matrix."""
    rows = as_list(rows, what, k)
    out = ([], [], [], [])
    for i, row in enumerate(rows):
        row = as_list(row, f"{what} row {i}", k)
        parts = ([], [], [], [])
        for j, z in enumerate(row):
            z = as_list(z, f"{what}[{i}][{j}]", 2)
            rm, rr = ball_of_float(as_float(z[0], what))
            im, ir = ball_of_float(as_float(z[1], what))
            parts[0].append(rm)
            parts[1].append(im)
            parts[2].append(rr)
            parts[3].append(ir)
        for o, p in zip(out, parts):
            o.append(p)
    return out


# ------------------------------------------------------ exact disc geometry


class Disc:
    __slots__ = ("re", "im", "r")

    def __init__(self, re, im, r):
        self.re, self.im, self.r = Fraction(re), Fraction(im), Fraction(r)

    def norm2(self):
        return self.re * self.re + self.im * self.im


def disjoint(a, b):
    dx, dy, s = a.re - b.re, a.im - b.im, a.r + b.r
    return dx * dx + dy * dy > s * s


def holds(d, x, y=Fraction(0)):
    dx, dy = d.re - x, d.im - y
    return dx * dx + dy * dy <= d.r * d.r


def meets_real_axis(d):
    return abs(d.im) <= d.r


def mod_below(d, bound):
    """Every point of d has modulus < bound: |c| + r < bound."""
    room = bound - d.r
    return room > 0 and d.norm2() < room * room


def mod_at_most(d, bound):
    room = bound - d.r
    return room >= 0 and d.norm2() <= room * room


def mod_above(d, bound):
    """Every point of d has modulus > bound (≥ 0): |c| − r > bound."""
    t = bound + d.r
    return d.norm2() > t * t


def mod_separated(a, b):
    """Every point of a has larger modulus than every point of b:
    |a.c| − a.r > |b.c| + b.r, i.e. |a.c|² − |b.c|² − s² > 2s|b.c| (s = a.r + b.r)."""
    s = a.r + b.r
    lhs = a.norm2() - b.norm2() - s * s
    return lhs > 0 and lhs * lhs > 4 * s * s * b.norm2()


def mod_from(d, lo):
    """Every point of d has modulus ≥ lo (≥ 0): |c| − r ≥ lo."""
    t = lo + d.r
    return d.norm2() >= t * t


def real_section_above(d, lo):
    """Every real point of d is ≥ lo: re − sqrt(r² − im²) ≥ lo."""
    if not meets_real_axis(d):
        return True
    room = d.re - lo
    return room >= 0 and d.r * d.r - d.im * d.im <= room * room


def real_section_below(d, hi):
    if not meets_real_axis(d):
        return True
    room = hi - d.re
    return room >= 0 and d.r * d.r - d.im * d.im <= room * room


# ------------------------------------------------------ exact polynomials over Q (lemma S7)


def det_fraction(a):
    """det of a square matrix of Fractions by Gaussian elimination."""
    a = [row[:] for row in a]
    n = len(a)
    det = Fraction(1)
    for c in range(n):
        piv = next((r for r in range(c, n) if a[r][c] != 0), None)
        if piv is None:
            return Fraction(0)
        if piv != c:
            a[c], a[piv] = a[piv], a[c]
            det = -det
        det *= a[c][c]
        inv = 1 / a[c][c]
        for r in range(c + 1, n):
            f = a[r][c] * inv
            if f:
                for k in range(c, n):
                    a[r][k] -= f * a[c][k]
    return det


def rank(a):
    a = [row[:] for row in a]
    rows, cols = len(a), len(a[0]) if a else 0
    r = 0
    for c in range(cols):
        piv = next((i for i in range(r, rows) if a[i][c] != 0), None)
        if piv is None:
            continue
        a[r], a[piv] = a[piv], a[r]
        for i in range(r + 1, rows):
            f = a[i][c] / a[r][c]
            if f:
                for k in range(c, cols):
                    a[i][k] -= f * a[r][k]
        r += 1
    return r


def charpoly_by_interpolation(s):
    """det(xI − S), lowest coefficient first: its values at x = 0..N, then
    Newton's divided differences, expanded."""
    n = len(s)
    xs = [Fraction(t) for t in range(n + 1)]
    ys = [det_fraction([[(xs[t] if i == j else 0) - s[i][j] for j in range(n)] for i in range(n)]) for t in range(n + 1)]
    coef = ys[:]
    for j in range(1, n + 1):
        for i in range(n, j - 1, -1):
            coef[i] = (coef[i] - coef[i - 1]) / (xs[i] - xs[i - j])
    p = [Fraction(0)] * (n + 1)
    p[0] = coef[n]
    deg = 0
    for i in range(n - 1, -1, -1):
        # p = p·(x − x_i) + coef[i]
        q = [Fraction(0)] * (n + 1)
        for k in range(deg + 1):
            q[k + 1] += p[k]
            q[k] -= xs[i] * p[k]
        q[0] += coef[i]
        p = q
        deg += 1
    if p[n] != 1:
        raise AssertionError("the characteristic polynomial is not monic")
    return p


def poly_at(p, x):
    """p(x), p lowest coefficient first (exact)."""
    v = Fraction(0)
    for c in reversed(p):
        v = v * x + c
    return v


def _trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def _poly_rem(a, b):
    a, b = _trim(a), _trim(b)
    while len(a) >= len(b) and a:
        f = a[-1] / b[-1]
        shift = len(a) - len(b)
        for i, c in enumerate(b):
            a[shift + i] -= f * c
        a = _trim(a)
    return a


def sturm_count(p, lo, hi):
    """The number of distinct real roots of p in (lo, hi] (Sturm's theorem
    on the squarefree part p / gcd(p, p′))."""
    p = _trim(p)
    d = [i * c for i, c in enumerate(p)][1:]
    g, h = p, _trim(d)
    while h:
        g, h = h, _poly_rem(g, h)
    if len(g) > 1:
        # exact division p / g
        q = [Fraction(0)] * (len(p) - len(g) + 1)
        r = list(p)
        for i in range(len(q) - 1, -1, -1):
            q[i] = r[i + len(g) - 1] / g[-1]
            for j, c in enumerate(g):
                r[i + j] -= q[i] * c
        p = _trim(q)
    chain = [p, _trim([i * c for i, c in enumerate(p)][1:])]
    while chain[-1] and len(chain[-1]) > 1:
        r = _poly_rem(chain[-2], chain[-1])
        if not r:
            break
        chain.append([-c for c in r])
    chain = [c for c in chain if c]

    def changes(x):
        signs = [v for v in (poly_at(c, x) for c in chain) if v != 0]
        return sum(1 for a, b in zip(signs, signs[1:]) if (a > 0) != (b > 0))

    return changes(lo) - changes(hi)


def root_multiplicity(p, r):
    """(m, q): r is a root of p of multiplicity m, p = (x − r)^m q."""
    p = list(p)
    while len(p) > 1 and p[-1] == 0:
        p.pop()
    m = 0
    while len(p) > 1:
        # synthetic division by (x − r)
        q = [Fraction(0)] * (len(p) - 1)
        carry = Fraction(0)
        for k in range(len(p) - 1, 0, -1):
            carry = carry * r + p[k]
            q[k - 1] = carry
        if carry * r + p[0] != 0:
            break
        p = q
        m += 1
    return m, p


def roots_inside(p, r):
    """Every root of p strictly inside |x| < r (Schur–Cohn on p(r x))."""
    f = [c * r**k for k, c in enumerate(p)]
    while True:
        while len(f) > 1 and f[-1] == 0:
            f.pop()
        if not f:
            return False
        if len(f) == 1:
            return f[0] != 0
        lead = f[-1]
        f = [c / lead for c in f]
        d = len(f) - 1
        c = f[0]
        if abs(c) >= 1:
            return False
        f = [f[k] - c * f[d - k] for k in range(1, d + 1)]


def roots_outside(p, r):
    """The number of roots of p of modulus > r, or None where the counting
    Schur–Cohn recursion meets |f_0| = |f_d| (a root of modulus r, or a
    pair symmetric about the circle): on f = p(r x), |f_d| > |f_0| keeps
    the count for h = (f_d f − f_0 f*)/x, |f_0| > |f_d| gives d − count(h)."""
    f = [c * r**k for k, c in enumerate(p)]
    sign, offset = 1, 0
    while True:
        while len(f) > 1 and f[-1] == 0:
            f.pop()
        if not f:
            return None
        if len(f) == 1:
            return offset if f[0] != 0 else None
        d = len(f) - 1
        lead, c = f[-1], f[0]
        if abs(lead) == abs(c):
            return None
        if abs(c) > abs(lead):
            offset += sign * d
            sign = -sign
        f = [lead * f[k] - c * f[d - k] for k in range(1, d + 1)]
        big = max(abs(x) for x in f)
        if big:
            f = [x / big for x in f]


def count_above(p, r):
    """roots_outside at r, else equal counts at r(1 ∓ 2^-j), j = 1..16."""
    c = roots_outside(p, r)
    if c is not None:
        return c
    for j in range(1, 17):
        e = Fraction(1, 2**j)
        lo, hi = roots_outside(p, r * (1 - e)), roots_outside(p, r * (1 + e))
        if lo is not None and lo == hi:
            return lo
    return None


# ------------------------------------------------------ the checker


class Checker:
    def __init__(self, doc):
        self.doc = doc
        self.lines = []

    def ok(self, msg):
        self.lines.append(f"  ok  {msg}")

    def run(self):
        doc = self.doc
        if not isinstance(doc, dict):
            raise Malformed("the document is not a JSON object")
        if doc.get("format") != "subdlab-certificate":
            raise Malformed("not a subdlab certificate document ('format' is not 'subdlab-certificate')")
        if doc.get("version") != 1:
            raise Malformed(f"certificate version {doc.get('version')!r}: this checker knows version 1")
        parts = get(doc, "parts", "document")
        if not isinstance(parts, dict) or not parts:
            raise Malformed("'parts' is not a non-empty object")
        unknown = sorted(set(parts) - {"spectrum", "charmap", "tagged", "sector"})
        if unknown:
            reject(f"part(s) {', '.join(unknown)}: this checker re-checks only the 'spectrum', 'charmap', 'tagged' and 'sector' parts")
        if "tagged" in parts:
            if set(parts) - {"tagged", "sector"}:
                reject("a tagged document holds the tagged part and at most the sector part")
            self.ok(f"document: {doc.get('scheme')} at a tagged vertex of {doc.get('valence')} sectors, {doc.get('neighbourhood')} neighbourhood")
            self.tagged(parts["tagged"])
            if "sector" in parts:
                self.sector(parts["sector"])
            elif doc.get("sector_omitted"):
                # a sector map not PROVED writes no sector part: only the
                # spectral verdict is re-checked, never the map's claim
                self.lines.append(f"  --  no sector part: {doc['sector_omitted']}")
                self.verdict = f"tagged {self.verdict}; sector criterion not re-checked (claimed {doc.get('sector_claimed')})"
            return
        if "sector" in parts:
            reject("a sector part without the tagged part it rests on")
        if "spectrum" not in parts:
            reject("the document has no spectrum part, on which every other part rests")
        self.ok(f"document: {doc.get('scheme')} at valence {doc.get('valence')}, {doc.get('neighbourhood')} neighbourhood")
        self.spectrum(parts["spectrum"])
        if "charmap" in parts:
            self.charmap(parts["charmap"])
        elif doc.get("charmap_omitted"):
            self.lines.append(f"  --  no charmap part: {doc['charmap_omitted']}")

    # -- the matrix and its premises

    def spectrum(self, part):
        self.part = part
        what = "spectrum"
        size = as_int(get(part, "size", what), "size")
        self.size = size
        self.method = get(part, "method", what)
        if self.method not in ("dft", "full"):
            raise Malformed(f"unknown method {self.method!r}")
        self.verdict = get(part, "verdict", what)
        if self.verdict not in ("PROVED", "DISPROVED", "NOT PROVED"):
            raise Malformed(f"unknown verdict {self.verdict!r}")
        self.read_rows(part)
        self.premises = {}
        self.premise("row sums", self.check_row_sums)
        if self.method == "dft":
            self.read_orbits(part)
            self.premise("rotation", self.check_rotation)
            self.premise("mirror", lambda: self.check_mirror(part))
        self.check_blocks(part)
        self.check_verdict(part)

    def premise(self, name, check):
        try:
            check()
            self.premises[name] = None
        except PremiseFails as e:
            self.premises[name] = str(e)
            self.lines.append(f"  --  premise fails ({name}): {e}")

    def need(self, *names):
        """The verdict uses these premises: each must hold."""
        for name in names:
            if name not in self.premises:
                reject(f"{self.verdict} needs the {name} premise, which the whole-matrix document does not have")
            if self.premises[name] is not None:
                reject(f"{self.verdict} rests on a premise that fails ({name}): {self.premises[name]}")

    def read_rows(self, part):
        size = self.size
        if not get(part, "exact", "spectrum") or get(part, "inexact_rows", "spectrum"):
            reject(
                "the certificate has rows known in floating point only (inexact_rows "
                f"{get(part, 'inexact_rows', 'spectrum')}): S cannot be re-verified from exact data"
            )
        rows = as_list(get(part, "rows", "spectrum"), "rows")
        if len(rows) != size:
            reject(f"the document has {len(rows)} rows for a matrix of {size} points")
        raw = []
        order = 1
        for k, row in enumerate(rows):
            if row is None:
                reject(f"row {k} has no exact form: S cannot be re-verified")
            row = as_list(row, f"row {k}")
            entries = []
            for e in row:
                e = as_list(e, f"row {k} entry", 2)
                col = as_int(e[0], f"row {k} column", size)
                v = e[1]
                if isinstance(v, str):
                    entries.append((col, 1, ((0, as_ratio(v, f"row {k}")),)))
                elif isinstance(v, dict):
                    n = get(v, "order", f"row {k} entry")
                    if isinstance(n, bool) or not isinstance(n, int) or n < 1 or n > MAX_FIELD:
                        reject(f"row {k}: cyclotomic order {n!r} outside 1..{MAX_FIELD}")
                    terms = tuple(
                        (as_int(as_list(t, f"row {k} coefficient", 2)[0], f"row {k} power"), as_ratio(t[1], f"row {k}"))
                        for t in as_list(get(v, "coefficients", f"row {k}"), f"row {k} coefficients")
                    )
                    order = order * n // math.gcd(order, n)
                    if order > MAX_FIELD:
                        reject(f"the rows need the field Q(ζ_{order}), beyond Q(ζ_{MAX_FIELD})")
                    entries.append((col, n, terms))
                else:
                    raise Malformed(f"row {k}: an entry is neither 'p/q' nor a cyclotomic element")
            raw.append(entries)
        self.field = Field(order)
        cache = {}
        self.rows = []
        for k, entries in enumerate(raw):
            row = {}
            for col, n, terms in entries:
                key = (n, terms)
                if key not in cache:
                    cache[key] = self.field.element(n, terms)
                x = cache[key]
                if col in row:
                    reject(f"row {k} lists column {col} twice")
                if not self.field.is_real(x):
                    reject(f"S[{k}, {col}] is not real")
                if x:
                    row[col] = x
            self.rows.append(row)
        self.ok(f"exact rows: {size} rows, every entry real, in Q(ζ_{order}) reduced modulo Φ_{order}" if order > 1 else f"exact rows: {size} rows in Q")

    def check_row_sums(self):
        one = (Fraction(1),)
        for k, row in enumerate(self.rows):
            s = ()
            for x in row.values():
                s = self.field.add(s, x)
            if s != one:
                raise PremiseFails(f"row {k} does not sum to 1")
        self.ok("premise: every row sums to 1 exactly (1 is an eigenvalue, of block 0)")

    def read_orbits(self, part):
        size = self.size
        g = as_int(get(part, "group_order", "spectrum"), "group_order")
        if g < 1:
            reject("group order 0")
        orbits = get(part, "orbits", "spectrum")
        member = as_list(get(orbits, "member", "orbits"), "orbits.member", size)
        rep = as_list(get(orbits, "representative", "orbits"), "orbits.representative")
        fixed = as_list(get(orbits, "fixed", "orbits"), "orbits.fixed", len(rep))
        if not all(isinstance(f, bool) for f in fixed):
            raise Malformed("orbits.fixed: not booleans")
        no = len(rep)
        index = [[None] * g for _ in range(no)]
        self.member = []
        for k, m in enumerate(member):
            m = as_list(m, f"orbits.member[{k}]", 2)
            o, t = as_int(m[0], "orbit", no), as_int(m[1], "orbit position", g)
            if fixed[o] and t != 0:
                reject(f"premise: point {k} of fixed orbit {o} has position {t}")
            if index[o][t] is not None:
                reject(f"premise: orbit {o} has two points at position {t}")
            index[o][t] = k
            self.member.append((o, t))
        for o in range(no):
            have = [t for t in range(g) if index[o][t] is not None]
            want = [0] if fixed[o] else list(range(g))
            if have != want:
                reject(f"premise: orbit {o} is not free: it has {len(have)} points, a {'fixed' if fixed[o] else 'moving'} orbit needs {len(want)}")
            if as_int(rep[o], "representative", size) != index[o][0]:
                reject(f"premise: the representative of orbit {o} is not its point at position 0")
        self.g, self.rep, self.fixed, self.index = g, rep, fixed, index
        self.ok(f"premise: {no} orbits under a rotation group of order {g}, each free ({sum(fixed)} fixed point(s))")

    def rotate(self, k, steps):
        o, t = self.member[k]
        return k if self.fixed[o] else self.index[o][(t + steps) % self.g]

    def check_rotation(self):
        for k, row in enumerate(self.rows):
            o, t = self.member[k]
            if self.fixed[o]:
                source, steps = k, 1
            else:
                source, steps = self.rep[o], t
            moved = {self.rotate(c, steps): x for c, x in self.rows[source].items()}
            if moved != row:
                raise PremiseFails(f"row {k} is not the row of {source} rotated by {steps} (S does not commute with the rotation)")
        self.ok("premise: every row is its representative's rotated, fixed points' rows rotation-invariant (PS = SP)")

    def check_mirror(self, part):
        q = get(part, "mirror", "spectrum")
        if q is None:
            raise PremiseFails("the document gives no reflection of the neighbourhood")
        q = [as_int(x, "mirror", self.size) for x in as_list(q, "mirror", self.size)]
        if sorted(q) != list(range(self.size)):
            raise PremiseFails("the mirror map is not a permutation")
        g = self.g
        for k in range(self.size):
            if q[q[k]] != k:
                raise PremiseFails(f"the mirror map is not an involution at {k}")
            if self.fixed[self.member[k][0]] != self.fixed[self.member[q[k]][0]]:
                raise PremiseFails(f"the mirror map moves the fixed point {k} off the centre (or onto it)")
            if q[self.rotate(q[k], 1)] != self.rotate(k, g - 1):
                raise PremiseFails(f"QPQ ≠ P⁻¹ at point {k}")

        def off(row):
            return {c: x for c, x in row.items() if not self.fixed[self.member[c][0]]}

        for r in range(self.size):
            if self.fixed[self.member[r][0]]:
                continue
            mirrored = {q[c]: x for c, x in off(self.rows[r]).items()}
            if mirrored != off(self.rows[q[r]]):
                raise PremiseFails(f"S[Q{r}, Q·] ≠ S[{r}, ·] off the centre (S does not commute with the reflection)")
        self.ok("premise: a reflection Q with Q² = I, QPQ = P⁻¹ commutes with S off the centre (block spectra closed under conjugation)")

    # -- the blocks and their discs

    def block_matrix(self, m):
        """The interval Fourier block B_m (or the whole matrix), and its orbit order."""
        if self.method == "tagged" and self.reflection is not None:
            return self.reflection_block(m)
        if self.method == "full":
            order = list(range(self.size))
            k = len(order)
            mr = [[0] * k for _ in range(k)]
            rr = [[0] * k for _ in range(k)]
            for i, row in enumerate(self.rows):
                for c, x in row.items():
                    vm, vr = self.field.value(x)
                    mr[i][c] += vm
                    rr[i][c] += vr
            zero = [[0] * k for _ in range(k)]
            return order, (mr, [r[:] for r in zero], rr, [r[:] for r in zero])
        g = self.g
        order = [o for o in range(len(self.rep)) if m == 0 or not self.fixed[o]]
        pos = {o: i for i, o in enumerate(order)}
        k = len(order)
        # exact sums at scale 2^-2P, one rounding per entry
        acc = [[[0, 0, 0, 0] for _ in range(k)] for _ in range(k)]
        for a, o in enumerate(order):
            for c, x in self.rows[self.rep[o]].items():
                ob, tau = self.member[c]
                if ob not in pos:
                    continue  # a fixed point outside block 0: its column sums to zero
                wm, wr = self.field.value(x)
                cm, cr, sm, sr = cos_sin(m * tau, g)
                e = acc[a][pos[ob]]
                e[0] += wm * cm
                e[1] += wm * sm
                e[2] += abs(wm) * cr + wr * abs(cm) + wr * cr
                e[3] += abs(wm) * sr + wr * abs(sm) + wr * sr
        mats = ([[0] * k for _ in range(k)], [[0] * k for _ in range(k)], [[0] * k for _ in range(k)], [[0] * k for _ in range(k)])
        for i in range(k):
            for j in range(k):
                e = acc[i][j]
                mats[0][i][j], mats[2][i][j] = shift_ball(e[0], e[2], P)
                mats[1][i][j], mats[3][i][j] = shift_ball(e[1], e[3], P)
        return order, mats

    def check_blocks(self, part):
        blocks = as_list(get(part, "blocks", "spectrum"), "blocks")
        if self.method == "dft":
            want = list(range(self.g))
        elif self.method == "tagged" and self.reflection is not None:
            want = [0, 1]
        else:
            want = [0]
        got = [as_int(get(b, "block", "block"), "block index") for b in blocks]
        self.discs, self.components, self.failed = {}, {}, []
        # for the characteristic map: per block V, the disc rows of each
        # component, and the radii recomputed here (scale 2^-P)
        self.vmats, self.comp_rows, self.needs = {}, {}, {}
        if not blocks and self.verdict == "NOT PROVED":
            self.lines.append("  --  no enclosures (the verdict stopped before them)")
            return
        if got != want:
            reject(f"the document's blocks are {got}, expected {want}")
        failed = []
        worst_eps, worst_slack = Fraction(0), None
        for b in blocks:
            m = b["block"]
            order, a = self.block_matrix(m)
            k = len(order)
            if self.method == "dft" and get(b, "orbits", f"block {m}") != order:
                reject(f"block {m}: its rows are orbits {b['orbits']}, the checker's block has {order}")
            if as_int(get(b, "size", f"block {m}"), "block size") != k:
                reject(f"block {m}: size {b['size']}, the block has {k} rows")
            if get(b, "failure", f"block {m}") is not None:
                failed.append(m)
                continue
            v = point_matrix(get(b, "v", f"block {m}"), k, f"block {m} V")
            r = point_matrix(get(b, "r", f"block {m}"), k, f"block {m} R")
            claimed_eps = Fraction(as_float(get(b, "epsilon", f"block {m}"), f"block {m} epsilon"))
            mm = cmatmul(r, cmatmul(a, v))
            rv = cmatmul(r, v)
            # ε ≥ ‖I − RV‖∞
            eps = 0
            for i in range(k):
                row = 0
                for j in range(k):
                    row += mag((UNIT if i == j else 0) - rv[0][i][j], -rv[1][i][j], rv[2][i][j], rv[3][i][j])
                eps = max(eps, row)
            if eps >= UNIT:
                reject(f"block {m}: ‖I − RV‖∞ is not below 1 (V is not shown invertible)")
            if claimed_eps * UNIT < eps:
                reject(f"block {m}: the claimed ε = {float(claimed_eps):.3e} is below ‖I − RV‖∞ ≥ {eps / UNIT:.3e}")
            worst_eps = max(worst_eps, Fraction(eps, UNIT))
            mags = [[mag(mm[0][i][j], mm[1][i][j], mm[2][i][j], mm[3][i][j]) for j in range(k)] for i in range(k)]
            norm = max((sum(row) for row in mags), default=0)
            delta = -((-eps * norm) // (UNIT - eps))  # ⌈ε‖M‖/(1 − ε)⌉ at scale 2^-P
            discs_doc = as_list(get(b, "discs", f"block {m}"), f"block {m} discs", k)
            discs = []
            needs = []
            for i, d in enumerate(discs_doc):
                d = as_list(d, f"block {m} disc {i}", 3)
                re_, im_, rad = (as_float(x, f"block {m} disc {i}") for x in d)
                cr_m, cr_r = ball_of_float(re_)
                ci_m, ci_r = ball_of_float(im_)
                need = mag(mm[0][i][i] - cr_m, mm[1][i][i] - ci_m, mm[2][i][i] + cr_r, mm[3][i][i] + ci_r)
                need += sum(mags[i][j] for j in range(k) if j != i) + delta
                claimed = Fraction(rad)
                if claimed * UNIT < need:
                    reject(
                        f"block {m}: disc {i} claims radius {rad:.6e}, but the Gershgorin bound about its centre "
                        f"is {need / UNIT:.6e}"
                    )
                needs.append(need)
                slack = claimed - Fraction(need, UNIT)
                worst_slack = slack if worst_slack is None else min(worst_slack, slack)
                discs.append(Disc(re_, im_, rad))
            comps = []
            seen = []
            for c in as_list(get(b, "components", f"block {m}"), f"block {m} components"):
                idx = [as_int(i, f"block {m} component disc", k) for i in as_list(get(c, "discs", "component"), "component discs")]
                count = get(c, "count", "component")
                if not idx or count != len(idx):
                    reject(f"block {m}: a component claims {count} eigenvalue(s) for its {len(idx)} disc(s)")
                comps.append(idx)
                seen.extend(idx)
            if sorted(seen) != list(range(k)):
                reject(f"block {m}: the components do not partition the block's {k} discs")
            owner = {i: ci for ci, idx in enumerate(comps) for i in idx}
            for i in range(k):
                for j in range(i + 1, k):
                    if owner[i] != owner[j] and not disjoint(discs[i], discs[j]):
                        reject(f"block {m}: discs {i} and {j} are in different components but not disjoint")
            self.discs[m] = discs
            self.vmats[m], self.comp_rows[m], self.needs[m] = v, comps, needs
            self.components[m] = [[discs[i] for i in idx] for idx in comps]
        self.failed = failed
        n = len(blocks) - len(failed)
        self.ok(
            f"enclosures: {n} block(s) recomputed from the rows (M ⊇ R·B·V, ε up to {float(worst_eps):.3e}); every claimed disc "
            f"holds its Gershgorin disc (least slack {float(worst_slack or 0):.3e}); components disjoint, counts = discs"
        )
        if failed:
            self.lines.append(f"  --  blocks without an enclosure (as the document says): {failed}")

    # -- tagged vertices (subdlab's certify::tagged, lemmas T4 and T7)

    def tagged(self, part):
        what = "tagged"
        self.part = part
        self.size = as_int(get(part, "size", what), "size")
        self.method = "tagged"
        self.verdict = get(part, "verdict", what)
        if self.verdict not in ("PROVED", "DISPROVED", "NOT PROVED"):
            raise Malformed(f"unknown verdict {self.verdict!r}")
        self.read_rows(part)
        self.premises = {}
        self.premise("row sums", self.check_row_sums)
        self.reflection = None
        refl = get(part, "reflection", what)
        if refl is not None:
            n = self.size
            p = [as_int(x, "reflection image", n) for x in as_list(refl, "reflection", n)]
            if any(p[p[a]] != a for a in range(n)):
                reject("the reflection is not an involution")
            # S[Pa][Pb] = S[a][b]: every non-zero entry of every row maps onto an
            # equal entry (an entry non-zero only at (Pa, Pb) is caught from row Pa)
            for a in range(n):
                for b, x in self.rows[a].items():
                    if self.rows[p[a]].get(p[b], ()) != x:
                        reject(f"S does not commute with the reflection: S[{a}][{b}] ≠ S[{p[a]}][{p[b]}]")
            self.reflection = p
            self.ok("reflection: an involution that S commutes with, exactly on every entry; blocks E, O rebuilt here")
        if self.premises["row sums"] is not None:
            reject("the rows do not sum to 1")
        self.check_blocks(part)
        # a crease vertex whose sides decouple: the document's verdict is the
        # sides'; S whole's own routes are re-checked against its own word
        crease = part.get("crease")
        decoupled = isinstance(crease, dict) and crease.get("decoupled") is True
        crease_word = self.verdict
        tag = part.get("tag")
        if isinstance(tag, str) and tag.startswith("crease:") and "crease" in part:
            self.check_crease_fallback(part, crease, decoupled)
        if decoupled:
            self.verdict = get(crease, "whole_verdict", "crease")
            if self.verdict not in ("PROVED", "DISPROVED", "NOT PROVED"):
                raise Malformed(f"unknown verdict {self.verdict!r} of S whole")
        self.check_tagged_routes(get(part, "claims", what))
        if decoupled:
            self.check_crease_sides(part, crease, crease_word)
            self.verdict = crease_word

    def check_tagged_routes(self, claims):
        """The verdict self.verdict against the routes' claims re-checked here."""
        exact = claims.get("exact_route")
        exact_word = self.check_tagged_exact(exact) if exact is not None else None
        enc_word = None
        enc_claim = get(claims, "enclosures", "claims")
        if enc_claim == "PROVED":
            self.check_tagged_proof(claims)
            enc_word = "PROVED"
        elif enc_claim == "DISPROVED":
            self.check_tagged_disproof()
            enc_word = "DISPROVED"
        if self.verdict == "PROVED" and "PROVED" not in (enc_word, exact_word):
            reject("PROVED, but neither route's proof is in the document")
        if self.verdict == "DISPROVED" and "DISPROVED" not in (enc_word, exact_word):
            reject("DISPROVED, but neither route's disproof is in the document")
        if self.verdict == "NOT PROVED":
            self.lines.append("  --  NOT PROVED: nothing to re-check")

    def crease_inside(self, part):
        """For each point of a crease:K document, the side it lies strictly
        inside (0: sectors 0..K-1, 1: the rest) or None on the crease curve
        (the centre and the 'edge' points of rays 0 and K), from the labels."""
        tag = get(part, "tag", "tagged")
        if not isinstance(tag, str) or not tag.startswith("crease:"):
            reject(f"a per-side verdict at a {tag!r} vertex")
        try:
            at = int(tag.split(":", 1)[1])
        except ValueError:
            raise Malformed(f"tag {tag!r}: the crease ray is not an integer")
        labels = as_list(get(part, "labels", "tagged"), "labels", self.size)
        inside = []
        for name in labels:
            if name == "centre":
                inside.append(None)
                continue
            m = re.fullmatch(r"(\w+)\[r(\d+),s(\d+),(\d+)\]", str(name))
            if m is None:
                raise Malformed(f"label {name!r} is not kind[rR,sS,I]")
            sector = int(m.group(3))
            on_sharp_ray = m.group(1) == "edge" and sector in (0, at)
            inside.append(None if on_sharp_ray else (0 if sector < at else 1))
        return labels, inside

    def check_crease_fallback(self, part, crease, decoupled):
        """A crease:K document says whose verdict it gives: 'verdict_of' is
        'sides' exactly when the sides decouple, else 'S whole' with the
        reason ('coupled'), the document's verdict then S whole's own. Where
        every row is exact, a fallback is re-derived here: the dependency
        closure, through the rows' non-zero entries, of the points strictly
        inside each side must reach a point strictly inside the other (or a
        side has no such point); sides that decouple must not be given S
        whole's verdict."""
        if not isinstance(crease, dict):
            raise Malformed("the crease part is not an object")
        verdict_of = get(crease, "verdict_of", "crease")
        want = "sides" if decoupled else "S whole"
        if verdict_of != want:
            reject(f"the crease's verdict is of {verdict_of!r}, but the document's sides {'decouple' if decoupled else 'do not decouple'}")
        if decoupled:
            return
        why = crease.get("coupled")
        if not isinstance(why, str) or not why.strip():
            reject("the crease's sides do not decouple and the document gives no reason")
        if get(crease, "whole_verdict", "crease") != self.verdict:
            reject("the sides do not decouple, but the document's verdict is not S whole's")
        if not get(part, "exact", "tagged"):
            self.lines.append(f"  --  crease: S whole's verdict (the sides do not decouple: {why}); not re-derived, the rows are not all exact")
            return
        labels, inside = self.crease_inside(part)
        seeds = [[p for p, w in enumerate(inside) if w == k] for k in (0, 1)]
        crosses = None
        if all(seeds):
            for k in (0, 1):
                seen, todo = set(seeds[k]), list(seeds[k])
                while todo:
                    a = todo.pop()
                    for b in self.rows[a]:  # the non-zero entries only
                        if b not in seen:
                            seen.add(b)
                            todo.append(b)
                hit = next((p for p in sorted(seen) if inside[p] == 1 - k), None)
                if hit is not None:
                    crosses = f"side {k}'s closure reaches {labels[hit]}"
                    break
            if crosses is None:
                reject("the document gives S whole's verdict, but the sides decouple (their closures, re-derived from the rows, stay apart)")
        else:
            crosses = "a side has no point strictly inside it"
        self.ok(f"crease: the sides do not decouple ({crosses}, re-derived from the exact rows): S whole's verdict {self.verdict}")

    def check_crease_sides(self, part, crease, word):
        """The per-side verdict of a crease:K vertex. Each side's points are
        re-derived from the labels (sector s between rays s and s + 1; an
        'edge' point lies on ray s; the curve is the centre and the points on
        rays 0 and K): a side's set must hold every point strictly inside it
        and none strictly inside the other side, and no row of it may read a
        column outside it (exactly, on the rows above). Each side's rows are
        then the principal submatrix, rebuilt here, and its certificate is
        re-checked like a whole one; the crease's verdict is PROVED iff both
        sides are, DISPROVED iff one is."""
        labels, inside = self.crease_inside(part)
        sides = as_list(get(crease, "sides", "crease"), "sides")
        if len(sides) != 2:
            reject(f"a crease has two sides, the document lists {len(sides)}")
        words = []
        raw_rows = as_list(get(part, "rows", "tagged"), "rows", self.size)
        for k, side in enumerate(sides):
            idx = [as_int(x, "side index", self.size) for x in as_list(get(side, "indices", "side"), "indices")]
            if idx != sorted(set(idx)):
                reject(f"side {k}: indices not strictly ascending")
            members = set(idx)
            for p, where in enumerate(inside):
                if where == k and p not in members:
                    reject(f"side {k} misses {labels[p]}, a point strictly inside it")
                if where == 1 - k and p in members:
                    reject(f"side {k} holds {labels[p]}, a point strictly inside the other side")
            for a in idx:
                for b in self.rows[a]:
                    if b not in members:
                        reject(f"side {k} is not invariant: the row of {labels[a]} reads {labels[b]} outside it")
            pos = {b: i for i, b in enumerate(idx)}
            sub = dict(side)
            sub["rows"] = [[[pos[e[0]], e[1]] for e in raw_rows[a] if e[0] in pos] for a in idx]
            sub["exact"] = True
            sub["inexact_rows"] = []
            sub["size"] = len(idx)
            checker = Checker(self.doc)
            checker.tagged(sub)
            self.lines.extend(f"  {line}" for line in checker.lines)
            self.ok(f"side {k} ({side.get('name')}): invariant, exactly; its certificate re-checked: {checker.verdict}")
            words.append(checker.verdict)
        want = "DISPROVED" if "DISPROVED" in words else "PROVED" if words == ["PROVED", "PROVED"] else "NOT PROVED"
        if word != want:
            reject(f"the sides' verdicts {words} make the crease {want}, the document claims {word}")
        self.ok(f"crease per side: {want} (S whole, not the crease's criterion: {self.verdict})")

    def reflection_block(self, m):
        """E (m = 0) or O (m = 1) from the exact rows: E[a][b] = S[a][b] + S[a][Pb]
        (S[a][b] where Pb = b), O[a][b] = S[a][b] − S[a][Pb], as balls."""
        p, n = self.reflection, self.size
        order = [b for b in range(n) if (b <= p[b] if m == 0 else b < p[b])]
        pos = {b: i for i, b in enumerate(order)}
        k = len(order)
        mr = [[0] * k for _ in range(k)]
        rr = [[0] * k for _ in range(k)]
        for i, a in enumerate(order):
            for c, x in self.rows[a].items():
                vm, vr = self.field.value(x)
                if c in pos:
                    mr[i][pos[c]] += vm
                    rr[i][pos[c]] += vr
                if p[c] != c and p[c] in pos:
                    # column b = Pc receives S[a][Pb] = S[a][c], with the block's sign
                    mr[i][pos[p[c]]] += vm if m == 0 else -vm
                    rr[i][pos[p[c]]] += vr
        zero = [[0] * k for _ in range(k)]
        return order, (mr, [r[:] for r in zero], rr, [r[:] for r in zero])

    def tagged_component(self, claim, what):
        if claim is None:
            reject(f"PROVED by the enclosures names no {what}")
        m = as_int(get(claim, "block", what), f"{what} block")
        i = as_int(get(claim, "component", what), f"{what} component")
        if m not in self.components or i >= len(self.components[m]):
            reject(f"{what}: no component {i} in block {m}")
        return m, i

    def check_tagged_proof(self, claims):
        """Lemma T4 on the discs recomputed above."""
        named = {w: self.tagged_component(claims.get(w), w) for w in ("lambda0", "lambda1", "lambda2")}
        if len(set(named.values())) != 3:
            reject("λ0, λ1 and λ2 must be three different components")
        one = Fraction(1)
        (m0, i0) = named["lambda0"]
        c0 = self.components[m0][i0]
        if len(c0) != 1 or not holds(c0[0], one):
            reject("λ0's component is not a single disc holding 1")
        for m, comps in self.components.items():
            for i, c in enumerate(comps):
                if (m, i) != (m0, i0) and any(holds(d, one) for d in c):
                    reject(f"block {m} component {i} may hold 1 too: λ0 = 1 is not separated")
        lams = []
        for w in ("lambda1", "lambda2"):
            m, i = named[w]
            c = self.components[m][i]
            if len(c) != 1:
                reject(f"{w}'s component holds {len(c)} eigenvalues")
            d = c[0]
            mirror = Disc(d.re, -d.im, d.r)
            if not meets_real_axis(d) or any(not disjoint(mirror, o) for j, oc in enumerate(self.components[m]) if j != i for o in oc):
                reject(f"{w} is not shown real (its mirror image meets another component of block {m})")
            # every real point of the disc is > 0: re > 0 and r² − im² < re²
            if not (d.re > 0 and d.r * d.r - d.im * d.im < d.re * d.re):
                reject(f"{w} is not shown positive")
            if not mod_separated(c0[0], d):
                reject(f"{w} is not shown below λ0 = 1")
            lams.append(d)
        for m, comps in self.components.items():
            for i, c in enumerate(comps):
                if (m, i) in named.values():
                    continue
                for o in c:
                    if not all(mod_separated(d, o) for d in lams):
                        reject(f"block {m} component {i} is not shown below λ2 in modulus")
        self.ok("PROVED by the enclosures (lemma T4): λ0 = 1 alone and simple, λ1 and λ2 single real positive "
                "eigenvalues below it, every other disc below both in modulus")

    def check_tagged_disproof(self):
        """Lemma T4's disproofs, found on the discs recomputed above (the
        document names no witness; nothing is taken from it but the discs,
        each checked to hold its Gershgorin disc, and their components,
        checked disjoint: a component of k discs holds exactly k eigenvalues).
        (1) A component whose every disc lies outside the closed unit disc
        holds an eigenvalue of modulus > 1. (2) Otherwise, with λ0's
        component the only one that may hold 1 (one disc), two one-disc
        components A and B whose discs lie above every disc of every other
        component in modulus hold the two eigenvalues of largest modulus
        after λ0; if one of them is proved not real (its disc misses the
        axis) or real (the mirror test of the proof) and negative, λ1 and λ2
        are not both real and positive."""
        one = Fraction(1)
        unit = Disc(1, 0, 0)
        everything = [(m, i, c) for m, comps in self.components.items() for i, c in enumerate(comps)]
        for m, i, c in everything:
            if c and all(mod_separated(d, unit) for d in c):
                self.ok(f"DISPROVED by the enclosures (lemma T4): block {m} component {i} ({len(c)} eigenvalue(s)) "
                        "lies outside the closed unit disc")
                return
        holding = [(m, i) for m, i, c in everything if any(holds(d, one) for d in c)]
        if len(holding) != 1 or len(self.components[holding[0][0]][holding[0][1]]) != 1:
            reject(f"DISPROVED by the enclosures, but {len(holding)} components may hold 1 (λ0 not separated) and "
                   "none lies outside the unit disc")
        rest = [(m, i, c) for m, i, c in everything if (m, i) != holding[0]]
        # for each one-disc component, the others not wholly below it in modulus
        not_below = {}
        for m, i, c in rest:
            if len(c) == 1:
                not_below[(m, i)] = {(m2, i2) for m2, i2, c2 in rest
                                     if (m2, i2) != (m, i) and not all(mod_separated(c[0], o) for o in c2)}

        def real(m, i, d):
            mirror = Disc(d.re, -d.im, d.r)
            return meets_real_axis(d) and all(disjoint(mirror, o) for j, oc in enumerate(self.components[m])
                                              if j != i for o in oc)

        for a, above_a in not_below.items():
            for b, above_b in not_below.items():
                if a >= b or not above_a <= {b} or not above_b <= {a}:
                    continue
                for (m, i) in (a, b):
                    d = self.components[m][i][0]
                    if not meets_real_axis(d):
                        self.ok(f"DISPROVED by the enclosures (lemma T4): the two leading eigenvalues after λ0 are "
                                f"single and separated; the one in block {m} component {i} is not real")
                        return
                    # real, and every real point of its disc < 0
                    if real(m, i, d) and d.re < 0 and d.r * d.r - d.im * d.im < d.re * d.re:
                        self.ok(f"DISPROVED by the enclosures (lemma T4): the two leading eigenvalues after λ0 are "
                                f"single and separated; the one in block {m} component {i} is real and negative")
                        return
        reject("DISPROVED by the enclosures, but no disproof of lemma T4 is found on the recomputed discs")

    def check_tagged_exact(self, claim):
        """Lemma T7 recomputed from the rows: this checker's characteristic
        polynomials (determinants at 0..N, Newton interpolation), ranks and
        counting Schur–Cohn."""
        if self.field.order != 1:
            reject("the exact route claims S over Q, but the rows lie in a larger field")
        dense = self.exact_matrix()
        n = self.size
        blocks = [dense]
        if self.reflection is not None:
            p = self.reflection
            blocks = []
            for m in (0, 1):
                order = [b for b in range(n) if (b <= p[b] if m == 0 else b < p[b])]
                blk = [[dense[a][b] if p[b] == b else dense[a][b] + (1 if m == 0 else -1) * dense[a][p[b]] for b in order] for a in order]
                blocks.append(blk)
        poly = [Fraction(1)]
        for blk in blocks:
            cp = charpoly_by_interpolation(blk)
            prod = [Fraction(0)] * (len(poly) + len(cp) - 1)
            for i, x in enumerate(poly):
                for j, y in enumerate(cp):
                    prod[i + j] += x * y
            poly = prod
        m1, p1 = root_multiplicity(poly, Fraction(1))
        if m1 != as_int(get(claim, "one_multiplicity", "exact route"), "one_multiplicity"):
            reject(f"1 has multiplicity {m1}, not the claimed {claim['one_multiplicity']}")
        word = get(claim, "verdict", "exact route")
        if m1 >= 2:
            verdict = "DISPROVED"
        elif claim.get("r") is None:
            verdict = "NOT PROVED"
        else:
            r = as_ratio(claim["r"], "r")
            m, q = root_multiplicity(p1, r)
            c = count_above(q, r)
            if c is None:
                reject(f"the count of eigenvalues above {r} in modulus is not decided here")
            geo = n - sum(rank([[blk[i][j] - (r if i == j else 0) for j in range(len(blk))] for i in range(len(blk))]) for blk in blocks)
            if (m, c) != (claim.get("algebraic"), claim.get("above")):
                reject(f"r = {r}: multiplicity {m} and {c} above it, not the claimed {claim.get('algebraic')} and {claim.get('above')}")
            if (c, m) == (0, 2):
                verdict = "PROVED" if geo == 2 else "DISPROVED"
                if geo != claim.get("geometric"):
                    reject(f"r = {r}: geometric multiplicity {geo}, not the claimed {claim.get('geometric')}")
            elif m >= 2 and c <= 1:
                verdict = "DISPROVED"
            elif (c, m) == (1, 1):
                at_r = sum(x * r**k for k, x in enumerate(q))
                mu_above = (at_r > 0) != (q[-1] > 0)
                above_one = count_above(q, Fraction(1))
                if not mu_above:
                    verdict = "DISPROVED"
                elif above_one == 0:
                    verdict = "PROVED"
                elif above_one is None:
                    verdict = "NOT PROVED"
                else:
                    verdict = "DISPROVED"
            else:
                verdict = "NOT PROVED"
        if verdict != word:
            reject(f"the exact route recomputed here gives {verdict}, the document claims {word}")
        self.ok(f"exact route (lemma T7) recomputed over Q from the rows: {verdict}")
        return verdict

    # -- the verdict

    def named(self, claim, what):
        if claim is None:
            reject(f"the verdict names no {what}")
        m = as_int(get(claim, "block", what), f"{what} block")
        i = as_int(get(claim, "component", what), f"{what} component")
        if m not in self.components:
            reject(f"{what}: block {m} has no enclosure")
        if i >= len(self.components[m]):
            reject(f"{what}: block {m} has no component {i}")
        return m, i

    def check_verdict(self, part):
        claims = get(part, "claims", "spectrum")
        margins = get(part, "margins", "spectrum")
        if self.verdict == "PROVED":
            self.check_proof(claims, margins)
        elif self.verdict == "DISPROVED":
            route = claims.get("exact_route") if isinstance(claims, dict) else None
            if route is not None:
                self.check_exact_disproof(route)
            else:
                self.check_disproof(claims)
        else:
            self.ok("verdict NOT PROVED: nothing claimed beyond the enclosures above")

    def check_proof(self, claims, margins):
        route = claims.get("exact_route") if isinstance(claims, dict) else None
        if route is not None:
            return self.check_exact_route(route, margins)
        if self.method != "dft":
            reject("PROVED on the whole matrix: λ1's realness and its two Fourier blocks need the rotation symmetry")
        g = self.g
        if g < 3:
            reject(f"PROVED with a rotation group of order {g}: blocks 1 and g − 1 must differ")
        self.need("row sums", "rotation", "mirror")
        m0, i0 = self.named(get(claims, "lambda0", "claims"), "λ0's component")
        if m0 != 0:
            reject("λ0's component is not in block 0")
        c0 = self.components[0][i0]
        if not any(holds(d, Fraction(1)) for d in c0):
            reject("λ0's component does not hold 1")
        if len(c0) != 1:
            reject(f"λ0's component holds {len(c0)} eigenvalues: λ0 = 1 is not shown simple")
        lam0_lo = min(d.re - d.r for d in c0)
        self.ok("λ0 = 1: block 0's named component holds 1 and exactly one eigenvalue")
        l1 = get(claims, "lambda1", "claims")
        if l1 is None:
            reject("the verdict names no λ1 components")
        l1 = as_list(l1, "claims.lambda1", 2)
        named1 = [self.named(l1[0], "λ1's component in block 1"), self.named(l1[1], "λ1's component in block g − 1")]
        if [m for m, _ in named1] != [1, g - 1]:
            reject(f"λ1's components are in blocks {[m for m, _ in named1]}, not 1 and {g - 1}")
        lows, highs = [], []
        for m, i in named1:
            c = self.components[m][i]
            if len(c) != 1:
                reject(f"λ1's component in block {m} holds {len(c)} eigenvalues: not simple")
            if not any(meets_real_axis(d) for d in c):
                reject(f"λ1's component in block {m} misses the real axis")
            mirror = [Disc(d.re, -d.im, d.r) for d in c]
            for j, other in enumerate(self.components[m]):
                if j != i and not all(disjoint(a, b) for a in mirror for b in other):
                    reject(f"the mirror image of λ1's component in block {m} meets its component {j}: realness not shown")
            lo = min(d.re - d.r for d in c)  # the real part's lower bound, not a modulus bound
            hi = max(d.re + d.r for d in c)
            if not lo > 0:
                reject(f"λ1 in block {m} is not shown positive: its real part may be as low as {float(lo):.6e}")
            if not hi < lam0_lo:
                reject(f"λ1 in block {m} is not shown below λ0's enclosure")
            lows.append(lo)
            highs.append(hi)
        lam1_lo = min(lows)
        self.lambda1_named = named1
        self.ok(
            f"λ1: simple in blocks 1 and {g - 1}, real (its component meets the real axis, its mirror image no other "
            f"component), {float(lam1_lo):.12f} ≤ λ1 ≤ {float(max(highs)):.12f}, below λ0"
        )
        # lemma S6: blocks whose eigenvalues are bounded by ‖B^k‖∞^(1/k)
        # instead of their discs (recomputed here from the rows)
        self.powers = self.check_power_bounds(claims, self.components[1][named1[0][1]])
        uncovered = [m for m in self.failed if m not in self.powers]
        if uncovered:
            reject(f"PROVED while block(s) {uncovered} have no enclosure (no discs, no lemma S6 bound)")
        special = {(0, i0)} | set(named1)
        worst = None
        for m, comps in self.components.items():
            if m in self.powers:
                continue
            for i, c in enumerate(comps):
                if (m, i) in special:
                    continue
                for d in c:
                    if not mod_below(d, lam1_lo):
                        reject(f"block {m}, component {i}: an eigenvalue may reach λ1's modulus (gap not shown)")
                    worst = d if worst is None or d.norm2() + d.r * d.r > worst.norm2() + worst.r * worst.r else worst
        self.ok(
            f"gap: every other component of every block{' not bounded by lemma S6' if self.powers else ''} lies "
            f"strictly inside |z| < {float(lam1_lo):.12f}"
        )
        self.check_margins(margins, c0, [self.components[m][i] for m, i in named1], special)

    def exact_matrix(self):
        if self.field.order != 1:
            reject("the exact route needs every entry of S in Q")
        n = self.size
        dense = [[Fraction(0)] * n for _ in range(n)]
        for i, row in enumerate(self.rows):
            for j, x in row.items():
                dense[i][j] = x[0] if x else Fraction(0)
        return dense

    def check_exact_route(self, route, margins):
        """Lemma S7, PROVED: S over Q; det(xI − S) recomputed here (by values
        at N + 1 points and interpolation, not subdlab's Hessenberg
        reduction); 1 a simple root; λ1 a root of multiplicity 2 whose
        eigenspace has dimension 2; the rest inside |x| < others_below ≤ λ1
        (Schur–Cohn)."""
        if route.get("proved") is not True:
            reject("a PROVED verdict whose exact route is not a proof")
        lam = as_ratio(get(route, "lambda1", "exact_route"), "exact_route.lambda1")
        below = as_ratio(get(route, "others_below", "exact_route"), "exact_route.others_below")
        if not (0 < lam < 1):
            reject(f"the exact route's λ1 = {lam} is not in (0, 1)")
        if not (0 <= below <= lam):
            reject(f"the exact route's bound {below} for the other eigenvalues is not in [0, λ1]")
        dense = self.exact_matrix()
        n = self.size
        p = charpoly_by_interpolation(dense)
        m1, p1 = root_multiplicity(p, Fraction(1))
        if m1 != 1:
            reject(f"1 is a root of det(xI − S) of multiplicity {m1}, not 1")
        m2, q = root_multiplicity(p1, lam)
        if m2 != 2:
            reject(f"λ1 = {lam} is a root of det(xI − S) of multiplicity {m2}, not 2")
        shifted = [[dense[i][j] - (lam if i == j else 0) for j in range(n)] for i in range(n)]
        geometric = n - rank(shifted)
        if geometric != 2:
            reject(f"the eigenspace of λ1 = {lam} has dimension {geometric}, not 2 (defective or larger)")
        if not roots_inside(q, below if below > 0 else lam):
            reject(f"an eigenvalue other than 1 and λ1 may have modulus ≥ {below}")
        self.ok(
            f"exact route: det(xI − S) of degree {n} recomputed over Q; 1 simple; λ1 = {lam} of multiplicity 2, "
            f"eigenspace of dimension 2; the other {len(q) - 1} roots inside |x| < {below if below > 0 else lam} (Schur–Cohn)"
        )
        if isinstance(margins, dict):
            l1 = margins.get("lambda1")
            if l1 is not None and not (Fraction(as_float(l1["lo"], "λ1.lo")) <= lam <= Fraction(as_float(l1["hi"], "λ1.hi"))):
                reject("margin: the claimed λ1 enclosure misses the exact λ1")
            others = margins.get("others_max_modulus")
            if others is not None and Fraction(as_float(others, "others_max_modulus")) < below:
                reject("margin: the claimed bound on the other eigenvalues is below the proved one")

    def check_exact_disproof(self, route):
        """Lemma S7, DISPROVED: 1 a root of multiplicity ≥ 2; or 1 simple and
        λ1 a root with every root other than 1 and λ1 inside |x| < λ1
        (Schur–Cohn on the cofactor of (x − λ1)^m), of multiplicity m ≠ 2 or
        with an eigenspace of dimension ≠ 2. Recomputed from the rows."""
        if route.get("proved") is not False:
            reject("a DISPROVED verdict whose exact route is not a disproof")
        dense = self.exact_matrix()
        n = self.size
        p = charpoly_by_interpolation(dense)
        m1, p1 = root_multiplicity(p, Fraction(1))
        if m1 != as_int(get(route, "one_multiplicity", "exact_route"), "one_multiplicity"):
            reject(f"1 is a root of det(xI − S) of multiplicity {m1}, not the claimed one")
        if m1 >= 2:
            self.ok(f"exact route: det(xI − S) of degree {n} recomputed over Q; 1 is a root of multiplicity {m1}: λ0 = 1 is not simple")
            return
        if m1 == 0:
            reject("1 is not a root of det(xI − S): the exact route claims nothing about it")
        lam = as_ratio(get(route, "lambda1", "exact_route"), "exact_route.lambda1")
        if not (0 < lam < 1):
            reject(f"the exact route's λ1 = {lam} is not in (0, 1)")
        m, q = root_multiplicity(p1, lam)
        if m == 0 or m != as_int(get(route, "algebraic", "exact_route"), "algebraic"):
            reject(f"λ1 = {lam} is a root of multiplicity {m}, not the claimed one")
        if not roots_inside(q, lam):
            reject(f"a root other than 1 and λ1 = {lam} may have modulus ≥ λ1: λ1 is not shown dominant")
        shifted = [[dense[i][j] - (lam if i == j else 0) for j in range(n)] for i in range(n)]
        geometric = n - rank(shifted)
        if geometric != as_int(get(route, "geometric", "exact_route"), "geometric"):
            reject(f"the eigenspace of λ1 = {lam} has dimension {geometric}, not the claimed one")
        if m == 2 and geometric == 2:
            reject(f"λ1 = {lam} is a double semisimple eigenvalue: nothing is disproved")
        self.ok(
            f"exact route: det(xI − S) of degree {n} recomputed over Q; 1 simple; λ1 = {lam} dominant (the other "
            f"{len(q) - 1} roots inside |x| < {lam}), algebraic multiplicity {m}, geometric {geometric}: not a double "
            "semisimple eigenvalue"
        )

    def check_power_bounds(self, claims, c1):
        """Lemma S6 re-derived: for each claimed block m (never 0, 1 or g − 1,
        whose spectral radius is λ0's or λ1's own), ρ(B_m)^k ≤ ‖B_m^k‖∞ for
        every induced norm and k ≥ 1. Here B_m is rebuilt from the rows,
        divided by the claimed lower bound ℓ of λ1 (checked against λ1's
        component c1, in block 1: λ1 is real and positive, shown above, so
        λ1 = |λ1| ≥ ℓ when every point of c1 has modulus ≥ ℓ), squared s times
        (k = 2^s) in ball arithmetic: ‖(B_m/ℓ)^k‖∞ < 1 gives ρ(B_m) < ℓ ≤ λ1.
        Dividing by ℓ first keeps the powers near 1 on the 2^-P grid. Returns
        {block: claimed radius} (each checked: radius^k ≥ claimed norm ≥ the
        recomputed bound of ‖B_m^k‖∞)."""
        recs = claims.get("power_bounds") if isinstance(claims, dict) else None
        out, used = {}, []
        if recs is None:
            return out
        g = self.g
        for rec in as_list(recs, "claims.power_bounds"):
            m = as_int(get(rec, "block", "power bound"), "power bound block")
            if m in (0, 1, g - 1) or m >= g:
                reject(f"lemma S6 is claimed for block {m}, which holds λ0 or λ1 (or does not exist): its spectral radius separates nothing")
            if m in out:
                reject(f"lemma S6 is claimed twice for block {m}")
            k = as_int(get(rec, "k", f"block {m} power bound"), f"block {m} k")
            if k < 1 or k & (k - 1) or k > 1 << 16:
                reject(f"block {m}: lemma S6's power k = {k} is not a power of two up to 2^16")
            norm = Fraction(as_float(get(rec, "norm", f"block {m} power bound"), f"block {m} norm"))
            radius = Fraction(as_float(get(rec, "radius", f"block {m} power bound"), f"block {m} radius"))
            ell = Fraction(as_float(get(rec, "lambda1_lower", f"block {m} power bound"), f"block {m} lambda1_lower"))
            if not (ell > 0 and all(mod_from(d, ell) for d in c1)):
                reject(f"block {m}: lemma S6 compares with λ1 ≥ {float(ell):.12f}, which λ1's component does not show")
            _, a = self.block_matrix(m)
            a = scale_matrix(1 / ell, a)
            for _ in range(k.bit_length() - 1):
                a = cmatmul(a, a)
            kk = len(a[0])
            scaled = max(
                (sum(mag(a[0][i][j], a[1][i][j], a[2][i][j], a[3][i][j]) for j in range(kk)) for i in range(kk)),
                default=0,
            )
            if scaled >= UNIT:
                reject(
                    f"block {m}: ‖(B/ℓ)^{k}‖∞ ≤ {scaled / UNIT:.6e} is not below 1 (ℓ = {float(ell):.12f} ≤ λ1): "
                    f"lemma S6 does not clear λ1"
                )
            bound = Fraction(scaled, UNIT) * ell**k  # ≥ ‖B^k‖∞
            if norm < bound:
                reject(f"block {m}: the claimed ‖B^{k}‖∞ ≤ {float(norm):.6e} is below the recomputed bound {float(bound):.6e}")
            if not norm < ell**k:
                reject(f"block {m}: the claimed ‖B^{k}‖∞ ≤ {float(norm):.6e} does not clear λ1^{k} ≥ {float(ell**k):.6e}")
            if radius**k < norm:
                reject(f"block {m}: the claimed radius {float(radius):.9f} is below ‖B^{k}‖∞^(1/{k})")
            out[m] = radius
            used.append(f"{m} (k = {k})")
        if out:
            self.ok(
                f"lemma S6, block(s) {', '.join(used)}: (B/ℓ)^k rebuilt from the rows by ball squarings has "
                "‖(B/ℓ)^k‖∞ < 1 for a lower bound ℓ of λ1, so ρ(B) < λ1"
            )
        return out

    def check_margins(self, margins, c0, c1s, special):
        """The claimed margins must be valid bounds of the enclosed values."""
        if not isinstance(margins, dict):
            raise Malformed("margins: not an object")
        l0 = margins.get("lambda0")
        if l0 is not None:
            lo, hi = Fraction(as_float(l0["lo"], "λ0.lo")), Fraction(as_float(l0["hi"], "λ0.hi"))
            if not lo <= 1 <= hi:
                reject("margin: the claimed λ0 enclosure misses 1")
        l1 = margins.get("lambda1")
        if l1 is not None:
            lo, hi = Fraction(as_float(l1["lo"], "λ1.lo")), Fraction(as_float(l1["hi"], "λ1.hi"))
            # λ1 is one real number, in both blocks: the tool bounds it with block 1's component
            for c in c1s[:1]:
                if not all(real_section_above(d, lo) and real_section_below(d, hi) for d in c):
                    reject("margin: the claimed λ1 enclosure does not hold the real points of λ1's component")
        others = margins.get("others_max_modulus")
        if others is not None:
            bound = Fraction(as_float(others, "others_max_modulus"))
            powers = getattr(self, "powers", {})
            for m, radius in powers.items():
                if radius > bound:
                    reject(f"margin: block {m}'s lemma S6 bound exceeds the claimed largest other modulus")
            for m, comps in self.components.items():
                if m in powers:
                    continue
                for i, c in enumerate(comps):
                    if (m, i) not in special and not all(mod_at_most(d, bound) for d in c):
                        reject(f"margin: block {m}, component {i} exceeds the claimed largest other modulus")
            gap = margins.get("gap_lower_bound")
            if gap is not None:
                t = Fraction(as_float(gap, "gap_lower_bound")) + bound
                for c in c1s[:1]:
                    if not all(t + d.r < 0 or d.norm2() >= (t + d.r) ** 2 for d in c):
                        reject("margin: the claimed gap exceeds λ1's lower modulus bound minus the others' upper one")
        self.ok("margins: the claimed λ0, λ1 enclosures, largest other modulus and gap are valid bounds")

    def no_candidate(self):
        """Lemma (no candidate), re-derived from the discs alone."""
        g = self.g
        block1 = self.components.get(1, [])
        pool = [
            c
            for m, comps in self.components.items()
            if m not in (1, g - 1)
            for c in comps
            if not (m == 0 and any(holds(d, Fraction(1)) for d in c))
        ]
        for i, c in enumerate(block1):
            if not any(meets_real_axis(d) and d.re + d.r > 0 for d in c):
                continue
            rivals = pool + [o for j, o in enumerate(block1) if j != i]
            if not any(all(mod_at_least(a, b) for a in o for b in c) for o in rivals):
                return False
        return True

    def check_disproof(self, claims):
        if self.method == "dft":
            self.need("rotation")  # the blocks' spectra are S's
        m, i = self.named(get(claims, "witness", "claims"), "witness")
        w = self.components[m][i]
        g = self.g if self.method == "dft" else 1
        # (a) an eigenvalue outside the unit disc
        if all(mod_above(d, Fraction(1)) for d in w):
            self.ok(f"witness: block {m}'s component {i} lies outside the unit disc (an eigenvalue of modulus > 1)")
            return
        if self.method != "dft" or g < 3:
            reject("DISPROVED: the witness is not outside the unit disc (the only disproof without blocks 1 and g − 1)")

        def dominates(others):
            return all(mod_separated(a, b) for a in w for c in others for b in c)

        if 1 not in self.components or g - 1 not in self.components:
            reject("DISPROVED: blocks 1 and g − 1 need enclosures for any other witness")
        # (c) no candidate: every component of block 1 that may hold a
        # positive real number is matched or exceeded in modulus by another
        # eigenvalue's enclosure (of block 1, or of a block other than 1 and
        # g − 1, and never a component of block 0 that may hold 1), so no
        # eigenvalue of block 1 is a dominant positive λ1
        if self.no_candidate():
            self.ok(
                "witness: every enclosure of block 1 that may hold a positive real number is outdone in modulus by "
                "another eigenvalue's: no dominant positive λ1 in block 1"
            )
            return
        # (b) eigenvalues outside blocks 1 and g − 1 above all of theirs
        if m not in (1, g - 1):
            self.need("row sums")  # 1 is block 0's: the witness is not λ0
            if m == 0 and any(holds(d, Fraction(1)) for d in w) and len(w) < 2:
                reject("DISPROVED: the witness may be λ0 = 1 itself")
            if dominates(self.components[1] + self.components[g - 1]):
                self.ok(
                    f"witness: block {m}'s component {i} ({len(w)} eigenvalue(s), none of them λ0) lies above every "
                    f"eigenvalue of blocks 1 and {g - 1} in modulus: the subdominant pair is not theirs"
                )
                return
            reject(f"DISPROVED: block {m}'s component {i} is not shown above every eigenvalue of blocks 1 and {g - 1}")
        # (c), (d) the leading eigenvalue of block 1 (or g − 1) is not real, or negative
        rest = [c for j, c in enumerate(self.components[m]) if j != i]
        if not dominates(rest):
            reject(f"DISPROVED: block {m}'s component {i} is not shown to lead its block")
        if all(not meets_real_axis(d) for d in w):
            self.ok(f"witness: the leading eigenvalue of block {m} (above the rest of its block) is not real")
            return
        if all(d.re + d.r < 0 for d in w):
            self.ok(f"witness: the leading eigenvalue of block {m} (above the rest of its block) has negative real part")
            return
        reject(f"DISPROVED: block {m}'s leading component {i} is neither off the real axis nor negative")

    # -- the characteristic map

    def charmap(self, part):
        """Re-check the geometric half of Reif's criterion from the spectral
        part's own block 1: the eigenvector enclosure, the exact refinement,
        every claimed Jacobian sign, the half-planes and the winding number."""
        what = "charmap"
        verdicts = {k: get(part, k, what) for k in ("regularity", "injectivity", "c1")}
        for k, v in verdicts.items():
            if v not in ("PROVED", "DISPROVED", "NOT PROVED"):
                raise Malformed(f"charmap: unknown {k} verdict {v!r}")
        if self.verdict != "PROVED":
            reject("a charmap part needs the spectrum PROVED: without a certified λ1 there is no map")
        levels = as_int(get(part, "levels", what), "charmap levels")
        x0 = self.eigenvector(get(part, "eigenvector", what))
        pts = self.refined_points(get(part, "points", what), x0)
        self.ok(f"net: {len(pts) - len(x0)} refined point(s) from the {len(x0)} analysis points by exact stencils "
                f"({levels} analysis steps), in interval arithmetic")
        self.regular_part = part.get("regular_part")
        self.lattice = None
        if self.regular_part == "difference-scheme":
            # lemma C9: the lattice constants re-derived from the document's
            # mask, windows and bases (DifferenceLattice)
            self.lattice = DifferenceLattice(get(part, "difference", what), self.lines)
        elif part.get("difference") is not None:
            raise Malformed(f"charmap: lemma C9 data, but the regular part is {self.regular_part!r}")
        sign = self.check_faces(as_list(get(part, "faces", what), "charmap faces"), pts, verdicts["regularity"])
        winding = get(part, "winding", what)
        number = None
        if winding is not None:
            number = self.check_winding(winding, pts)
        inj = verdicts["injectivity"]
        if inj == "PROVED":
            if verdicts["regularity"] != "PROVED" or number is None:
                reject("injectivity PROVED needs regularity PROVED and a winding number")
            if number != sign:
                reject(f"injectivity PROVED, but the winding number {number} is not the Jacobian's sign {sign}")
            self.ok(f"injectivity: regular with winding number {number} = the Jacobian's sign (Peters–Reif)")
        elif inj == "DISPROVED":
            if verdicts["regularity"] == "DISPROVED":
                self.ok("injectivity DISPROVED: the map is not regular")
            elif verdicts["regularity"] == "PROVED" and number is not None and number != sign:
                self.ok(f"injectivity DISPROVED: regular with winding number {number} ≠ ±1 of its sign")
            else:
                reject("injectivity DISPROVED without a fold or a winding number other than the Jacobian's sign")
        parts = [self.verdict, verdicts["regularity"], inj]
        want = "DISPROVED" if "DISPROVED" in parts else "NOT PROVED" if "NOT PROVED" in parts else "PROVED"
        if verdicts["c1"] != want:
            reject(f"the C¹ verdict {verdicts['c1']} does not follow from its parts ({', '.join(parts)}): {want}")
        self.ok(f"C¹ (Reif): {want}; trusted, not re-checked: " + "; ".join(as_list(get(part, "trusted", what), "trusted")))
        self.verdict = f"spectrum {self.verdict}, C¹ {want}"

    def eigenvector(self, claim):
        """λ1's eigenvector of block 1 enclosed from V and the discs
        recomputed here (discs::eigenvector's lemma), spread over the
        neighbourhood: balls (re, im) per matrix index."""
        m, ci = self.lambda1_named[0]
        rows = self.comp_rows[m][ci]
        if len(rows) != 1:
            reject("λ1's component in block 1 is not one disc")
        i = rows[0]
        if as_int(get(claim, "block", "eigenvector"), "eigenvector block") != 1 or get(claim, "disc", "eigenvector") != i:
            reject(f"the eigenvector is claimed for {claim}, but λ1's disc is row {i} of block 1")
        discs, need = self.discs[m], self.needs[m]
        k = len(discs)
        ci_re, ci_im = Fraction(discs[i].re), Fraction(discs[i].im)
        q = [Fraction(0)] * k
        for j in range(k):
            if j == i:
                continue
            d2 = (Fraction(discs[j].re) - ci_re) ** 2 + (Fraction(discs[j].im) - ci_im) ** 2
            # |c_j − c_i| from below at scale 2^-P, less the recomputed r_i
            lower = math.isqrt(math.floor(d2 * UNIT * UNIT)) - need[i]
            if lower <= 0:
                reject(f"the eigenvector is not enclosed: disc {i} (λ1) meets disc {j} of block 1")
            q[j] = Fraction(need[j], lower)
            if q[j] >= 1:
                reject(f"the eigenvector is not enclosed: q_{j} = r_{j}/(|c_{j} − c_{i}| − r_{i}) ≥ 1")
        vr, vi, vrr, vri = self.vmats[m]
        z = []
        for l in range(k):
            s = sum((mag(vr[l][j], vi[l][j], vrr[l][j], vri[l][j]) * q[j] for j in range(k) if j != i), Fraction(0))
            s = math.ceil(s)
            z.append(((vr[l][i], vrr[l][i] + s), (vi[l][i], vri[l][i] + s)))
        order = [o for o in range(len(self.rep)) if not self.fixed[o]]
        pos = {o: a for a, o in enumerate(order)}
        out = []
        for o, t in self.member:
            if self.fixed[o]:
                out.append(((0, 0), (0, 0)))
                continue
            (zr, zi) = z[pos[o]]
            cm, cr, sm, sr = cos_sin(t, self.g)
            c, s = (cm, cr), (sm, sr)
            re = ball_sub(ball_mul(zr, c, P), ball_mul(zi, s, P))
            im = ball_add(ball_mul(zr, s, P), ball_mul(zi, c, P))
            out.append((re, im))
        self.ok(f"eigenvector: block 1's disc {i} (λ1's), |y_j| ≤ q_j ≤ {float(max(q)):.3e} from the recomputed discs; "
                f"x_(t,a) = ω^t z_a over {len(out)} points")
        return out

    def refined_points(self, points, x0):
        n0 = as_int(get(points, "level0", "points"), "points.level0")
        if n0 != len(x0):
            reject(f"the net starts from {n0} points, the neighbourhood has {len(x0)}")
        pts = list(x0)
        raw = as_list(get(points, "stencils", "points"), "points.stencils")
        weights = {}
        orders = set()
        for st in raw:
            for e in as_list(st, "stencil"):
                w = as_list(e, "stencil term", 2)[1]
                if isinstance(w, dict):
                    orders.add(as_int(get(w, "order", "weight"), "weight order", MAX_FIELD + 1))
        field = Field(math.lcm(*orders)) if orders else None
        if field is not None and field.order > MAX_FIELD:
            reject(f"the stencils need Q(ζ_{field.order}), beyond Q(ζ_{MAX_FIELD})")
        sums = {}
        for n, st in enumerate(raw):
            re, im = (0, 0), (0, 0)
            # every rule reproduces constants: the weights sum to 1 exactly
            # (a consistency check; that they are the scheme's rules is trusted)
            total = ()
            for e in st:
                parent = as_int(e[0], "stencil parent", len(pts))  # only earlier points
                w = e[1]
                key = w if isinstance(w, str) else json.dumps(w, sort_keys=True)
                if key not in weights:
                    if isinstance(w, str):
                        weights[key] = as_ratio(w, "stencil weight")
                    elif isinstance(w, dict):
                        terms = tuple((as_int(t[0], "power"), as_ratio(t[1], "coefficient")) for t in get(w, "coefficients", "weight"))
                        x = field.element(as_int(w["order"], "order"), terms)
                        if not field.is_real(x):
                            reject(f"stencil {n}: a weight is not real")
                        weights[key] = field.value(x)
                    else:
                        raise Malformed("a stencil weight is neither 'p/q' nor a cyclotomic element")
                if key not in sums:
                    if isinstance(w, str):
                        q = as_ratio(w, "stencil weight")
                        sums[key] = (q,) if q else ()
                    else:
                        terms = tuple((as_int(t[0], "power"), as_ratio(t[1], "coefficient")) for t in w["coefficients"])
                        sums[key] = field.element(as_int(w["order"], "order"), terms)
                total = field.add(total, sums[key]) if field else _add_q(total, sums[key])
                wt = weights[key]
                pr, pi = pts[parent]
                if isinstance(wt, Fraction):
                    re = ball_add(re, scale_ball(wt, *pr))
                    im = ball_add(im, scale_ball(wt, *pi))
                else:
                    re = ball_add(re, ball_mul(wt, pr, P))
                    im = ball_add(im, ball_mul(wt, pi, P))
            if total != (Fraction(1),):
                reject(f"stencil {n}: its weights do not sum to 1")
            pts.append((re, im))
        return pts

    def check_faces(self, faces, pts, regularity):
        """Every claimed sign re-proved from det(u_i, v_j) over the window's
        edge vectors; returns the common sign (+1, −1) or None."""
        count = {"+": 0, "-": 0, "?": 0}
        self.windows = []
        # per window, the radius (scale 2^-P) by which its hull is enlarged:
        # 0 but for lemma C9's windows (the face's corners within δ)
        self.hull_radius = []
        lattice = self.lattice
        refined = 0
        worst = None
        for f, face in enumerate(faces):
            claim = get(face, "sign", "face")
            if claim not in count:
                raise Malformed(f"face {f}: sign {claim!r}")
            edges = []
            for name in ("u_edges", "v_edges"):
                vecs = []
                for e in as_list(get(face, name, "face"), f"face {f} {name}"):
                    a, b = (as_int(x, "edge point", len(pts)) for x in as_list(e, "edge", 2))
                    vecs.append((ball_sub(pts[b][0], pts[a][0]), ball_sub(pts[b][1], pts[a][1]), a, b))
                edges.append(vecs)
            us, vs = edges
            if not us or not vs:
                reject(f"face {f}: a window without edges along both directions")
            if self.regular_part == "non-box-s31":
                non_box_window(f, face, us, vs)
            elif "layout" in face:
                raise Malformed(f"face {f}: a lattice layout, but the regular part is {self.regular_part!r}")
            if lattice is None and "window" in face:
                raise Malformed(f"face {f}: a lemma C9 window, but the regular part is {self.regular_part!r}")
            if lattice is not None:
                # lemma C9: f(T) within δ = δ-factor·N(p) of the face's
                # control triangle (its three corners)
                vals, norm, corners = lattice.face(f, face, pts, us, vs)
                self.windows.append(set(corners))
                self.hull_radius.append(lattice.scaled_up(lattice.position_factor, norm))
            else:
                self.windows.append({p for e in us + vs for p in e[2:]})
                self.hull_radius.append(0)
            count[claim] += 1
            if claim == "?":
                continue
            if lattice is not None:
                # det(∂₁f, ∂₂f) over the face within ε(|u| + |v|) + ε² of
                # det(u, v), ε = ε-factor·N(p), refined where undecided
                lo, hi = lattice.jacobian(0, vals, 0)
                if not (lo > 0 or hi < 0) and lattice.depth:
                    lo, hi = lattice.jacobian(0, vals, lattice.depth)
                    refined += lo > 0 or hi < 0
            else:
                lo, hi = None, None
                for ux, uy, _, _ in us:
                    for vx, vy, _, _ in vs:
                        dm, dr = ball_sub(ball_mul(ux, vy, P), ball_mul(uy, vx, P))
                        lo = dm - dr if lo is None else min(lo, dm - dr)
                        hi = dm + dr if hi is None else max(hi, dm + dr)
            bound = "det(u_i, v_j)" if lattice is None else "its lemma C9 enclosure"
            if claim == "+" and not lo > 0:
                reject(f"face {f}: the Jacobian is claimed positive, but {bound} may be as low as {lo / UNIT:.3e}")
            if claim == "-" and not hi < 0:
                reject(f"face {f}: the Jacobian is claimed negative, but {bound} may be as high as {hi / UNIT:.3e}")
            margin = lo if claim == "+" else -hi
            worst = margin if worst is None else min(worst, margin)
        n = len(faces)
        if self.regular_part == "non-box-s31":
            self.ok(f"non-box S_3^1 windows: on each of the {n} faces the {len(NON_BOX_DIFFERENCES[0])} u- and "
                    f"{len(NON_BOX_DIFFERENCES[1])} v-differences and the {len(NON_BOX_HULL)} hull points re-derived "
                    "from the generators' supports are among the window's edges")
        if lattice is not None:
            self.ok(f"lemma C9 faces: each window is W_up at its layout's positions with the face's own u- and "
                    f"v-edge; Jacobian within ε(|u| + |v|) + ε² of det(u, v), ε = {float(lattice.edge_factor):.6g}·N(p) "
                    f"(N from the face's values), {refined} face(s) decided only by refining the window up to "
                    f"{lattice.depth} level(s) with the S_c")
        self.ok(f"Jacobian: {n} ring faces, {count['+']} proved > 0, {count['-']} proved < 0, {count['?']} not claimed "
                f"(least proved margin {float(Fraction(worst or 0, UNIT)):.3e})")
        if regularity == "PROVED":
            if n == 0 or count["?"] or (count["+"] and count["-"]):
                reject("regularity PROVED needs every ring face proved of one sign")
            self.ok("regularity: one sign on every ring face (the covering of the neighbourhood is trusted)")
            return 1 if count["+"] else -1
        if regularity == "DISPROVED":
            if not (count["+"] and count["-"]):
                reject("regularity DISPROVED needs one face proved positive and one proved negative")
            self.ok("regularity DISPROVED: faces of both proved signs")
        return None

    def check_winding(self, w, pts):
        what = "winding"
        wins = as_list(get(w, "windows", what), "winding windows")
        k = len(wins)
        if k < 3:
            reject(f"a winding chain of {k} edges")
        verts = as_list(get(w, "vertices", what), "winding vertices", k)
        dirs = as_list(get(w, "directions", what), "winding directions", k)
        poly = as_list(get(w, "polygon", what), "winding polygon", k)
        wins = [as_int(x, "chain window", len(self.windows)) for x in wins]
        d = [tuple(as_float(c, "direction") for c in as_list(x, "direction", 2)) for x in dirs]
        wp = [tuple(Fraction(as_float(c, "polygon point")) for c in as_list(x, "polygon point", 2)) for x in poly]
        for i in range(k):
            dx, dy = ball_of_float(d[i][0]), ball_of_float(d[i][1])
            # a hull enlarged by a radius ρ (lemma C9) lies in the half-plane
            # when every corner p has d·p − ρ|d| > 0
            rho = self.hull_radius[wins[i]]
            length = ceil_sqrt((abs(dx[0]) + dx[1]) ** 2 + (abs(dy[0]) + dy[1]) ** 2)
            slack = -((-rho * length) >> P)
            for p in sorted(self.windows[wins[i]]):
                m, r = ball_add(ball_mul(dx, pts[p][0], P), ball_mul(dy, pts[p][1], P))
                if not m - r - slack > 0:
                    reject(f"winding: a point of window {wins[i]} is not proved in its half-plane d_{i}·p > 0")
            v = as_int(verts[i], "chain vertex", len(pts))
            if v not in self.windows[wins[i]] or v not in self.windows[wins[(i + 1) % k]]:
                reject(f"winding: chain vertex {i + 1} is not a point of both windows beside it")
            for j in (i, (i + 1) % k):
                if not Fraction(d[j][0]) * wp[i][0] + Fraction(d[j][1]) * wp[i][1] > 0:
                    reject(f"winding: polygon point w_{i} is not in the half-plane H_{j}")
        number = winding_about_centre(wp)
        if number is None:
            reject("winding: an edge of the polygon passes through the centre")
        claimed = get(w, "number", what)
        if claimed != number:
            reject(f"winding: the polygon winds {number} time(s) about the centre, the document claims {claimed!r}")
        self.ok(f"winding: {k} half-planes hold their windows, each w_i lies in H_i ∩ H_(i+1); the polygon winds "
                f"{number} time(s), counted exactly")
        return number

    # -- the sector characteristic map at a boundary vertex (subdlab's
    #    certify::tagged_charmap, lemmas B1–B6)

    def sector(self, part):
        """Re-derive a PROVED sector map: λ1's and λ2's eigenvectors by
        Krawczyk's test on the reflection blocks rebuilt from the rows (B1),
        the normal coordinate's vanishing on the sharp curve by Sturm over Q
        (B2), the net by the exact stencils in interval arithmetic with the
        host's ghost points (2b − p for the bicubic B-spline, a + b − p for
        the quartic box spline) computed here (B3), every face's Jacobian sign
        from det(u_i, v_j) (B4), the tangent coordinate's monotonicity along
        the sharp rows (B5) and the doubled chain's winding number (B6)."""
        what = "sector"
        for key in ("regularity", "injectivity", "sector_criterion"):
            if get(part, key, what) != "PROVED":
                reject(f"a sector part is written for a PROVED sector map only, its {key} is {part[key]!r}")
        if self.verdict != "PROVED":
            reject(f"the sector map needs the tagged spectral part PROVED, it is {self.verdict}")
        claims = get(self.part, "claims", "tagged")
        if claims.get("enclosures") != "PROVED":
            reject("the sector map's eigenvectors are the enclosure route's λ1 and λ2, and that route did not prove the spectral part")
        if self.reflection is None:
            reject("the sector map needs the reflection keeping the sharp rays")
        n = self.size
        named = [self.tagged_component(claims.get(w), w) for w in ("lambda1", "lambda2")]
        eig = as_list(get(part, "eigenvectors", what), "eigenvectors", 2)
        vecs, mus = [], []
        for w, (m, ci), e in zip(("λ1", "λ2"), named, eig):
            if (get(e, "block", w), get(e, "component", w)) != (m, ci):
                reject(f"{w}'s eigenvector is given for block {e.get('block')} component {e.get('component')}, the spectral part names block {m} component {ci}")
            x, mu = self.krawczyk(m, ci, e, w)
            vecs.append(self.spread(m, x))
            mus.append((m, mu))
        self.ok("B1: λ1's and λ2's eigenvectors enclosed by Krawczyk's test (K(Y) ⊂ int Y) on the reflection blocks rebuilt "
                "from the rows, each eigenvalue inside its named disc; spread over S's points by the reflection")
        normal = {"lambda1": 0, "lambda2": 1}.get(get(part, "normal", what))
        if normal is None:
            raise Malformed(f"sector: normal {part['normal']!r} is neither 'lambda1' nor 'lambda2'")
        tangent = 1 - normal
        curve = [as_int(c, "curve point", n) for c in as_list(get(part, "curve", what), "curve")]
        self.sharp_curve_vanishing(curve, *mus[normal], ("λ1", "λ2")[normal])
        x0 = [(vecs[0][a], vecs[1][a]) for a in range(n)]
        for c in curve:
            xm, xr = x0[c][normal]
            if not xm - xr <= 0 <= xm + xr:
                reject(f"the eigenvector proved to vanish on the curve has an enclosure excluding 0 at point {c}")
            x0[c] = tuple((0, 0) if i == normal else x0[c][i] for i in (0, 1))
        levels = as_int(get(part, "levels", what), "sector levels")
        pts = self.refined_points(get(part, "points", what), x0)
        self.ok(f"net: {len(pts) - n} refined point(s) from the {n} analysis points by exact stencils ({levels} "
                "analysis steps), in interval arithmetic, the normal coordinate exactly 0 on the curve")
        on_line = lambda p: p[normal] == (0, 0)
        faces = as_list(get(part, "faces", what), "sector faces")
        if not faces:
            reject("no ring faces")
        windows, net_points, signs = [], [], []
        row_sign = None
        rows_seen = 0
        worst = None
        ghosts_total = 0
        # the host box spline of the windows (lemma B3): its lattice, the
        # face's corners, the window's positions and the ghost rule across a
        # sharp ray, all rebuilt here from the host's name
        host = get(part, "host", what)
        if host == "bicubic B-spline":
            steps = [(1, 0), (0, 1), (-1, 0), (0, -1)]
            corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
            want_positions = {(x, y) for x in range(-1, 3) for y in range(-1, 3)}
        elif host == "three-direction quartic box spline":
            # the third lattice direction is (−1, 1); the window of the face
            # (0,0), (1,0), (0,1) is its corners and their six neighbours each
            steps = [(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)]
            corners = [(0, 0), (1, 0), (0, 1)]
            want_positions = {(c[0] + e[0], c[1] + e[1]) for c in corners for e in steps + [(0, 0)]}
        else:
            raise Malformed(f"sector: host {host!r} is neither the bicubic B-spline nor the three-direction quartic box spline")
        for f, face in enumerate(faces):
            value, net, ghosts = {}, {}, {}
            for entry in as_list(get(face, "layout", "face"), f"face {f} layout"):
                entry = as_list(entry, f"face {f} layout entry")
                if len(entry) not in (3, 4, 5) or any(isinstance(v, bool) or not isinstance(v, int) for v in entry):
                    raise Malformed(f"face {f}: a layout entry is not [x, y, point], [x, y, b, p] or [x, y, a, b, p]")
                pos = (entry[0], entry[1])
                if pos in value:
                    reject(f"face {f}: position {pos} given twice")
                if len(entry) == 3:
                    q = as_int(entry[2], "window point", len(pts))
                    value[pos] = pts[q]
                    net[pos] = q
                    continue
                # the ghost rule across a sharp ray: a + b − p, a and b on
                # the ray ([x, y, b, p] is 2b − p: a = b)
                a, b, q = (as_int(v, "ghost point", len(pts)) for v in ([entry[2]] + entry[2:] if len(entry) == 4 else entry[2:]))
                if (len(entry) == 4) != (host == "bicubic B-spline"):
                    reject(f"face {f}: the ghost at {pos} is not the {host}'s ghost rule")
                if not (on_line(pts[a]) and on_line(pts[b])):
                    reject(f"face {f}: the ghost at {pos} reflects through a point not exactly on the rays' line")
                value[pos] = tuple(ball_sub(ball_add(pts[a][i], pts[b][i]), pts[q][i]) for i in (0, 1))
                ghosts[pos] = (a, b, q)
                ghosts_total += 1
            if set(value) != want_positions:
                reject(f"face {f}: the window is not the {host}'s {len(want_positions)} positions")
            # the ghost's points where the host puts them: bicubic, 2b − p
            # with b = q + e and p = q + 2e (a unit step e); quartic box,
            # a + b − p with a = q + d_i, b = q + d_(i+1) (a lattice triangle
            # with q) and p = a + b − q, the apex across the edge a–b
            for pos, (a, b, q) in ghosts.items():
                if host == "bicubic B-spline":
                    ok = a == b and any(net.get((pos[0] + ex, pos[1] + ey)) == b and net.get((pos[0] + 2 * ex, pos[1] + 2 * ey)) == q
                                        for ex, ey in steps)
                    rule = "2b − p of the net points one and two steps beside it"
                else:
                    ok = False
                    for i in range(6):
                        pa = (pos[0] + steps[i][0], pos[1] + steps[i][1])
                        pb = (pos[0] + steps[(i + 1) % 6][0], pos[1] + steps[(i + 1) % 6][1])
                        pp = (pa[0] + pb[0] - pos[0], pa[1] + pb[1] - pos[1])
                        if {net.get(pa), net.get(pb)} == {a, b} and None not in (net.get(pa), net.get(pb)) and net.get(pp) == q:
                            ok = True
                    rule = "a + b − p of a lattice edge a–b beside it and the apex p across that edge"
                if not ok:
                    reject(f"face {f}: the ghost at {pos} is not {rule}")
            if any(c not in net for c in corners):
                reject(f"face {f}: a corner of the face itself is a ghost")
            # the derivatives along the lattice's first two directions are
            # convex combinations of the window's differences along them
            us = [tuple(ball_sub(value[(x + 1, y)][i], value[(x, y)][i]) for i in (0, 1))
                  for (x, y) in sorted(want_positions) if (x + 1, y) in want_positions]
            vs = [tuple(ball_sub(value[(x, y + 1)][i], value[(x, y)][i]) for i in (0, 1))
                  for (x, y) in sorted(want_positions) if (x, y + 1) in want_positions]
            lo = hi = None
            for ux, uy in us:
                for vx, vy in vs:
                    dm, dr = ball_sub(ball_mul(ux, vy, P), ball_mul(uy, vx, P))
                    lo = dm - dr if lo is None else min(lo, dm - dr)
                    hi = dm + dr if hi is None else max(hi, dm + dr)
            claim = get(face, "sign", "face")
            if claim == "+" and lo > 0:
                signs.append(1)
                margin = lo
            elif claim == "-" and hi < 0:
                signs.append(-1)
                margin = -hi
            elif claim in ("+", "-"):
                reject(f"face {f}: the Jacobian is claimed {claim}, but det(u_i, v_j) over its window ranges over "
                       f"[{lo / UNIT:.3e}, {hi / UNIT:.3e}]")
            else:
                raise Malformed(f"face {f}: sign {claim!r}")
            worst = margin if worst is None else min(worst, margin)
            # B5: along each sharp row the normal coordinate is 0 and the
            # tangent one moves with one sign (in the face's orientation)
            for r in as_list(get(face, "rows", "face"), f"face {f} rows"):
                r = [tuple(as_list(c, "row position", 2)) for c in as_list(r, "row", 4)]
                row_steps = {(b[0] - a[0], b[1] - a[1]) for a, b in zip(r, r[1:])}
                if len(row_steps) != 1 or next(iter(row_steps)) not in steps:
                    reject(f"face {f}: a sharp row is not four window positions one lattice step apart")
                if any(c not in net for c in r):
                    reject(f"face {f}: a sharp row holds a position that is not a net point")
                for c in r:
                    if not on_line(value[c]):
                        reject(f"face {f}: a sharp row's point is not exactly on the rays' line")
                for a, b in zip(r, r[1:]):
                    dm, dr = ball_sub(value[b][tangent], value[a][tangent])
                    if not (dm - dr > 0 or dm + dr < 0):
                        reject(f"face {f}: the tangent coordinate's direction along a sharp row is undecided")
                    up = dm - dr > 0
                    if row_sign is None:
                        row_sign = up
                    elif row_sign != up:
                        reject("the two sharp rays' neighbourhoods are not shown to map to one side of the line")
                rows_seen += 1
            windows.append(list(value.values()))
            net_points.append(set(net.values()))
        if len(set(signs)) != 1:
            reject("regularity needs every ring face of one Jacobian sign")
        sign = signs[0]
        self.ok(f"B3/B4: {len(faces)} ring faces' windows of the {host} with {ghosts_total} ghost point(s) "
                f"{'2b − p' if host == 'bicubic B-spline' else 'a + b − p'} computed here (a, b exactly on the line); "
                f"every det(u_i, v_j) proved {'> 0' if sign > 0 else '< 0'} (least margin "
                f"{float(Fraction(worst, UNIT)):.3e})")
        if rows_seen == 0:
            reject("no sharp row: the rays' images are not checked")
        self.ok(f"B5: {rows_seen} sharp row(s) exactly on the line, the tangent coordinate strictly "
                f"{'increasing' if row_sign else 'decreasing'} along every one")
        number = self.doubled_winding(get(part, "chain", what), pts, windows, net_points, normal)
        if number != sign:
            reject(f"the doubled chain winds {number} time(s), not the Jacobian's sign {sign}")
        self.ok(f"B6: the doubled chain winds {number} time(s) = the Jacobian's sign (Peters–Reif); trusted, not "
                "re-checked: " + "; ".join(as_list(get(part, "trusted", what), "trusted")))
        self.verdict = f"tagged {self.verdict}, sector criterion PROVED"

    def krawczyk(self, m, ci, e, w):
        """Krawczyk's test for the simple eigenpair of block m with x_s = 1:
        F(x, μ) = B·x − μ·x, K(Y) = −R·F(ũ) + (I − R·J(ũ + Y))·Y over the
        block rebuilt from the rows; K(Y) ⊂ int Y proves one zero in ũ + K(Y)
        for every B in the interval block (any R). Returns x's balls and μ's
        enclosure (Fractions)."""
        order, (mr, _, rr, _) = self.reflection_block(m)
        k = len(order)
        a = [[(mr[i][j], rr[i][j]) for j in range(k)] for i in range(k)]
        s = as_int(get(e, "s", w), f"{w} s", k)
        xt = [ball_of_float(as_float(v, f"{w} x")) for v in as_list(get(e, "x", w), f"{w} x", k)]
        if xt[s] != (UNIT, 0):
            reject(f"{w}: the approximation's normalised entry x_s is not 1")
        mu = ball_of_float(as_float(get(e, "mu", w), f"{w} mu"))
        r = [[ball_of_float(as_float(v, f"{w} R")) for v in as_list(row, f"{w} R row", k)] for row in as_list(get(e, "r", w), f"{w} R", k)]
        y = []
        for v in as_list(get(e, "y", w), f"{w} y", k):
            ym, yr = ball_of_float(as_float(v, f"{w} y"))
            if not as_float(v, f"{w} y") > 0:
                reject(f"{w}: a radius of Y is not positive")
            # Y may be any box: at least 2^-(P-32), where the grid's own
            # rounding (one unit per product) cannot fill it
            y.append((0, max(ym + yr, 1 << 32)))

        def dot(xs, ys):
            mid = sum(p[0] * q[0] for p, q in zip(xs, ys))
            rad = sum(abs(p[0]) * q[1] + p[1] * abs(q[0]) + p[1] * q[1] for p, q in zip(xs, ys))
            return shift_ball(mid, rad, P)

        f = [ball_sub(dot(a[i], xt), ball_mul(mu, xt[i], P)) for i in range(k)]
        z = [(-bm, br) for bm, br in (dot(r[i], f) for i in range(k))]
        mu_y = ball_add(mu, y[s])
        jac = [[None] * k for _ in range(k)]
        for i in range(k):
            for l in range(k):
                if l == s:
                    jac[i][l] = (-UNIT, 0) if i == s else (-(xt[i][0] + y[i][0]), xt[i][1] + y[i][1])
                elif i == l:
                    jac[i][l] = ball_sub(a[i][l], mu_y)
                else:
                    jac[i][l] = a[i][l]
        cols = [[jac[i][l] for i in range(k)] for l in range(k)]
        kr = []
        for i in range(k):
            c_row = []
            for l in range(k):
                rm, rd = dot(r[i], cols[l])
                c_row.append(((UNIT if i == l else 0) - rm, rd))
            kr.append(ball_add(z[i], dot(c_row, y)))
        for i in range(k):
            if not (kr[i][0] - kr[i][1] > -y[i][1] and kr[i][0] + kr[i][1] < y[i][1]):
                reject(f"{w}: Krawczyk's test fails (K(Y) is not inside Y at entry {i}): the eigenvector is not enclosed")
        mu_m, mu_r = ball_add(mu, kr[s])
        lo, hi = Fraction(mu_m - mu_r, UNIT), Fraction(mu_m + mu_r, UNIT)
        discs = self.components[m][ci]
        if len(discs) != 1:
            reject(f"{w}'s component holds {len(discs)} discs")
        d = discs[0]
        far = max((lo - d.re) ** 2, (hi - d.re) ** 2)
        if not far + d.im * d.im < d.r * d.r:
            reject(f"{w}: the eigenvalue Krawczyk's test found is not inside the named disc")
        x = [(UNIT, 0) if i == s else ball_add(xt[i], kr[i]) for i in range(k)]
        return x, (lo, hi)

    def spread(self, m, x):
        """From block m's basis to S's points: even (m = 0) the same value at a
        point and its mirror, odd (m = 1) opposite values, 0 at an odd block's
        fixed points."""
        p, n = self.reflection, self.size
        order = [b for b in range(n) if (b <= p[b] if m == 0 else b < p[b])]
        if len(order) != len(x):
            reject("the eigenvector's size is not its block's")
        out = [(0, 0)] * n
        for i, b in enumerate(order):
            out[b] = x[i]
            if p[b] != b:
                out[p[b]] = x[i] if m == 0 else (-x[i][0], x[i][1])
        return out

    def sharp_curve_vanishing(self, curve, m, mu, w):
        """B2: the curve (holding the centre) is invariant under S and the
        reflection, exactly; the curve's block of the parity of w's block
        has no root of its characteristic polynomial in w's enclosure
        (Sturm over Q), so w's eigenvector vanishes on the curve."""
        if curve != sorted(set(curve)) or not curve:
            reject("the curve's points are not strictly ascending")
        labels = as_list(get(self.part, "labels", "tagged"), "labels", self.size)
        if not any(labels[c] == "centre" for c in curve):
            reject("the sharp curve does not hold the centre")
        members = set(curve)
        for a in curve:
            for b, x in self.rows[a].items():
                if b not in members:
                    reject(f"the sharp curve is not invariant: the row of {labels[a]} reads {labels[b]}")
                if len(x) > 1:
                    reject("a weight of the sharp curve's rows is not rational")
        p = self.reflection
        if any(p[c] not in members for c in curve):
            reject("the reflection does not keep the sharp curve")
        reps = [b for b in curve if (b <= p[b] if m == 0 else b < p[b])]
        q = lambda a, b: (self.rows[a].get(b) or (Fraction(0),))[0]
        blk = [[q(a, b) if p[b] == b else q(a, b) + (1 if m == 0 else -1) * q(a, p[b]) for b in reps] for a in reps]
        lo, hi = mu
        if blk:
            cp = charpoly_by_interpolation(blk)
            if poly_at(cp, lo) == 0 or sturm_count(cp, lo, hi) != 0:
                reject(f"{w}'s enclosure [{float(lo)}, {float(hi)}] may hold an eigenvalue of the sharp curve's "
                       f"{'even' if m == 0 else 'odd'} block: its eigenvector is not shown to vanish on the rays")
        self.ok(f"B2: the sharp curve ({len(curve)} points, the centre and both rays) invariant under S and the "
                f"reflection, exactly; its {'even' if m == 0 else 'odd'} block ({len(blk)}×{len(blk)}) has no eigenvalue in "
                f"{w}'s enclosure (Sturm over Q): {w}'s eigenvector vanishes on the rays, the normal coordinate")

    def doubled_winding(self, chain, pts, windows, net_points, normal):
        """B6: the chain from ray to ray and its mirror image in the rays'
        line (σ negates the normal coordinate), built here: every window of
        the chain in its half-plane, rigorously; every polygon point in the
        half-planes of the arcs beside it, exactly; the ends on the line; the
        doubled polygon's winding number counted exactly."""
        what = "chain"
        arcs = [as_int(a, "chain arc", len(windows)) for a in as_list(get(chain, "arcs", what), "chain arcs")]
        m = len(arcs)
        if m < 1:
            reject("an empty chain")
        verts = [as_int(v, "chain vertex", len(pts)) for v in as_list(get(chain, "vertices", what), "chain vertices", m + 1)]
        dirs = [tuple(Fraction(as_float(c, "direction")) for c in as_list(d, "direction", 2)) for d in as_list(get(chain, "directions", what), "chain directions", m)]
        poly = [tuple(Fraction(as_float(c, "polygon point")) for c in as_list(w, "polygon point", 2)) for w in as_list(get(chain, "polygon", what), "chain polygon", m + 1)]
        for i, v in enumerate(verts):
            for arc in ([i - 1] if i >= 1 else []) + ([i] if i < m else []):
                if v not in net_points[arcs[arc]]:
                    reject(f"chain vertex {i} is not a point of the window of arc {arc} beside it")
                if not dirs[arc][0] * poly[i][0] + dirs[arc][1] * poly[i][1] > 0:
                    reject(f"polygon point w_{i} is not in the half-plane of arc {arc}")
        for i in (0, m):
            if pts[verts[i]][normal] != (0, 0) or poly[i][normal] != 0:
                reject("an end of the chain is not exactly on the rays' line")
        for i, arc in enumerate(arcs):
            dx, dy = ball_of_float(float(dirs[i][0])), ball_of_float(float(dirs[i][1]))
            for p in windows[arc]:
                dm, dr = ball_add(ball_mul(dx, p[0], P), ball_mul(dy, p[1], P))
                if not dm - dr > 0:
                    reject(f"a point of arc {i}'s window is not proved in its half-plane d_{i}·p > 0")
        sigma = lambda w: tuple(-c if j == normal else c for j, c in enumerate(w))
        doubled = poly + [sigma(poly[i]) for i in range(m - 1, 0, -1)]
        number = winding_about_centre(doubled)
        if number is None:
            reject("an edge of the doubled polygon passes through the centre")
        claimed = get(chain, "number", what)
        if claimed != number:
            reject(f"the doubled polygon winds {number} time(s) about the centre, the document claims {claimed!r}")
        self.ok(f"B6: the chain's {m} windows in their half-planes, each w_i in the half-planes beside it, the ends on "
                f"the line; the polygon doubled here by the mirror winds {number} time(s), counted exactly")
        return number


def winding_about_centre(poly):
    """The winding number of the closed polygon `poly` (exact coordinates)
    about the origin, by signed crossings of the positive x-axis (an edge
    from y <= 0 to y > 0 counts +1 where it crosses at x > 0, the reverse
    -1); None when an edge that crosses the axis passes through the origin,
    where the number is not defined."""
    number = 0
    for i in range(len(poly)):
        (ax, ay), (bx, by) = poly[i], poly[(i + 1) % len(poly)]
        up, down = ay <= 0 < by, by <= 0 < ay
        if not (up or down):
            continue
        cross = ax * by - ay * bx
        if cross == 0:
            return None
        if up and cross > 0:
            number += 1
        elif down and cross < 0:
            number -= 1
    return number


# The non-box S_3^1 window (subdlab's lemma C3′), re-derived from the lattice
# positions the document gives, in half units: the face is [0, 2]², V-vertices
# at even, face control vertices (FCVs) at odd positions. In face units
# (half the half units) the basis of a V-vertex is the square hat φ_□
# (support |x|∞ ≤ 1/2) smoothed by the unit square χ, that of an FCV the
# diamond hat φ_◇ (|x|₁ ≤ 1) smoothed by χ; ∂_u f is the convex combination of
# the u-differences of points of one kind at distance 1, weighted by φ * χ^v
# (χ^v the unit segment along v) about their midpoints. What is positive on
# the face is decided from the open supports:
#   ψ_□ = φ_□ * χ^v:  |x1| < 1/2 and |x2| < 1
#   ψ_◇ = φ_◇ * χ^v:  |x1| + max(|x2| − 1/2, 0) < 1
#   B_□ = φ_□ * χ:    |x|∞ < 1
#   B_◇ = φ_◇ * χ:    max(|x1| − 1/2, 0) + max(|x2| − 1/2, 0) < 1
# each written as a condition on how far a point of the closed face can come
# to the centre along each axis (the conditions only grow with those
# distances, so the nearest point of the face decides).

def _combine(row, vals):
    """Σ c·v over a sparse integer row [(index, c, |c|), ...] of ball pairs
    (xm, xr, ym, yr): the midpoints combined with c, the radii with |c|."""
    xm = xr = ym = yr = 0
    for i, c, a in row:
        v = vals[i]
        xm += c * v[0]
        xr += a * v[1]
        ym += c * v[2]
        yr += a * v[3]
    return xm, xr, ym, yr


def _reach(c):
    """The least |x − c| over x in [0, 1] (face units)."""
    return max(Fraction(0), -c, c - 1)


def _needed_differences(along):
    """Midpoints (half units) of the differences along u (along = 0) or v (1)
    whose ψ is positive somewhere on the closed face, with the kind of their
    points. The two points lie one face (2 half units)
    apart along the direction, so a V–V midpoint is odd along it and even
    across, an FCV–FCV one even along and odd across; every support is at
    most 3 face units across, so the range searched holds them all."""
    out = []
    for x in range(-4, 7):
        for y in range(-4, 7):
            a, b = (x, y) if along == 0 else (y, x)
            if a % 2 == 1 and b % 2 == 0:
                kind = "V"
            elif a % 2 == 0 and b % 2 == 1:
                kind = "F"
            else:
                continue
            da, db = _reach(Fraction(a, 2)), _reach(Fraction(b, 2))
            if kind == "V":
                positive = da < Fraction(1, 2) and db < 1
            else:
                positive = da + max(db - Fraction(1, 2), Fraction(0)) < 1
            if positive:
                out.append(((x, y), kind))
    return out


def _needed_hull():
    """Half-unit positions of the control points whose basis is positive
    somewhere on the closed face."""
    out = []
    for x in range(-6, 9):
        for y in range(-6, 9):
            if x % 2 == 0 and y % 2 == 0:
                kind = "V"
            elif x % 2 and y % 2:
                kind = "F"
            else:
                continue
            a, b = _reach(Fraction(x, 2)), _reach(Fraction(y, 2))
            half = Fraction(1, 2)
            if kind == "V":
                positive = a < 1 and b < 1
            else:
                positive = max(a - half, Fraction(0)) + max(b - half, Fraction(0)) < 1
            if positive:
                out.append((x, y))
    return out


NON_BOX_DIFFERENCES = (_needed_differences(0), _needed_differences(1))
NON_BOX_HULL = _needed_hull()


def non_box_window(f, face, us, vs):
    """The listed u- and v-edges of a non-box window are differences of
    points of one kind one face apart along their direction, oriented along
    it, and include every difference and every hull point the S_3^1 bounds
    need (re-derived above from the supports); a superset is sound."""
    layout = as_list(get(face, "layout", "non-box face"), f"face {f} layout")
    pos, at = {}, {}
    for e in layout:
        p, x, y = as_list(e, "layout entry", 3)
        p = as_int(p, "layout point")
        for c in (x, y):
            if isinstance(c, bool) or not isinstance(c, int):
                raise Malformed(f"face {f}: layout position {c!r} is not an integer")
        if (x % 2) != (y % 2):
            reject(f"face {f}: layout position ({x}, {y}) is neither a V-vertex nor an FCV")
        if p in pos or (x, y) in at:
            reject(f"face {f}: the layout places a point twice or two points at one position")
        pos[p], at[(x, y)] = (x, y), p
    for (x, y) in [(0, 0), (2, 0), (2, 2), (0, 2)]:
        if (x, y) not in at:
            reject(f"face {f}: the layout lacks the face's corner ({x}, {y})")
    for along, edges, name in ((0, us, "u"), (1, vs, "v")):
        listed = set()
        for _, _, a, b in edges:
            if a not in pos or b not in pos:
                reject(f"face {f}: a {name}-edge point has no layout position")
            (ax, ay), (bx, by) = pos[a], pos[b]
            step = (bx - ax, by - ay)
            if step != ((2, 0) if along == 0 else (0, 2)):
                reject(f"face {f}: the {name}-edge ({a}, {b}) is not one face along {name} between points of one kind")
            listed.add(((ax + bx) // 2, (ay + by) // 2))
        for h, kind in NON_BOX_DIFFERENCES[along]:
            if h not in listed:
                reject(f"face {f}: the S_3^1 bound needs the {kind}–{kind} {name}-difference about {h}, not listed")
    ends = {p for e in us + vs for p in e[2:]}
    for h in NON_BOX_HULL:
        if at.get(h) not in ends:
            reject(f"face {f}: the hull needs the control point at {h}, not among the window's points")


# The difference-scheme bounds (subdlab's lemma C9), re-derived from the
# document's regular mask, windows and second-difference bases alone: the
# children of each lattice triangle, the matrices S_c and M_c, the constants
# K_edge and K_pos (exact), the word norms P_j (exact, by integer products)
# and the factors of ε and δ (exact fractions). The document's own constants
# are only reported.

# own corners of the up and the down lattice triangle, counter-clockwise
C9_CORNERS = (((0, 0), (1, 0), (0, 1)), ((1, 0), (1, 1), (0, 1)))
# each type's own edges along e1 and e2, as (from, to)
C9_EDGES = ((((0, 0), (1, 0)), ((0, 0), (0, 1))), (((0, 1), (1, 1)), ((1, 0), (1, 1))))
C9_TYPES = ("up", "down")
# bounds of what this checker re-derives (the work grows with the window's
# size, D² children per level and (D²)^word words)
C9_MAX_WINDOW = 64
C9_MAX_WORD = 3
C9_MAX_DEPTH = 4
C9_MAX_DILATION = 4


def _lattice_point(p, what):
    p = as_list(p, what, 2)
    for c in p:
        if isinstance(c, bool) or not isinstance(c, int):
            raise Malformed(f"{what}: {c!r} is not an integer")
    return (p[0], p[1])


def _c9_children(t, d):
    """The lattice triangles of the 1/d lattice inside the triangle of type t
    at the origin (d·corners, 1/d units): (offset, type). Each has area 1/2,
    the parent d²/2, and lattice triangles do not overlap: d² of them tile it."""

    def inside(x, y):
        if t == 0:
            return x >= 0 and y >= 0 and x + y <= d
        return x <= d and y <= d and x + y >= d

    out = []
    for ox in range(-1, d + 1):
        for oy in range(-1, d + 1):
            for t2 in (0, 1):
                if all(inside(ox + cx, oy + cy) for cx, cy in C9_CORNERS[t2]):
                    out.append(((ox, oy), t2))
    if len(out) != d * d:
        raise AssertionError("the children do not tile the triangle")
    return out


def _c9_barycentric(t, y, d):
    """Weights of the point y/d on the corners of the triangle of type t:
    solved from Σ w = 1, Σ w·corner = y/d (exact, Cramer's rule)."""
    (ax, ay), (bx, by), (cx, cy) = C9_CORNERS[t]
    px, py = Fraction(y[0], d), Fraction(y[1], d)
    det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    wb = ((px - ax) * (cy - ay) - (py - ay) * (cx - ax)) / det
    wc = ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / det
    return {C9_CORNERS[t][0]: 1 - wb - wc, C9_CORNERS[t][1]: wb, C9_CORNERS[t][2]: wc}


class DifferenceLattice:
    """Lemma C9's lattice half, recomputed: raises Rejected when an
    inequality or identity fails, Malformed when the data cannot be read."""

    def __init__(self, diff, lines):
        self.lines = lines
        what = "charmap difference"
        d = as_int(get(diff, "dilation", what), "dilation")
        if not 2 <= d <= C9_MAX_DILATION:
            reject(f"lemma C9: dilation {d} outside 2..{C9_MAX_DILATION}")
        self.d = d
        self.steps = as_int(get(diff, "steps", what), "steps")
        self.read_mask(as_list(get(diff, "mask", what), "mask"))
        wins = get(diff, "windows", what)
        self.windows = []
        for name in C9_TYPES:
            w = [_lattice_point(p, f"window {name}") for p in as_list(get(wins, name, "windows"), f"window {name}")]
            if len(set(w)) != len(w):
                reject(f"lemma C9: the {name} window lists a point twice")
            if len(w) > C9_MAX_WINDOW:
                reject(f"lemma C9: the {name} window has {len(w)} points, beyond this checker's {C9_MAX_WINDOW}")
            self.windows.append(w)
        self.index = [{p: i for i, p in enumerate(w)} for w in self.windows]
        self.check_windows()
        basis = get(diff, "basis", what)
        self.basis = [self.read_basis(t, as_list(get(basis, name, "basis"), f"basis {name}"))
                      for t, name in enumerate(C9_TYPES)]
        self.solvers = [self.left_inverse(t) for t in (0, 1)]
        self.ok(f"lemma C9 second differences: {len(self.basis[0])} (up) and {len(self.basis[1])} (down) rows, "
                "each vanishing on affine data, independent (exact rank), |W| − 3 of them: they span every "
                "functional of a window that vanishes on affine data")
        self.derive_matrices()
        # the per-face forms: sparse integer basis rows, own edges by window
        # index, and the S_c over one common denominator
        self.sparse_basis = [[[(i, c, abs(c)) for i, c in enumerate(row) if c] for row in self.basis[t]]
                             for t in (0, 1)]
        self.edge_index = [[(self.index[t][a], self.index[t][b]) for a, b in C9_EDGES[t]] for t in (0, 1)]
        den = 1
        for kids in self.children:
            for _, _, rows in kids:
                for row in rows:
                    for w in row.values():
                        den = math.lcm(den, w.denominator)
        self.s_den = den
        self.s_int = [[(t2, [[(i, int(w * den), abs(int(w * den))) for i, w in row.items()] for row in rows])
                       for _, t2, rows in kids] for kids in self.children]
        self.word = as_int(get(diff, "word", what), "word")
        if not 1 <= self.word <= C9_MAX_WORD:
            reject(f"lemma C9: word length {self.word} outside 1..{C9_MAX_WORD}")
        depth = as_int(get(diff, "depth", what), "depth")
        if depth > C9_MAX_DEPTH:
            reject(f"lemma C9: refinement depth {depth} beyond this checker's {C9_MAX_DEPTH}")
        self.depth = depth
        self.word_norms()
        self.factors(diff)

    def ok(self, msg):
        self.lines.append(f"  ok  {msg}")

    def read_mask(self, raw):
        d = self.d
        self.mask = {}
        for entry in raw:
            cx, cy, terms = as_list(entry, "mask class", 3)
            c = _lattice_point([cx, cy], "mask class")
            if not (0 <= c[0] < d and 0 <= c[1] < d):
                reject(f"lemma C9: mask class {c} is not a residue modulo {d}")
            if c in self.mask:
                reject(f"lemma C9: mask class {c} given twice")
            weights = {}
            for term in as_list(terms, f"mask class {c}"):
                dx, dy, w = as_list(term, "mask term", 3)
                delta = _lattice_point([dx, dy], "mask offset")
                if (delta[0] + c[0]) % d or (delta[1] + c[1]) % d:
                    reject(f"lemma C9: mask class {c}: offset {delta} does not reach a lattice point")
                if delta in weights:
                    reject(f"lemma C9: mask class {c}: offset {delta} given twice")
                w = as_ratio(w, "mask weight")
                if w:
                    weights[delta] = w
            # affine combinations reproducing affine data: Σ w = 1 and
            # Σ w·(D·x − y) = 0, i.e. Σ w·x = y/D
            if sum(weights.values(), Fraction(0)) != 1:
                reject(f"lemma C9: mask class {c}: the weights do not sum to 1")
            for k in (0, 1):
                if sum((w * delta[k] for delta, w in weights.items()), Fraction(0)) != 0:
                    reject(f"lemma C9: mask class {c}: the rule does not reproduce linear data (Σ w·δ ≠ 0)")
            self.mask[c] = weights
        if len(self.mask) != d * d:
            reject(f"lemma C9: the mask has {len(self.mask)} classes, expected {d * d}")

    def weights(self, y):
        """The new point at y (1/D units) over old lattice points: {x: w}."""
        d = self.d
        out = {}
        for (dx, dy), w in self.mask[(y[0] % d, y[1] % d)].items():
            out[((y[0] + dx) // d, (y[1] + dy) // d)] = w
        return out

    def check_windows(self):
        d = self.d
        self.children = []
        for t in (0, 1):
            for c in C9_CORNERS[t]:
                if c not in self.index[t]:
                    reject(f"lemma C9: the {C9_TYPES[t]} window lacks its corner {c}")
        reach = 0
        for t in (0, 1):
            kids = []
            for o, t2 in _c9_children(t, d):
                # S_c: the child's window points over the parent's window
                rows = []
                for w in self.windows[t2]:
                    row = {}
                    for x, wt in self.weights((o[0] + w[0], o[1] + w[1])).items():
                        i = self.index[t].get(x)
                        if i is None:
                            reject(f"lemma C9: the {C9_TYPES[t]} window is not closed: its child at {o}/{d} needs "
                                   f"the point {x}")
                        row[i] = wt
                        reach += 1
                    rows.append(row)
                kids.append((o, t2, rows))
            self.children.append(kids)
        self.ok(f"lemma C9 mask: {d * d} classes of affine rules (weights sum to 1, Σ w·δ = 0, exactly), dilation {d} "
                f"(one analysis step of {self.steps} refinement(s), as the document says); windows of {len(self.windows[0])} (up) and {len(self.windows[1])} (down) points hold their corners "
                f"and are closed: every point of each of the {d * d} children's windows is computed from the parent's "
                f"window ({reach} weights)")

    def read_basis(self, t, raw):
        n = len(self.windows[t])
        rows = []
        for r, row in enumerate(raw):
            dense = [0] * n
            for term in as_list(row, f"basis row {r}"):
                x, y, c = as_list(term, "basis term", 3)
                p = _lattice_point([x, y], "basis point")
                if isinstance(c, bool) or not isinstance(c, int):
                    raise Malformed(f"basis coefficient {c!r} is not an integer")
                i = self.index[t].get(p)
                if i is None:
                    reject(f"lemma C9: a {C9_TYPES[t]} basis row uses {p}, not a window point")
                dense[i] += c
            w = self.windows[t]
            if sum(dense) or sum(c * p[0] for c, p in zip(dense, w)) or sum(c * p[1] for c, p in zip(dense, w)):
                reject(f"lemma C9: {C9_TYPES[t]} basis row {r} does not vanish on affine data")
            rows.append(dense)
        if len(rows) != n - 3:
            reject(f"lemma C9: {len(rows)} {C9_TYPES[t]} basis rows, the window needs |W| − 3 = {n - 3}")
        return rows

    def left_inverse(self, t):
        """E with E·Rᵀ = [I_k; 0] (Gauss–Jordan on [Rᵀ | I], exact): then
        κᵀR = g has the solution κ = (E g)[:k] exactly when (E g)[k:] = 0."""
        rows = self.basis[t]
        k, n = len(rows), len(self.windows[t])
        a = [[Fraction(rows[j][i]) for j in range(k)] + [Fraction(int(i == c)) for c in range(n)] for i in range(n)]
        for c in range(k):
            piv = next((r for r in range(c, n) if a[r][c] != 0), None)
            if piv is None:
                reject(f"lemma C9: the {C9_TYPES[t]} basis rows are not independent")
            a[c], a[piv] = a[piv], a[c]
            inv = 1 / a[c][c]
            a[c] = [x * inv for x in a[c]]
            for r in range(n):
                if r != c and a[r][c] != 0:
                    f = a[r][c]
                    a[r] = [x - f * y for x, y in zip(a[r], a[c])]
        return [row[k:] for row in a], k

    def coordinates(self, t, g, what):
        """κ with κᵀR_t = g (exact), for a functional g on W_t vanishing on
        affine data."""
        e, k = self.solvers[t]
        nz = [(i, x) for i, x in enumerate(g) if x]
        y = [sum((row[i] * x for i, x in nz), Fraction(0)) for row in e]
        if any(y[k:]):
            reject(f"lemma C9: {what} is not a combination of second differences (the mask does not reproduce "
                   "affine data)")
        return y[:k]

    def derive_matrices(self):
        d = self.d
        k_edge, k_pos = Fraction(0), Fraction(0)
        self.m = [[], []]
        for t in (0, 1):
            n = len(self.windows[t])
            for o, t2, s in self.children[t]:
                def combine(terms):
                    g = [Fraction(0)] * n
                    for p, c in terms:
                        for i, w in s[self.index[t2][p]].items():
                            g[i] += c * w
                    return g

                m = []
                for r, row in enumerate(self.basis[t2]):
                    terms = [(self.windows[t2][i], c) for i, c in enumerate(row) if c]
                    m.append(self.coordinates(t, combine(terms), f"a second difference of the child at {o}/{d}"))
                self.m[t].append((t2, m))
                for e in (0, 1):
                    (ca, cb), (pa, pb) = C9_EDGES[t2][e], C9_EDGES[t][e]
                    g = combine([(cb, d), (ca, -d)])
                    g[self.index[t][pb]] -= 1
                    g[self.index[t][pa]] += 1
                    kappa = self.coordinates(t, g, f"D·edge − edge of the child at {o}/{d}")
                    k_edge = max(k_edge, sum(map(abs, kappa)))
                for c in C9_CORNERS[t2]:
                    g = combine([(c, 1)])
                    for corner, w in _c9_barycentric(t, (o[0] + c[0], o[1] + c[1]), d).items():
                        g[self.index[t][corner]] -= w
                    kappa = self.coordinates(t, g, f"a corner of the child at {o}/{d} off the parent's interpolant")
                    k_pos = max(k_pos, sum(map(abs, kappa)))
        self.k_edge, self.k_pos = k_edge, k_pos
        sizes = {(len(m), len(m[0])) for kids in self.m for _, m in kids}
        self.ok(f"lemma C9 matrices: per type the {d * d} children's S_c from the mask and M_c with "
                f"Δ2_child·S_c = M_c·Δ2_parent solved exactly and checked on every column ({len(self.m[0]) + len(self.m[1])} "
                f"matrices, {' '.join(f'{a}×{b}' for a, b in sorted(sizes))}); K_edge = max‖κ‖₁ = {k_edge} "
                f"(≈ {float(k_edge):.6g}), K_pos = {k_pos} (≈ {float(k_pos):.6g}), exact")

    def word_norms(self):
        """P_j = max over type-consistent words of j children of D^j‖M_w‖∞,
        exactly: the M_c times the common denominator are integer matrices,
        their products exact; words share their prefixes."""
        d, word = self.d, self.word
        den = 1
        for kids in self.m:
            for _, m in kids:
                for row in m:
                    for x in row:
                        den = math.lcm(den, x.denominator)
        ints = [[(t2, [[int(x * den) for x in row] for row in m]) for t2, m in kids] for kids in self.m]

        def norm(a):
            return max(sum(map(abs, row)) for row in a)

        def product(a, b_cols):
            return [[sum(map(mul, row, col)) for col in b_cols] for row in a]

        norms = [Fraction(1)]
        # frontier: (type reached, product as columns) — the words of length j
        frontier = [(t2, list(zip(*a))) for t in (0, 1) for t2, a in ints[t]]
        worst = max(norm(a) for t in (0, 1) for _, a in ints[t])
        norms.append(Fraction(d * worst, den))
        for j in range(2, word + 1):
            worst, nxt = 0, []
            last = j == word
            for t, cols in frontier:
                for t2, a in ints[t]:
                    p = product(a, cols)
                    worst = max(worst, norm(p))
                    if not last:
                        nxt.append((t2, list(zip(*p))))
            norms.append(Fraction(d**j * worst, den**j))
            frontier = nxt
        self.p = norms
        words = sum(2 * (d * d) ** j for j in range(1, word + 1))
        shown = ", ".join(f"{float(x):.6g}" for x in norms)
        if not norms[word] < 1:
            reject(f"lemma C9: the difference scheme is not proved contractive at word length {word}: "
                   f"P_{word} = {float(norms[word]):.6g} ≥ 1 (P_0..P_{word} = {shown})")
        self.ok(f"lemma C9 word norms: P_j = max D^j‖M_w‖∞ over all {words} type-consistent words of up to {word} "
                f"children, exactly (integer products): P_0..P_{word} = {shown}; P_{word} < 1")

    def factors(self, diff):
        d, word, p = self.d, self.word, self.p
        q = p[word]
        self.edge_factor = self.k_edge * sum(p[:word], Fraction(0)) / (1 - q)
        self.position_factor = (self.k_pos * sum((p[j] / d**j for j in range(word)), Fraction(0))
                                / (1 - q / d**word))
        theirs = {k: diff.get(k) for k in ("k_edge", "k_pos", "edge_constant", "position_constant", "word_norms")}
        self.ok(f"lemma C9 factors (exact, used below): ε ≤ {float(self.edge_factor):.9g}·N(p), "
                f"δ ≤ {float(self.position_factor):.9g}·N(p); the document's own (reported, not used): "
                f"k_edge {theirs['k_edge']}, k_pos {theirs['k_pos']}, edge_constant {theirs['edge_constant']}, "
                f"position_constant {theirs['position_constant']}, word_norms {theirs['word_norms']}")

    # -- per face, in the ball arithmetic of the net (scale 2^-P)

    def seminorm(self, t, vals):
        """An upper bound (scale 2^-P, integer) of N(p): the largest
        Euclidean length of the basis rows' combinations of the values
        (each value a ball pair (xm, xr, ym, yr))."""
        n = 0
        for row in self.sparse_basis[t]:
            xm, xr, ym, yr = _combine(row, vals)
            n = max(n, ceil_sqrt((abs(xm) + xr) ** 2 + (abs(ym) + yr) ** 2))
        return n

    def scaled_up(self, factor, n):
        """⌈factor·n⌉ for a nonnegative Fraction factor: an upper bound."""
        return -((-factor.numerator * n) // factor.denominator)

    def jacobian(self, t, vals, depth):
        """An enclosure [lo, hi] (scale 2^-P) of det(∂₁f, ∂₂f) over the
        triangle of type t with window values vals, in its own parameter;
        refined by the S_c up to depth levels while its sign is undecided."""
        eps = self.scaled_up(self.edge_factor, self.seminorm(t, vals))
        (a0, b0), (a1, b1) = self.edge_index[t]
        pa, pb, qa, qb = vals[a0], vals[b0], vals[a1], vals[b1]
        ux, uy = (pb[0] - pa[0], pb[1] + pa[1]), (pb[2] - pa[2], pb[3] + pa[3])
        vx, vy = (qb[0] - qa[0], qb[1] + qa[1]), (qb[2] - qa[2], qb[3] + qa[3])
        lu = ceil_sqrt((abs(ux[0]) + ux[1]) ** 2 + (abs(uy[0]) + uy[1]) ** 2)
        lv = ceil_sqrt((abs(vx[0]) + vx[1]) ** 2 + (abs(vy[0]) + vy[1]) ** 2)
        pad = -((-(eps * (lu + lv) + eps * eps)) >> P)
        dm, dr = ball_sub(ball_mul(ux, vy, P), ball_mul(uy, vx, P))
        lo, hi = dm - dr - pad, dm + dr + pad
        if lo > 0 or hi < 0 or depth == 0:
            return lo, hi
        # the triangle's Jacobian set is the union of its children's, and
        # in the parent's parameter (D times coarser) a child's is D² times
        # its own
        den = self.s_den
        clo, chi = None, None
        for t2, s in self.s_int[t]:
            child = []
            for row in s:
                xm, xr, ym, yr = _combine(row, vals)
                # Σ (w/den)·[m ± r] ⊆ [Σ w m ∓ Σ |w| r]/den, rounded outward
                xq, xrem = divmod(xm, den)
                yq, yrem = divmod(ym, den)
                child.append((xq, -(-xr // den) + (1 if xrem else 0), yq, -(-yr // den) + (1 if yrem else 0)))
            a, b = self.jacobian(t2, child, depth - 1)
            clo = a if clo is None else min(clo, a)
            chi = b if chi is None else max(chi, b)
            if clo <= 0 <= chi:
                return lo, hi  # both signs possible: undecided, whatever the rest
        d2 = self.d * self.d
        lo2, hi2 = max(lo, d2 * clo), min(hi, d2 * chi)
        if lo2 > hi2:
            reject("lemma C9: two enclosures of one Jacobian are disjoint (an arithmetic fault)")
        return lo2, hi2

    def face(self, f, face, pts, us, vs):
        """A ring face's window (W_up laid out at the positions `window`
        gives): its values, its u- and v-edge checked to be the face's own,
        N(p) (upper bound, scale 2^-P). Returns (values, N, corners)."""
        layout = as_list(get(face, "window", "difference-scheme face"), f"face {f} window")
        at = {}
        used = set()
        for e in layout:
            i, x, y = as_list(e, "window entry", 3)
            i = as_int(i, "window point", len(pts))
            p = _lattice_point([x, y], "window position")
            if p in at or i in used:
                reject(f"face {f}: the window places a point twice or two points at one position")
            at[p] = i
            used.add(i)
        if set(at) != set(self.windows[0]):
            reject(f"face {f}: the window's positions are not the up window W_up")
        ids = [at[p] for p in self.windows[0]]
        vals = [(pts[i][0][0], pts[i][0][1], pts[i][1][0], pts[i][1][1]) for i in ids]
        o, a, b = (at[c] for c in C9_CORNERS[0])
        if [(e[2], e[3]) for e in us] != [(o, a)] or [(e[2], e[3]) for e in vs] != [(o, b)]:
            reject(f"face {f}: the u- and v-edges are not the window's own edges (0,0)→(1,0) and (0,0)→(0,1)")
        return vals, self.seminorm(0, vals), (o, a, b)


def _add_q(x, y):
    """The sum of two rationals in the tuple form of Field elements."""
    s = (x[0] if x else 0) + (y[0] if y else 0)
    return (Fraction(s),) if s else ()


def ball_add(a, b):
    return a[0] + b[0], a[1] + b[1]


def ball_sub(a, b):
    return a[0] - b[0], a[1] + b[1]


def mod_at_least(a, b):
    """Every point of a has modulus ≥ every point of b: |a.c| − a.r ≥ |b.c| + b.r."""
    s = a.r + b.r
    lhs = a.norm2() - b.norm2() - s * s
    return lhs >= 0 and lhs * lhs >= 4 * s * s * b.norm2()


def main(argv):
    if len(argv) != 2:
        print("usage: check_cert.py CERTIFICATE.json", file=sys.stderr)
        return 2
    try:
        with open(argv[1], encoding="utf-8") as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        print(f"CERTIFICATE UNREADABLE: {e}")
        return 2
    checker = Checker(doc)
    try:
        checker.run()
    except Malformed as e:
        print("\n".join(checker.lines))
        print(f"CERTIFICATE MALFORMED: {e}")
        return 2
    except Rejected as e:
        print("\n".join(checker.lines))
        print(f"CERTIFICATE REJECTED: {e}")
        return 1
    except (KeyError, TypeError, IndexError, AttributeError) as e:
        print("\n".join(checker.lines))
        print(f"CERTIFICATE MALFORMED: unexpected structure ({type(e).__name__}: {e})")
        return 2
    print("\n".join(checker.lines))
    print(f"CERTIFICATE ACCEPTED ({checker.verdict})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
