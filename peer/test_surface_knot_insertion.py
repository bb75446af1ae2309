"""Knot insertion and refinement in u or v: t2spline (A5.1/A5.4 on stacked
lines of the net) against splipy (`Surface.insert_knot`, on the projective
control points) and geomdl (`operations.insert_knot`, A5.3). The result of an
insertion is unique, so the control nets, weights and knots are compared.

geomdl is asked only what it supports, as for curves: a knot strictly inside
the domain, at most degree − multiplicity times."""

from geomdl import operations

from common import answered, Topic
from common_surface import compare_surfaces, domain, geomdl_as_case, geomdl_surface, kind, multiplicity, random_surface, splipy_as_case, splipy_surface

CASES = 150


def knot_choice(rng, case, d):
    a, b = domain(case, d)
    p = case["degree"][d]
    inner = sorted({u for u in case["knots"][d] if a < u < b and multiplicity(case["knots"][d], u) <= p})
    options = [rng.uniform(a, b)]
    if inner:
        options.append(rng.choice(inner))
    if case["kinds"][d] == "unclamped":
        options += [a, b]
    return rng.choice(options)


def run(rng, binary):
    topic = Topic("surface knot insertion")
    cases = []
    for _ in range(CASES):
        s = random_surface(rng)
        d = rng.randrange(2)
        p = s["degree"][d]
        if rng.random() < 0.75:
            u = knot_choice(rng, s, d)
            room = p + 1 - multiplicity(s["knots"][d], u)
            cases.append(dict(s, op="surface_insert", direction="uv"[d], knot=u, times=rng.randint(1, room)))
        else:
            new = [knot_choice(rng, s, d) for _ in range(rng.randint(1, 4))]
            new = [u for j, u in enumerate(new) if multiplicity(s["knots"][d], u) + new[: j + 1].count(u) <= p + 1]
            cases.append(dict(s, op="surface_refine", direction="uv"[d], new_knots=new))
    for i, case, result in answered(topic, binary, cases):
        got = result["surface"]
        d = "uv".index(case["direction"])
        knots = [case["knot"]] * case["times"] if case["op"] == "surface_insert" else sorted(case["new_knots"])
        detail = f"{case['op']} in {case['direction']} {knots}, {kind(case)}, degree {case['degree']}"
        s = splipy_surface(case)
        if knots:
            s.insert_knot(knots, direction=d)
        topic.check(i, "splipy", compare_surfaces(got, splipy_as_case(s)), detail)
        if case["op"] == "surface_insert":
            u, times = case["knot"], case["times"]
            a, b = domain(case, d)
            if a < u < b and times <= case["degree"][d] - multiplicity(case["knots"][d], u):
                g = geomdl_surface(case)
                operations.insert_knot(g, [u, None] if d == 0 else [None, u], [times, 0] if d == 0 else [0, times])
                topic.check(i, "geomdl", compare_surfaces(got, geomdl_as_case(g)), detail)
    return topic
