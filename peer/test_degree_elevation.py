"""Degree elevation by 1-3: t2spline (A5.9) against geomdl and scipy.

geomdl 5.4.0's own `operations.degree_operations` is wrong for curves of more
than one span: it links the elevated Bézier pieces with shifted knots and
removes one knot too many (for the knots [0, 0, 0, .5, 1, 1, 1] it returns
[0, 0, 0, 0, 1, 2, 2, 2, 2]). So geomdl is used where it is right: both curves,
the original and our elevated one, are decomposed into Bézier segments by
geomdl (`operations.decompose_curve`, knot insertion), the original segments
are elevated by geomdl (`helpers.degree_elevation`, Eq. 5.36), and their
control points and weights must equal those of our segments. Bézier segments
are unique, so this compares our control net segment by segment. geomdl's
decomposition needs a clamped, continuous curve: unclamped curves and knots of
full multiplicity are left to scipy.

For every case, scipy checks the geometry:
the elevated curve (ours) and the original curve, both evaluated by scipy at
the ends, every knot and 40 random parameters, must agree; and every knot's
multiplicity must have grown by the number of elevations."""

from geomdl import helpers, operations

from common import answered, compare_curves, coordinate_scale, domain, geomdl_as_dict, geomdl_curve, multiplicity, params, random_curve, relative_error, scipy_points, Topic

CASES = 250


def run(rng, binary):
    topic = Topic("degree elevation")
    cases = []
    for _ in range(CASES):
        curve = random_curve(rng)
        cases.append(dict(curve, op="elevate", times=rng.randint(1, 3)))
    for i, case, result in answered(topic, binary, cases):
        got = result["curve"]
        p, times = case["degree"], case["times"]
        detail = f"degree {p} + {times}, {case['kind']}"
        a, b = domain(case)
        for u in set(case["knots"]):
            if a <= u <= b and case["kind"] != "unclamped":
                if multiplicity(got, u) != multiplicity(case, u) + times:
                    topic.fail(i, f"knot {u}: multiplicity {multiplicity(got, u)}, expected {multiplicity(case, u)} + {times}")
        ts = params(rng, case, 40)
        got_points = scipy_points(got, ts)
        topic.check(i, "scipy", relative_error(got_points, scipy_points(case, ts), coordinate_scale(case)), detail)
        full = any(multiplicity(case, u) > p for u in case["knots"] if a < u < b)
        if case["kind"] != "unclamped" and not full:
            topic.check(i, "geomdl", geomdl_segments_error(case, got, times), detail)
    return topic


def bezier(segment):
    """A geomdl Bézier segment as a curve dict (knots left out)."""
    d = geomdl_as_dict(segment)
    return dict(d, knots=[0.0] * (2 * d["degree"] + 2))


def geomdl_segments_error(case, got, times):
    """Largest difference between geomdl's elevated Bézier segments of the
    original and geomdl's Bézier segments of our elevated curve."""
    theirs = operations.decompose_curve(geomdl_curve(case))
    mine = operations.decompose_curve(geomdl_curve(got))
    if len(theirs) != len(mine):
        return float("inf")
    worst = 0.0
    for a, b in zip(theirs, mine):
        elevated = helpers.degree_elevation(a.degree, a.ctrlptsw, num=times)
        w = [row[-1] for row in elevated]
        expected = {
            "degree": a.degree + times,
            "knots": [0.0] * (2 * (a.degree + times) + 2),
            "points": [[x / row[-1] for x in row[:-1]] for row in elevated],
            "weights": w,
        }
        worst = max(worst, compare_curves(bezier(b), expected))
    return worst
