"""Evaluation C(t): t2spline against geomdl (A3.1/A4.1) and scipy (de Boor on
(wP, w), divided by w), at both ends of the domain, every interior knot and
random parameters."""

from common import answered, coordinate_scale, geomdl_curve, params, random_curve, relative_error, scipy_points, Topic

CASES = 250


def run(rng, binary):
    topic = Topic("evaluation")
    cases = []
    for _ in range(CASES):
        curve = random_curve(rng)
        cases.append(dict(curve, op="derivatives", order=0, params=params(rng, curve, 12)))
    for i, case, result in answered(topic, binary, cases):
        got = [d[0] for d in result["derivatives"]]
        scale = coordinate_scale(case)
        g = geomdl_curve(case)
        reference = [g.derivatives(t, 0)[0] for t in case["params"]]
        topic.check(i, "geomdl", relative_error(got, reference, scale), case["kind"])
        topic.check(i, "scipy", relative_error(got, scipy_points(case, case["params"]), scale), case["kind"])
    return topic
