"""Shared parts of the surface topics of the peer suite: random rational
surfaces, the two surface peers (geomdl 5.4.0 and splipy), and measures.

A surface case is a dict with `degree` [p, q], `knots` [U, V], `points`
(points[i][j], i along u, 3-D) and `weights` of the same shape, plus `kinds`
(the knot kind of each direction, see common.KNOT_KINDS).
"""

import math

import numpy as np
import splipy
from geomdl import NURBS

from common import KNOT_KINDS, _interior_knots


def _knots(rng, kind, p):
    """A knot vector of degree p of the given kind, on a random domain."""
    a = rng.uniform(-3.0, 3.0)
    b = a + 10 ** rng.uniform(-1.0, 1.0)
    interior = _interior_knots(rng, kind, p, a, b)
    if kind == "unclamped":
        span = b - a
        lower = sorted(a - rng.uniform(0.0, span) for _ in range(p))
        upper = sorted(b + rng.uniform(0.0, span) for _ in range(p))
        return lower + [a] + interior + [b] + upper
    return [a] * (p + 1) + interior + [b] * (p + 1)


def random_surface(rng, kinds=None):
    """A random rational surface: degrees 1-4 per direction, knots of a random
    kind per direction (as the curves), weights in [0.2, 5] (log-uniform),
    coordinates in [-10, 10]."""
    kinds = kinds or [rng.choice(KNOT_KINDS), rng.choice(KNOT_KINDS)]
    degree = [rng.randint(1, 4), rng.randint(1, 4)]
    knots = [_knots(rng, kind, p) for kind, p in zip(kinds, degree)]
    nu, nv = (len(k) - p - 1 for k, p in zip(knots, degree))
    return {
        "kinds": kinds,
        "degree": degree,
        "knots": knots,
        "points": [[[rng.uniform(-10.0, 10.0) for _ in range(3)] for _ in range(nv)] for _ in range(nu)],
        "weights": [[10 ** rng.uniform(math.log10(0.2), math.log10(5.0)) for _ in range(nv)] for _ in range(nu)],
    }


def kind(case):
    return "/".join(case["kinds"])


def domain(case, d):
    p, u = case["degree"][d], case["knots"][d]
    return u[p], u[len(u) - p - 1]


def shape(case):
    return len(case["points"]), len(case["points"][0])


def direction_params(rng, case, d, count=3):
    """Both ends of direction d's domain, every interior knot, random values."""
    a, b = domain(case, d)
    inner = sorted({u for u in case["knots"][d] if a < u < b})
    return [a, b] + inner + [rng.uniform(a, b) for _ in range(count)]


def grid_params(rng, case, count=3):
    """Pairs (u, v) from the probes of both directions."""
    return [[u, v] for u in direction_params(rng, case, 0, count) for v in direction_params(rng, case, 1, count)]


def multiplicity(knots, u):
    return sum(1 for v in knots if v == u)


def coordinate_scale(case):
    return max(abs(x) for row in case["points"] for p in row for x in p)


def homogeneous_rows(case):
    """(w·P, w) of every control point, u-major (i outer, j inner)."""
    return [[w * x for x in p] + [w] for prow, wrow in zip(case["points"], case["weights"]) for p, w in zip(prow, wrow)]


# --- geomdl 5.4.0 ----------------------------------------------------------


def geomdl_surface(case):
    """The surface as a geomdl NURBS.Surface (no knot normalisation);
    geomdl's control points are u-major: index i·nv + j."""
    nu, nv = shape(case)
    s = NURBS.Surface(normalize_kv=False)
    s.degree_u, s.degree_v = case["degree"]
    s.ctrlpts_size_u, s.ctrlpts_size_v = nu, nv
    s.ctrlptsw = homogeneous_rows(case)
    s.knotvector_u, s.knotvector_v = (list(k) for k in case["knots"])
    return s


def geomdl_as_case(s):
    nu, nv = s.ctrlpts_size_u, s.ctrlpts_size_v
    pts, w = s.ctrlpts, s.weights
    return {
        "degree": [s.degree_u, s.degree_v],
        "knots": [list(s.knotvector_u), list(s.knotvector_v)],
        "points": [[list(pts[i * nv + j]) for j in range(nv)] for i in range(nu)],
        "weights": [[w[i * nv + j] for j in range(nv)] for i in range(nu)],
    }


