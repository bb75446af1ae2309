"""Surface evaluation S(u, v): t2spline against geomdl (A3.5/A4.3) and splipy
(rational tensor-product evaluation), on a grid of both domain ends, every
interior knot and random values in each direction."""

from common import answered, relative_error, Topic
from common_surface import coordinate_scale, geomdl_surface, grid_params, kind, random_surface, splipy_points

CASES = 150


def run(rng, binary):
    topic = Topic("surface evaluation")
    cases = []
    for _ in range(CASES):
        s = random_surface(rng)
        cases.append(dict(s, op="surface_derivatives", order=0, params=grid_params(rng, s)))
    for i, case, result in answered(topic, binary, cases):
        got = [d[0][0] for d in result["derivatives"]]
        scale = coordinate_scale(case)
        g = geomdl_surface(case)
        geomdl = [g.derivatives(u, v, 0)[0][0] for u, v in case["params"]]
        topic.check(i, "geomdl", relative_error(got, geomdl, scale), kind(case))
        topic.check(i, "splipy", relative_error(got, splipy_points(case, case["params"]), scale), kind(case))
    return topic
