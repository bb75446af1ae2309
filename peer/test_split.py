"""Splitting at a parameter: t2spline (insertion to multiplicity p, then cut)
against geomdl (operations.split_curve) and scipy.

geomdl is asked for clamped curves split strictly between knots of
multiplicity at most p (its split indexes wrongly at knots of full
multiplicity, and it starts from U[p+1]); its pieces come back with knots
normalised to [0, 1], so ours are normalised the same way for the comparison.
For every case scipy checks that each piece, evaluated by scipy on its own
domain (ends, knots, 20 random parameters), is the original curve there. At a
split point where the curve jumps (a knot of full multiplicity) the left piece
ends with the left limit, not with C(t) (the value from the right), so there
its end is compared just before t."""

from geomdl import operations

from common import answered, compare_curves, coordinate_scale, domain, geomdl_as_dict, geomdl_curve, multiplicity, params, random_curve, relative_error, scipy_points, Topic

CASES = 250


def normalised(curve):
    u = curve["knots"]
    lo, hi = u[0], u[-1]
    return dict(curve, knots=[(v - lo) / (hi - lo) for v in u])


def run(rng, binary):
    topic = Topic("splitting")
    cases = []
    for _ in range(CASES):
        curve = random_curve(rng)
        a, b = domain(curve)
        inner = [u for u in curve["knots"] if a < u < b]
        t = rng.choice(inner) if inner and rng.random() < 0.3 else rng.uniform(a, b)
        cases.append(dict(curve, op="split", t=t))
    for i, case, result in answered(topic, binary, cases):
        left, right = result["pieces"]
        detail = f"split at {case['t']}, {case['kind']}, degree {case['degree']}"
        t, (a, b) = case["t"], domain(case)
        jump = multiplicity(case, t) > case["degree"]
        for piece in (left, right):
            ts = params(rng, piece, 20)
            if jump and piece is left:
                ts = [s for s in ts if s != t] + [t - 1e-9 * (b - a)]
            topic.check(i, "scipy", relative_error(scipy_points(piece, ts), scipy_points(case, ts), coordinate_scale(case)), detail)
        full = any(multiplicity(case, u) > case["degree"] for u in case["knots"] if a < u < b)
        if case["kind"] != "unclamped" and not full:
            theirs = operations.split_curve(geomdl_curve(case), case["t"])
            error = max(compare_curves(normalised(mine), geomdl_as_dict(g)) for mine, g in zip((left, right), theirs))
            topic.check(i, "geomdl", error, detail)
    return topic
