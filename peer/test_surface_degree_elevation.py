"""Degree elevation by 1-2 in u or v: t2spline (A5.9 on stacked lines of the
net) against splipy (`Surface.raise_order` on the projective control points)
and geomdl (`operations.degree_operations`).

The elevated surface has every knot of the elevated direction once more per
elevation; in that spline space its representation is unique, so for clamped
directions our net, weights and knots must equal splipy's. For an unclamped
direction t2spline clamps first (same domain) while splipy keeps the knots, so
there the geometry is compared (both evaluated by splipy).

geomdl 5.4.0's `degree_operations` is checked the same way where its knot
vector is right; where it is wrong (the curve suite found wrong knots for
curves of more than one span), only the geometry of its result is measured
and reported on the summary line, not counted as our failure."""

from geomdl import operations

from common import answered, Topic
from common_surface import compare_surfaces, domain, geometry_error, geomdl_as_case, geomdl_surface, kind, multiplicity, random_surface, splipy_as_case, splipy_surface

CASES = 150


def run(rng, binary):
    topic = Topic("surface degree elevation")
    cases = []
    for _ in range(CASES):
        s = random_surface(rng)
        d = rng.randrange(2)
        cases.append(dict(s, op="surface_elevate", direction="uv"[d], times=rng.randint(1, 2)))
    geomdl_wrong = []
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
        s = splipy_surface(case)
        s.raise_order(*([times, 0] if d == 0 else [0, times]))
        theirs = splipy_as_case(s)
        if case["kinds"][d] == "unclamped":
            topic.check(i, "splipy", geometry_error(got, theirs, rng), detail + " (geometry)")
        else:
            topic.check(i, "splipy", compare_surfaces(got, theirs), detail)
        g = geomdl_surface(case)
        operations.degree_operations(g, [times, 0] if d == 0 else [0, times])
        mine = geomdl_as_case(g)
        if mine["knots"] == got["knots"]:
            topic.check(i, "geomdl", compare_surfaces(got, mine), detail)
        else:
            geomdl_wrong.append((i, case["kinds"][d], len(set(case["knots"][d])) > 2, geometry_error(case, mine, rng)))
    multi = [w for w in geomdl_wrong if w[2]]
    worst = max((w[3] for w in geomdl_wrong), default=0.0)
    topic.note = (
        f"geomdl knots wrong in {len(geomdl_wrong)} cases ({len(multi)} with interior knots in the elevated direction); "
        f"geometry of its result off by up to {worst:.2e} relative there"
    )
    return topic
