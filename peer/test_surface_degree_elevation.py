"""Degree elevation by 1-2 in u or v: t2spline (A5.9 on stacked lines of the
net) against splipy (`Surface.raise_order` on the projective control points)
and geomdl (`operations.degree_operations`).

The elevated surface has every knot of the elevated direction once more per
elevation; in that spline space its representation is unique, so for clamped
directions our net, weights and knots must equal splipy's. For an unclamped
direction t2spline clamps first (same domain) while splipy keeps the knots, so
splipy's `raise_order` is only asked when both directions are clamped (with an
unclamped basis it re-interpolates), and where it raises `LinAlgError` (its
interpolation at Greville points, `raise_order_implicit`, which it also takes
for some clamped bases, was singular for some random cases: counted in the
topic's note). For every case, splipy also evaluates the elevated and the original
surface at the probes, which must agree ("splipy geometry").

geomdl 5.4.0's `operations.degree_operations` does nothing for surfaces (its
surface branch is an empty stub: degree, knots and net come back unchanged;
`test_surface_closed_forms.py` checks that this is still so). So geomdl is
used where it is right, as for curves: the original surface and our elevated
one are both decomposed into Bézier strips along the elevated direction by
geomdl (`operations.decompose_surface`, knot insertion), every line of each
original strip is elevated by geomdl's Bézier elevation
(`helpers.degree_elevation`, Eq. 5.36), and the nets must equal those of our
strips (Bézier strips are unique). geomdl's decomposition needs a clamped,
continuous direction: unclamped ones and knots of full multiplicity are left
to splipy."""

import numpy as np
from geomdl import helpers, operations

from common import answered, Topic
from common_surface import compare_surfaces, domain, geometry_error, geomdl_as_case, geomdl_surface, kind, multiplicity, random_surface, splipy_as_case, splipy_surface

CASES = 150


def run(rng, binary):
    topic = Topic("surface degree elevation")
    singular = []
    cases = []
    for _ in range(CASES):
        s = random_surface(rng)
        d = rng.randrange(2)
        cases.append(dict(s, op="surface_elevate", direction="uv"[d], times=rng.randint(1, 2)))
    for i, case, result in answered(topic, binary, cases):
        got = result["surface"]
        d = "uv".index(case["direction"])
        times = case["times"]
        detail = f"degree {case['degree']} + {times} in {case['direction']}, {kind(case)}"
        a, b = domain(case, d)
        for u in set(case["knots"][d]):
            if a <= u <= b and case["kinds"][d] != "unclamped":
                if multiplicity(got["knots"][d], u) != multiplicity(case["knots"][d], u) + times:
                    topic.fail(i, f"knot {u}: multiplicity {multiplicity(got['knots'][d], u)}, expected +{times}")
        # splipy's geometry: the elevated and the original surface, both
        # evaluated by splipy, agree at the probes.
        topic.check(i, "splipy geometry", geometry_error(case, got, rng), detail)
        if all(k != "unclamped" for k in case["kinds"]):
            s = splipy_surface(case)
            try:
                s.raise_order(*([times, 0] if d == 0 else [0, times]))
            except np.linalg.LinAlgError:
                singular.append(kind(case))
            else:
                topic.check(i, "splipy", compare_surfaces(got, splipy_as_case(s)), detail)
        full = any(multiplicity(case["knots"][d], u) > case["degree"][d] for u in case["knots"][d] if a < u < b)
        if case["kinds"][d] != "unclamped" and not full:
            topic.check(i, "geomdl", geomdl_strips_error(case, got, d, times), detail)
    topic.note = f"splipy's raise_order found its interpolation matrix singular in {len(singular)} cases ({', '.join(sorted(set(singular)))}); not asked there"
    return topic


def strips(case, d):
    """geomdl's Bézier strips of a surface along direction d, each as its
    homogeneous net [i][j]."""
    out = []
    for strip in operations.decompose_surface(geomdl_surface(case), decompose_dir="uv"[d]):
        nu, nv = strip.ctrlpts_size_u, strip.ctrlpts_size_v
        w = strip.ctrlptsw
        out.append([[list(w[i * nv + j]) for j in range(nv)] for i in range(nu)])
    return out


def geomdl_strips_error(case, got, d, times):
    """Largest relative difference between geomdl's elevated strips of the
    original and geomdl's strips of our elevated surface."""
    theirs, mine = strips(case, d), strips(got, d)
    if len(theirs) != len(mine):
        return float("inf")
    p = case["degree"][d]
    worst = 0.0
    scale = max(abs(x) for row in case["points"] for pt in row for x in pt)
    for a, b in zip(theirs, mine):
        # Lines of the strip along d: columns for u, rows for v.
        lines = [[a[i][j] for i in range(len(a))] for j in range(len(a[0]))] if d == 0 else a
        elevated = [helpers.degree_elevation(p, line, num=times) for line in lines]
        expect = [[elevated[j][i] for j in range(len(elevated))] for i in range(p + times + 1)] if d == 0 else elevated
        if len(expect) != len(b) or len(expect[0]) != len(b[0]):
            return float("inf")
        for er, br in zip(expect, b):
            for e, x in zip(er, br):
                cart_e = [c / e[-1] for c in e[:-1]]
                cart_x = [c / x[-1] for c in x[:-1]]
                worst = max(worst, max(abs(u - v) for u, v in zip(cart_e, cart_x)) / scale)
                worst = max(worst, abs(e[-1] - x[-1]) / max(abs(e[-1]), 1e-300))
    return worst
