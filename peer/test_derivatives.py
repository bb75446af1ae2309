"""Derivatives C', ..., C^(K) of rational curves, K from 1 to degree + 2 (above
the degree the rational derivatives do not vanish): t2spline (A2.3, A3.2, A4.2)
against geomdl (A3.2 + A4.2) and scipy (derivatives of the homogeneous B-spline
(wP, w), then Leibniz's rule for the quotient), at both ends of the domain,
every interior knot (one-sided: the span to the right, the last span at the
end) and random parameters.

The error of order k is relative to the largest reference value of that order
in the case, but at least (largest coordinate)·(domain length)^-k, the natural
size of a k-th derivative of the curve."""

from common import answered, coordinate_scale, domain, geomdl_curve, params, random_curve, relative_error, scipy_derivatives, Topic

CASES = 250


def run(rng, binary):
    topic = Topic("derivatives")
    cases = []
    for _ in range(CASES):
        curve = random_curve(rng)
        order = rng.randint(1, curve["degree"] + 2)
        cases.append(dict(curve, op="derivatives", order=order, params=params(rng, curve)))
    for i, case, result in answered(topic, binary, cases):
        g = geomdl_curve(case)
        a, b = domain(case)
        peers = {
            "geomdl": [g.derivatives(t, case["order"]) for t in case["params"]],
            "scipy": [scipy_derivatives(case, t, case["order"]) for t in case["params"]],
        }
        for peer, reference in peers.items():
            for k in range(1, case["order"] + 1):
                ref_k = [r[k] for r in reference]
                got_k = [d[k] for d in result["derivatives"]]
                natural = coordinate_scale(case) * (b - a) ** -k
                scale = max(natural, max(abs(x) for r in ref_k for x in r))
                topic.check(i, peer, relative_error(got_k, ref_k, scale), f"order {k}, {case['kind']}")
    return topic