# --- splipy -----------------------------------------------------------------


def splipy_surface(case, rational=True):
    """The surface as a splipy Surface on the projective control points
    (w·P, w); splipy takes the first direction fastest. With
    `rational=False`, the non-rational spline of the projective points (the
    homogeneous surface (A, w))."""
    nu, nv = shape(case)
    b = [splipy.BSplineBasis(p + 1, np.array(k, dtype=float)) for p, k in zip(case["degree"], case["knots"])]
    rows = homogeneous_rows(case)
    cp = np.array([rows[i * nv + j] for j in range(nv) for i in range(nu)], dtype=float)
    return splipy.Surface(b[0], b[1], cp, rational=rational)


def splipy_as_case(s):
    """A splipy rational surface as a case dict (controlpoints[i, j] are
    (w·P, w))."""
    cp = np.asarray(s.controlpoints, dtype=float)
    return {
        "degree": [o - 1 for o in s.order()],
        "knots": [list(k) for k in s.knots(with_multiplicities=True)],
        "points": (cp[:, :, :-1] / cp[:, :, -1:]).tolist(),
        "weights": cp[:, :, -1].tolist(),
    }


def splipy_derivatives(case, u, v, order):
    """S^(k,l)(u, v) for k + l <= order: derivatives of the homogeneous
    surface by splipy (any order), then Leibniz's rule for the quotient
    (The NURBS Book, Eq. 4.20) written here."""
    h = splipy_surface(case, rational=False)
    d = [[np.asarray(h.derivative(u, v, d=(k, l))) for l in range(order + 1 - k)] for k in range(order + 1)]
    a = [[x[:-1] for x in row] for row in d]
    w = [[x[-1] for x in row] for row in d]
    s = [[None] * (order + 1 - k) for k in range(order + 1)]
    for k in range(order + 1):
        for l in range(order + 1 - k):
            value = a[k][l].copy()
            for j in range(1, l + 1):
                value -= math.comb(l, j) * w[0][j] * s[k][l - j]
            for i in range(1, k + 1):
                value -= math.comb(k, i) * w[i][0] * s[k - i][l]
                for j in range(1, l + 1):
                    value -= math.comb(k, i) * math.comb(l, j) * w[i][j] * s[k - i][l - j]
            s[k][l] = value / w[0][0]
    return s


# --- comparison ---------------------------------------------------------------


def compare_surfaces(ours, peer):
    """The relative difference of two surface representations: knots
    (relative to max(1, largest |knot|)), control points (to the largest
    coordinate) and weights (to the largest weight); inf if shapes differ."""
    if list(ours["degree"]) != list(peer["degree"]):
        return math.inf
    for d in range(2):
        if len(ours["knots"][d]) != len(peer["knots"][d]):
            return math.inf
    if np.shape(ours["points"]) != np.shape(peer["points"]):
        return math.inf
    knot_scale = max(1.0, max(abs(u) for k in peer["knots"] for u in k))
    point_scale = max(1e-300, float(np.max(np.abs(peer["points"]))))
    weight_scale = float(np.max(peer["weights"]))
    knots = max(float(np.max(np.abs(np.array(a) - np.array(b)))) for a, b in zip(ours["knots"], peer["knots"]))
    return max(
        knots / knot_scale,
        float(np.max(np.abs(np.array(ours["points"]) - np.array(peer["points"])))) / point_scale,
        float(np.max(np.abs(np.array(ours["weights"]) - np.array(peer["weights"])))) / weight_scale,
    )


def splipy_points(case, pairs):
    """S(u, v) at the pairs by splipy (rational evaluation, from the right)."""
    s = splipy_surface(case)
    return [np.asarray(s(u, v)).reshape(3) for u, v in pairs]


def geometry_error(case, other, rng, count=5):
    """Largest difference between two surfaces over the same domain (splipy
    evaluates both) at probes of `case`, relative to its coordinates."""
    pairs = grid_params(rng, case, count)
    a, b = splipy_points(case, pairs), splipy_points(other, pairs)
    return float(np.max(np.abs(np.array(a) - np.array(b)))) / coordinate_scale(case)
