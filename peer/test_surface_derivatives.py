"""Partial derivatives S^(k,l), k + l up to max(p, q) + 1, of rational
surfaces: t2spline (A3.6 + A4.4) against geomdl (A3.6 + A4.4) and splipy
(derivatives of the homogeneous surface (A, w) of any order, then Leibniz's
rule for the quotient, written in common_surface.py, since splipy's own
rational derivatives stop at order 1). Probes as for evaluation (one-sided at
knots: from the right, the last span at the end).

The error of order (k, l) is relative to the largest reference value of that
order in the case, but at least (largest coordinate)·(u length)^-k·(v length)^-l."""

from common import answered, relative_error, Topic
from common_surface import coordinate_scale, domain, geomdl_surface, grid_params, kind, random_surface, splipy_derivatives

CASES = 120


def run(rng, binary):
    topic = Topic("surface derivatives")
    cases = []
    for _ in range(CASES):
        s = random_surface(rng)
        order = rng.randint(1, max(s["degree"]) + 1)
        cases.append(dict(s, op="surface_derivatives", order=order, params=grid_params(rng, s, 2)))
    for i, case, result in answered(topic, binary, cases):
        order = case["order"]
        g = geomdl_surface(case)
        peers = {
            "geomdl": [g.derivatives(u, v, order) for u, v in case["params"]],
            "splipy": [splipy_derivatives(case, u, v, order) for u, v in case["params"]],
        }
        (au, bu), (av, bv) = domain(case, 0), domain(case, 1)
        for peer, reference in peers.items():
            for k in range(order + 1):
                for l in range(order + 1 - k):
                    if k + l == 0:
                        continue
                    ref = [r[k][l] for r in reference]
                    got = [d[k][l] for d in result["derivatives"]]
                    natural = coordinate_scale(case) * (bu - au) ** -k * (bv - av) ** -l
                    scale = max(natural, max(abs(x) for r in ref for x in r))
                    topic.check(i, peer, relative_error(got, ref, scale), f"order ({k}, {l}), {kind(case)}")
    return topic
