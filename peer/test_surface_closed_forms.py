"""Each surface peer on a closed form before it is trusted, and t2spline on
the same: the quarter cylinder of radius 2 and height 3 about the z axis
(rational quadratic in u with weights 1, √2/2, 1; linear in v) must have every
point at radius 2, the partial derivatives at u = 0 must be
S_u = (0, 2·√2, 0) and S_v = (0, 0, 3), and knot insertion and degree
elevation (one span, and two spans after inserting u = 0.5) must keep the
radius. splipy's elevation must also give each knot of u once more; geomdl
5.4.0's surface `degree_operations` must still be the no-op it is (else the
elevation topic should use it), and its Bézier elevation of each strip (the
route the elevation topic takes) must keep the radius."""

import math

import numpy as np
from geomdl import helpers, operations

from common import ours, Topic
from common_surface import geomdl_as_case, geomdl_surface, splipy_as_case, splipy_points, splipy_surface
from test_surface_degree_elevation import strips

R, H = 2.0, 3.0


def cylinder():
    w = math.sqrt(0.5)
    corner = [[R, 0.0], [R, R], [0.0, R]]
    return {
        "kinds": ["clamped-uniform", "clamped-uniform"],
        "degree": [2, 1],
        "knots": [[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], [0.0, 0.0, 1.0, 1.0]],
        "points": [[[x, y, 0.0], [x, y, H]] for x, y in corner],
        "weights": [[1.0, 1.0], [w, w], [1.0, 1.0]],
    }


PAIRS = [[u / 10.0, v / 4.0] for u in range(11) for v in range(5)]


def radius_error(points):
    return max(abs(math.hypot(p[0], p[1]) - R) / R for p in points)


def run(rng, binary):
    topic = Topic("surface closed forms")
    c = cylinder()
    two = splipy_surface(c)
    two.insert_knot([0.5], direction=0)
    two = dict(splipy_as_case(two), kinds=c["kinds"])
    cases = [dict(c, op="surface_derivatives", order=1, params=PAIRS)]
    for base in (c, two):
        cases.append(dict(base, op="surface_elevate", direction="u", times=1))
        cases.append(dict(base, op="surface_insert", direction="u", knot=0.3, times=2))
    results = ours(binary, cases)
    topic.cases = len(cases)
    expected_su, expected_sv = [0.0, 2.0 * math.sqrt(2.0), 0.0], [0.0, 0.0, H]
    # Ours.
    d = results[0]["derivatives"]
    topic.check(0, "t2spline", radius_error([x[0][0] for x in d]), "radius")
    at0 = [x for x, uv in zip(d, PAIRS) if uv[0] == 0.0]
    topic.check(0, "t2spline", max(np.max(np.abs(np.array(x[1][0]) - expected_su)) for x in at0) / R, "S_u(0, v)")
    topic.check(0, "t2spline", max(np.max(np.abs(np.array(x[0][1]) - expected_sv)) for x in at0) / H, "S_v(0, v)")
    for k in range(1, len(cases)):
        got = results[k]["surface"]
        topic.check(k, "t2spline", radius_error(splipy_points(got, PAIRS)), cases[k]["op"])
    # geomdl.
    g = geomdl_surface(c)
    topic.check(0, "geomdl", radius_error([g.evaluate_single(uv) for uv in PAIRS]), "radius")
    ders = [g.derivatives(0.0, v, 1) for v in (0.0, 0.5, 1.0)]
    topic.check(0, "geomdl", max(np.max(np.abs(np.array(x[1][0]) - expected_su)) for x in ders) / R, "S_u(0, v)")
    topic.check(0, "geomdl", max(np.max(np.abs(np.array(x[0][1]) - expected_sv)) for x in ders) / H, "S_v(0, v)")
    for k, base in enumerate((c, two)):
        g = geomdl_surface(base)
        before = geomdl_as_case(g)
        operations.degree_operations(g, [1, 0])
        if geomdl_as_case(g) != before:
            topic.fail(k, "geomdl's degree_operations changed a surface: revisit test_surface_degree_elevation.py")
        g = geomdl_surface(base)
        operations.insert_knot(g, [0.3, None], [2, 0])
        topic.check(k, "geomdl", radius_error(splipy_points(geomdl_as_case(g), PAIRS)), "insertion")
    # geomdl's Bézier elevation per strip (the route test_surface_degree_elevation.py
    # takes) keeps the cylinder.
    for k, strip in enumerate(strips(two, 0)):
        lines = [[strip[i][j] for i in range(3)] for j in range(2)]
        elevated = [helpers.degree_elevation(2, line, num=1) for line in lines]
        pts = [[[x / e[-1] for x in e[:-1]] for e in (elevated[0][i], elevated[1][i])] for i in range(4)]
        strip_case = {
            "degree": [3, 1],
            "knots": [[0.0] * 4 + [1.0] * 4, [0.0, 0.0, 1.0, 1.0]],
            "points": pts,
            "weights": [[elevated[0][i][-1], elevated[1][i][-1]] for i in range(4)],
        }
        topic.check(k, "geomdl", radius_error(splipy_points(strip_case, PAIRS)), "Bézier elevation of a strip")
    # splipy.
    s = splipy_surface(c)
    topic.check(0, "splipy", radius_error(splipy_points(c, PAIRS)), "radius")
    su = [s.derivative(0.0, v, d=(1, 0)) for v in (0.0, 0.5, 1.0)]
    sv = [s.derivative(0.0, v, d=(0, 1)) for v in (0.0, 0.5, 1.0)]
    topic.check(0, "splipy", max(np.max(np.abs(np.asarray(x) - expected_su)) for x in su) / R, "S_u(0, v)")
    topic.check(0, "splipy", max(np.max(np.abs(np.asarray(x) - expected_sv)) for x in sv) / H, "S_v(0, v)")
    for k, base in enumerate((c, two)):
        s = splipy_surface(base)
        s.raise_order(1, 0)
        e = splipy_as_case(s)
        want = sorted(base["knots"][0] + sorted(set(base["knots"][0])))
        if e["knots"][0] != want:
            topic.fail(k, f"splipy elevation knots {e['knots'][0]}, expected {want}")
        topic.check(k, "splipy", radius_error(splipy_points(e, PAIRS)), "elevation")
    topic.note = "geomdl 5.4.0 operations.degree_operations leaves surfaces unchanged (a stub); its Bézier elevation per strip is used instead"
    return topic
