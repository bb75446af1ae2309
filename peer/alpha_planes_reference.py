"""The alpha-plane value of one number (docs/method.md §9) at 40 digits, from the
definition alone, as an oracle for `crates/t2spline/tests/reductions.rs`.

c_l(z), c_r(z): bisection on the Karnik–Mendel function of the plane at z,
whose integrals of (x − c)·(piecewise-linear membership) are exact by
Simpson's rule on each linear piece; then ∫₀¹ z·(c_l + c_r) dz by mpmath's
tanh-sinh quadrature in v with z = v⁶ (smooth at z = 0, where c may grow like
z^(1/3) or z^(1/2)).

    python3 peer/alpha_planes_reference.py CRISP UL UR PL PR LL LR H
"""
import sys

import mpmath as mp

mp.mp.dps = 40


def triangle(a, c, b, top, x):
    if x == c:
        return top
    if a <= x < c:
        return top * (x - a) / (c - a)
    if c < x <= b:
        return top * (b - x) / (b - c)
    return mp.mpf(0)


def plane(crisp, upper, primary, lower, h, z):
    breaks = sorted({*upper, *primary, *lower, crisp})
    up = lambda x: (1 - z) * triangle(upper[0], crisp, upper[1], 1, x) + z * triangle(primary[0], crisp, primary[1], 1, x)
    lo = lambda x: (1 - z) * triangle(lower[0], crisp, lower[1], h, x) + z * triangle(primary[0], crisp, primary[1], 1, x)
    return breaks, up, lo


def integral(f, a, b, breaks):
    """∫ₐᵇ f for f cubic between breaks; the ends of each piece are taken just inside."""
    points = [a] + [p for p in breaks if a < p < b] + [b]
    total = mp.mpf(0)
    for p, q in zip(points, points[1:]):
        e = (q - p) * mp.mpf(10) ** -35
        total += (q - p) / 6 * (f(p + e) + 4 * f((p + q) / 2) + f(q - e))
    return total


def km(c, breaks, before, after):
    a, b = breaks[0], breaks[-1]
    return integral(lambda x: (x - c) * before(x), a, min(c, b), breaks) + integral(
        lambda x: (x - c) * after(x), max(c, a), b, breaks)


def ends(number, z):
    breaks, up, lo = plane(*number, z)
    out = []
    for before, after in ((up, lo), (lo, up)):
        a, b = breaks[0], breaks[-1]
        for _ in range(140):
            m = (a + b) / 2
            if km(m, breaks, before, after) > 0:
                a = m
            else:
                b = m
        out.append((a + b) / 2)
    return out


def main():
    crisp, ul, ur, pl, pr, ll, lr, h = (mp.mpf(v) for v in sys.argv[1:9])
    number = (crisp, (ul, ur), (pl, pr), (ll, lr), h)
    f = lambda v: 6 * v**5 * v**6 * sum(ends(number, v**6))
    print(mp.nstr(mp.quad(f, mp.linspace(0, 1, 9), maxdegree=8), 25))


if __name__ == "__main__":
    main()
