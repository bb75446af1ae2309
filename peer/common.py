"""Shared parts of the peer suite: random curves, our results, the two peers
(geomdl 5.4.0 and scipy), and the comparison.

Every topic script builds random cases, asks t2spline for its results through
the example binary `peer` (crates/t2spline/examples/peer.rs: JSON cases on
standard input, JSON results on standard output), computes the same quantities
with the peers, and records relative errors in a `Topic`.
"""

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
from geomdl import NURBS
from scipy.interpolate import BSpline

ROOT = Path(__file__).resolve().parent.parent
TOLERANCE = 1e-9
KNOT_KINDS = ("clamped-uniform", "clamped-random", "repeated", "full-multiplicity", "unclamped")


# --- our side -------------------------------------------------------------


def build_ours():
    """Builds the example binary `peer` and returns its path."""
    subprocess.run(
        ["cargo", "build", "--release", "--quiet", "-p", "t2spline", "--example", "peer"],
        cwd=ROOT,
        check=True,
    )
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "examples" / "peer"


def ours(binary, cases):
    """t2spline's results for `cases` (one dict per case, or {'error': ...})."""
    done = subprocess.run(
        [str(binary)],
        input=json.dumps({"cases": cases}),
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(done.stdout)["results"]


# --- random curves --------------------------------------------------------


def random_curve(rng, kind=None):
    """A random rational curve: degree 1-5, 2-D or 3-D, weights in [0.2, 5]
    (log-uniform), coordinates in [-10, 10], a domain [a, b] of length 0.1-10
    anywhere in [-3, 13], and knots of the given kind (random if None)."""
    kind = kind or rng.choice(KNOT_KINDS)
    p = rng.randint(1, 5)
    dim = rng.choice((2, 3))
    a = rng.uniform(-3.0, 3.0)
    b = a + 10 ** rng.uniform(-1.0, 1.0)
    interior = _interior_knots(rng, kind, p, a, b)
    n = len(interior) + p + 1
    if kind == "unclamped":
        span = b - a
        lower = sorted(a - rng.uniform(0.0, span) for _ in range(p))
        upper = sorted(b + rng.uniform(0.0, span) for _ in range(p))
        knots = lower + [a] + interior + [b] + upper
    else:
        knots = [a] * (p + 1) + interior + [b] * (p + 1)
    return {
        "kind": kind,
        "degree": p,
        "knots": knots,
        "points": [[rng.uniform(-10.0, 10.0) for _ in range(dim)] for _ in range(n)],
        "weights": [10 ** rng.uniform(math.log10(0.2), math.log10(5.0)) for _ in range(n)],
    }


def _interior_knots(rng, kind, p, a, b):
    if kind == "clamped-uniform":
        m = rng.randint(0, 6)
        return [a + (b - a) * i / (m + 1) for i in range(1, m + 1)]
    values = sorted(rng.uniform(a, b) for _ in range(rng.randint(0, 5)))
    values = [v for v in values if a < v < b]
    if kind in ("clamped-random", "unclamped"):
        return values
    # Repeated knots: multiplicities 2..p; one of full multiplicity p + 1.
    out = []
    full_at = rng.randrange(len(values) + 1)
    if kind == "full-multiplicity" and full_at == len(values):
        values.append(rng.uniform(a, b))
    for i, v in enumerate(values):
        if kind == "full-multiplicity" and i == full_at:
            out += [v] * (p + 1)
        else:
            out += [v] * rng.randint(1, max(1, p))
    return sorted(out)


def domain(curve):
    p, u = curve["degree"], curve["knots"]
    return u[p], u[len(curve["points"])]


def params(rng, curve, count=6):
    """Both ends of the domain, every interior knot, and `count` random values."""
    a, b = domain(curve)
    inner = sorted({u for u in curve["knots"] if a < u < b})
    return [a, b] + inner + [rng.uniform(a, b) for _ in range(count)]


def multiplicity(curve, u):
    return sum(1 for v in curve["knots"] if v == u)


def homogeneous(curve):
    return np.array([[w * x for x in pt] + [w] for pt, w in zip(curve["points"], curve["weights"])])


def coordinate_scale(curve):
    return max(abs(x) for pt in curve["points"] for x in pt)


# --- the peers ------------------------------------------------------------


def geomdl_curve(curve):
    """The curve as a geomdl NURBS.Curve (no knot normalisation)."""
    c = NURBS.Curve(normalize_kv=False)
    c.degree = curve["degree"]
    c.ctrlptsw = homogeneous(curve).tolist()
    c.knotvector = list(curve["knots"])
    return c


def geomdl_as_dict(c):
    return {
        "degree": c.degree,
        "knots": list(c.knotvector),
        "points": [list(p) for p in c.ctrlpts],
        "weights": list(c.weights),
    }


def scipy_spline(curve):
    """The homogeneous curve (wP, w) as a scipy BSpline."""
    return BSpline(np.array(curve["knots"], dtype=float), homogeneous(curve), curve["degree"], extrapolate=False)


def scipy_derivatives(curve, t, order):
    """C, C', ..., C^(order) at t: homogeneous derivatives by scipy, then
    Leibniz's rule for the quotient C = A / w (The NURBS Book, Eq. 4.8)."""
    s = scipy_spline(curve)
    h = [s(t, nu=k) for k in range(order + 1)]
    a = [row[:-1] for row in h]
    w = [row[-1] for row in h]
    c = []
    for k in range(order + 1):
        v = a[k].copy()
        for i in range(1, k + 1):
            v -= math.comb(k, i) * w[i] * c[k - i]
        c.append(v / w[0])
    return c


def scipy_points(curve, ts):
    s = scipy_spline(curve)
    h = np.array([s(t) for t in ts])
    return h[:, :-1] / h[:, -1:]


# --- comparison -----------------------------------------------------------


def relative_error(ours_value, reference, scale):
    """max |ours − reference| / scale, entry by entry."""
    diff = np.max(np.abs(np.asarray(ours_value, dtype=float) - np.asarray(reference, dtype=float)))
    return float(diff / scale)


def compare_curves(ours_curve, peer_curve):
    """The relative difference of two curve representations: knots (relative
    to the domain size), control points (to the largest coordinate) and
    weights (to the largest weight); inf if the shapes differ."""
    if ours_curve["degree"] != peer_curve["degree"] or len(ours_curve["knots"]) != len(peer_curve["knots"]):
        return math.inf
    if len(ours_curve["points"]) != len(peer_curve["points"]):
        return math.inf
    knot_scale = max(1.0, max(abs(u) for u in peer_curve["knots"]))
    point_scale = max(1e-300, max(abs(x) for p in peer_curve["points"] for x in p))
    weight_scale = max(peer_curve["weights"])
    return max(
        relative_error(ours_curve["knots"], peer_curve["knots"], knot_scale),
        relative_error(ours_curve["points"], peer_curve["points"], point_scale),
        relative_error(ours_curve["weights"], peer_curve["weights"], weight_scale),
    )


def answered(topic, binary, cases):
    """Our results for `cases`, as (index, case, result) for every case we
    answered; a case we refused counts as a failure of `topic`."""
    for i, (case, result) in enumerate(zip(cases, ours(binary, cases))):
        topic.cases += 1
        if "error" in result:
            topic.fail(i, result["error"])
        else:
            yield i, case, result


class Topic:
    """Counts cases and comparisons of one topic, and keeps the largest error
    seen per peer and every failure."""

    def __init__(self, name):
        self.name = name
        self.cases = 0
        self.failed_cases = set()
        self.comparisons = {}
        self.max_error = {}
        self.failures = []

    def check(self, case_id, peer, error, detail=""):
        self.comparisons[peer] = self.comparisons.get(peer, 0) + 1
        self.max_error[peer] = max(self.max_error.get(peer, 0.0), error)
        if not error <= TOLERANCE:
            self.failed_cases.add(case_id)
            self.failures.append(f"{self.name} case {case_id} vs {peer}: relative error {error:.3e} {detail}")

    def fail(self, case_id, message):
        self.failed_cases.add(case_id)
        self.failures.append(f"{self.name} case {case_id}: {message}")

    def summary(self):
        peers = ", ".join(
            f"{peer}: {self.comparisons[peer]} comparisons, max error {self.max_error[peer]:.2e}"
            for peer in sorted(self.comparisons)
        )
        return f"{self.name}: {self.cases} cases, {len(self.failed_cases)} failed; {peers}"
