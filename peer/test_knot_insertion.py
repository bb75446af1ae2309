"""Knot insertion and refinement: t2spline (A5.1, A5.4) against geomdl
(operations.insert_knot, A5.1) and scipy (FITPACK's insert on the homogeneous
coefficients (wP, w)). Knots are random, existing interior knots, and the ends
of the domain of unclamped curves; insertion goes up to full multiplicity.

geomdl is asked only what it supports: a knot strictly inside the domain, at
most degree − multiplicity times (its A5.1 refuses multiplicity p + 1 and,
forced with check_num=False, leaves an empty control point; its span search
assumes U[span] <= u < U[n]). scipy covers every case. Refinement is compared with FITPACK's insertions one knot at a time."""

import numpy as np
from geomdl import operations
from scipy.interpolate import insert as fitpack_insert

from common import answered, compare_curves, domain, geomdl_as_dict, geomdl_curve, homogeneous, multiplicity, random_curve, Topic

CASES = 250


def knot_choice(rng, curve):
    a, b = domain(curve)
    inner = sorted({u for u in curve["knots"] if a < u < b and multiplicity(curve, u) <= curve["degree"]})
    options = [rng.uniform(a, b)]
    if inner:
        options.append(rng.choice(inner))
    if curve["kind"] == "unclamped":
        options += [a, b]
    return rng.choice(options)


def scipy_insert(curve, knots):
    """FITPACK insertions, one at a time; the curve as a dict."""
    t = np.array(curve["knots"], dtype=float)
    h = homogeneous(curve)
    n, k = len(h), curve["degree"]
    for u in knots:
        tck = (t, [h[:, j] for j in range(h.shape[1])], k)
        t, c, _ = fitpack_insert(u, tck, m=1)
        n += 1
        h = np.array(c).T[:n]
    return {
        "degree": k,
        "knots": list(t),
        "points": (h[:, :-1] / h[:, -1:]).tolist(),
        "weights": list(h[:, -1]),
    }


def run(rng, binary):
    topic = Topic("knot insertion")
    cases = []
    for _ in range(CASES):
        curve = random_curve(rng)
        p = curve["degree"]
        if rng.random() < 0.75:
            u = knot_choice(rng, curve)
            room = p + 1 - multiplicity(curve, u)
            cases.append(dict(curve, op="insert", knot=u, times=rng.randint(1, room)))
        else:
            new = [knot_choice(rng, curve) for _ in range(rng.randint(1, 6))]
            new = [u for j, u in enumerate(new) if multiplicity(curve, u) + new[: j + 1].count(u) <= p + 1]
            cases.append(dict(curve, op="refine", new_knots=new))
    for i, case, result in answered(topic, binary, cases):
        got = result["curve"]
        if case["op"] == "insert":
            u, times = case["knot"], case["times"]
            detail = f"insert {u} x{times}, {case['kind']}, degree {case['degree']}"
            a, b = domain(case)
            if a < u < b and times <= case["degree"] - multiplicity(case, u):
                g = geomdl_curve(case)
                operations.insert_knot(g, [u], [times])
                topic.check(i, "geomdl", compare_curves(got, geomdl_as_dict(g)), detail)
            topic.check(i, "scipy", compare_curves(got, scipy_insert(case, [u] * times)), detail)
        else:
            detail = f"refine {case['new_knots']}, {case['kind']}"
            topic.check(i, "scipy", compare_curves(got, scipy_insert(case, sorted(case["new_knots"]))), detail)
    return topic
