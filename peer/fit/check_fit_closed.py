"""Peer check of `t2spline fit --closed` against scipy's FITPACK, live.

For random loops of fuzzy data points (2-D and 3-D, degrees 1-5, 3-40
distinct points, chord-length, centripetal and uniform parameters), runs the
real `t2spline fit --closed` binary (interpolation) and compares the job file
it writes with scipy `interpolate.splprep(per=1, s=0)`, which runs FITPACK's
periodic interpolation (`percur`/`fpperi`) on the same loop, its last point
repeating the first, with the same parameters `u` (computed here, the closing
chord counted):

  knots         splprep's knot vector (for odd k the parameters, for even k
                their midpoints, extended periodically), value by value
  crisp layer   splprep's coefficients against the job's crisp control points
                (the first k repeated at the end in both)
  every layer   with `--fuzzy-fit independent`, each of the seven layers
                against splprep on that layer's values (same u), when the
                independent fit is valid and written
  evaluation    scipy `BSpline` of the job against `splev` of splprep at 200
                points of the domain, and at the data parameters against the
                data (the curve passes through every point)
  seam          derivatives 0 .. k-1 of the job's curve at both ends of [0, 1]

Errors are relative to max(1, the largest coordinate); the tolerance is 1e-9.

    /work/venv-py/bin/python peer/fit/check_fit_closed.py --bin target/debug/t2spline [--cases 200] [--seed S]

Exits with 1 on any mismatch.
"""

import argparse
import json
import math
import os
import random
import subprocess
import sys
import tempfile

import numpy as np
from scipy.interpolate import BSpline, splev, splprep

TOLERANCE = 1e-9
AXES = "xyz"
LAYERS = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right", "upper_right"]


def random_loop(rng, count, dim):
    """A star-shaped loop about a random centre: angles and radii jittered."""
    centre = [rng.uniform(-50, 50) for _ in range(dim)]
    points = []
    for k in range(count):
        a = 2 * math.pi * (k + rng.uniform(-0.3, 0.3)) / count
        r = rng.uniform(2, 10)
        crisp = [centre[0] + r * math.cos(a), centre[1] + r * math.sin(a)]
        if dim == 3:
            crisp.append(centre[2] + rng.uniform(-3, 3))
        coords = {}
        for d in range(dim):
            c = crisp[d]
            left = sorted(rng.uniform(0, 0.5) for _ in range(3))
            right = sorted(rng.uniform(0, 0.5) for _ in range(3))
            coords[AXES[d]] = {
                "crisp": c,
                "upper": [c - left[2], c + right[2]],
                "primary": [c - left[1], c + right[1]],
                "lower": [c - left[0], c + right[0]],
            }
        points.append(coords)
    return points


def layer_value(number, layer):
    side = 0 if layer.endswith("left") else 1
    name = layer.split("_")[0]
    return number["crisp"] if layer == "crisp" else number[name][side]


def loop_parameters(crisp, method):
    """u_0 = 0 .. u_N = 1 around the loop, the closing chord counted."""
    n = len(crisp)
    if method == "uniform":
        return np.arange(n + 1) / n
    closed = np.vstack([crisp, crisp[:1]])
    chords = np.linalg.norm(np.diff(closed, axis=0), axis=1)
    if method == "centripetal":
        chords = np.sqrt(chords)
    s = np.concatenate([[0.0], np.cumsum(chords)])
    return s / s[-1]


def rel_error(ours, ref):
    ours, ref = np.asarray(ours, float), np.asarray(ref, float)
    return float(np.max(np.abs(ours - ref)) / max(1.0, float(np.max(np.abs(ref)))))


def job_curve(job, layer, dim):
    knots = np.array(job["knots"], float)
    control = np.array([[layer_value(p[AXES[d]], layer) for d in range(dim)] for p in job["points"]])
    return knots, control


def check_case(binary, rng, case, worst):
    dim = rng.choice([2, 3])
    degree = rng.randint(1, 5)
    count = rng.randint(max(degree + 1, 3), 40)
    method = rng.choice(["chord", "centripetal", "uniform"])
    mode = rng.choice(["valid", "independent"])
    points = random_loop(rng, count, dim)
    data = {"degree": degree, "lower_height": 0.5, "points": points}
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "data.json")
        with open(path, "w") as f:
            json.dump(data, f)
        out = subprocess.run(
            [binary, "fit", path, "--closed", "--parametrization", method, "--fuzzy-fit", mode, "-q"],
            capture_output=True,
            text=True,
        )
    label = f"case {case}: dim {dim}, degree {degree}, {count} points, {method}, {mode}"
    worst.setdefault("cases of degree", {}).setdefault(degree, 0)
    worst["cases of degree"][degree] += 1
    if out.returncode != 0:
        if mode == "independent" and "breaks the order" in out.stderr:
            worst["refused (independent layers cross)"] = worst.get("refused (independent layers cross)", 0) + 1
            return []  # refused as it should be when the layers cross
        return [f"{label}: t2spline failed: {out.stderr.strip()}"]
    job = json.loads(out.stdout)
    problems = []

    def check(what, error):
        worst[what] = max(worst.get(what, 0.0), error)
        if not error <= TOLERANCE:
            problems.append(f"{label}: {what}: relative error {error:.3e}")

    crisp = np.array([[p[AXES[d]]["crisp"] for d in range(dim)] for p in points])
    u = loop_parameters(crisp, method)
    layers = LAYERS if mode == "independent" else ["crisp"]
    for layer in layers:
        q = np.array([[layer_value(p[AXES[d]], layer) for d in range(dim)] for p in points])
        closed = np.vstack([q, q[:1]])
        tck, _ = splprep(list(closed.T), u=u, k=degree, s=0, per=1, quiet=2)
        t, c, k = tck
        knots, control = job_curve(job, layer, dim)
        if layer == "crisp":
            check("knots", rel_error(knots, t))
        check(f"control points ({layer})", rel_error(control, np.array(c).T[: len(control)]))
        ours = BSpline(knots, control, degree)
        s = np.linspace(0, 1, 200)
        check(f"curve ({layer})", rel_error(ours(s), np.array(splev(s, tck)).T))
        check(f"through the data ({layer})", rel_error(ours(u[:-1]), q))
    ours = BSpline(*job_curve(job, "crisp", dim), degree)
    for j in range(degree):
        d = ours.derivative(j) if j else ours
        scale = max(1.0, float(np.max(np.abs(d(np.linspace(0, 1, 50))))))
        worst["seam"] = max(worst.get("seam", 0.0), float(np.max(np.abs(d(0.0) - d(1.0)))) / scale)
        if not np.max(np.abs(d(0.0) - d(1.0))) <= TOLERANCE * scale:
            problems.append(f"{label}: derivative {j} differs across the seam")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True, help="the t2spline binary")
    parser.add_argument("--cases", type=int, default=200)
    parser.add_argument("--seed", type=int, default=20261207)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    worst, problems = {}, []
    for case in range(args.cases):
        problems += check_case(args.bin, rng, case, worst)
    print(f"cases of degree 1-5: {sorted(worst.pop('cases of degree', {}).items())}")
    print(f"independent fits refused (crossing layers): {worst.pop('refused (independent layers cross)', 0)}")
    for what, error in sorted(worst.items()):
        print(f"{what:32s} largest relative error {error:.2e}")
    for p in problems[:20]:
        print(p)
    print(f"{args.cases} cases, {len(problems)} mismatch(es)")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
