"""Peer check of `t2spline fit` of a net of data points (a surface) against
geomdl 5.4.0, live.

For random nets of fuzzy data points (3 to 12 rows and columns, degrees 1-3
in each direction, chord-length and centripetal parameters, interpolation and
least squares with fewer control points in one or both directions), writes a
data file of the net, runs the real `t2spline fit` binary and compares the job
file it writes with geomdl's implementation of the same algorithms:

  interpolation  geomdl `fitting.interpolate_surface` (The NURBS Book A9.4,
                 parameters averaged over rows and columns as in A9.3)
  least squares  geomdl `fitting.approximate_surface` (A9.7: every column,
                 then every row of the intermediate points, fitted by least
                 squares with the end points interpolated)

Compared: the knot vectors in u and v and the crisp layer's control points;
with `--fuzzy-fit independent`, every one of the seven layers (each is fitted
as the crisp one is), unless t2spline refuses the fit because the layers'
control points break the order of the seven values.

Errors are relative to max(1, the largest coordinate of geomdl's control
points); the tolerance is 1e-9. geomdl solves least squares through the
normal equations (LU without pivoting), which squares the condition number;
the nets here are small and well spread, where that costs no more than a few
digits.

    peer/.venv/bin/python peer/fit/check_fit_surface.py --bin target/release/t2spline [--cases 200] [--seed S]

Exits with 1 on any mismatch.
"""

import argparse
import json
import random
import subprocess
import sys
import tempfile
from pathlib import Path

from geomdl import fitting

TOLERANCE = 1e-9
LAYERS = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right", "upper_right"]
AXES = "xyz"


def number(rng: random.Random, crisp: float, spreads=None) -> dict:
    """A fuzzy number around `crisp`: the given spreads `(left, right)`, or
    spreads drawn inner to outer, zero a third of the time."""
    def side() -> list:
        s = sorted(0.0 if rng.random() < 1 / 3 else rng.uniform(0, 0.4) for _ in range(3))
        return s
    left, right = spreads if spreads is not None else (side(), side())
    return {
        "crisp": crisp,
        "upper": [crisp - left[2], crisp + right[2]],
        "primary": [crisp - left[1], crisp + right[1]],
        "lower": [crisp - left[0], crisp + right[0]],
    }


def layer_value(n: dict, layer: str) -> float:
    if layer == "crisp":
        return n["crisp"]
    function, side = layer.split("_")
    return n[function][0 if side == "left" else 1]


def random_case(rng: random.Random) -> dict:
    p, q = rng.randint(1, 3), rng.randint(1, 3)
    rows, columns = rng.randint(max(p + 1, 3), 12), rng.randint(max(q + 1, 3), 12)
    # A bumpy graph over a jittered grid: no two neighbours coincide. Half
    # of the nets have the same spreads everywhere, which fitting each layer
    # on its own keeps in order, so that all seven layers are compared.
    same = rng.random() < 0.5
    fixed = {a: ([0.1, 0.2, 0.3], [0.05, 0.25, 0.4]) for a in AXES}
    net = []
    for i in range(rows):
        row = []
        for j in range(columns):
            x = i + rng.uniform(-0.3, 0.3)
            y = 0.7 * j + rng.uniform(-0.2, 0.2)
            z = rng.uniform(-2, 2)
            row.append({a: number(rng, c, fixed[a] if same else None) for a, c in zip(AXES, (x, y, z))})
        net.append(row)
    control = None
    least = [max(p + 1, 3), max(q + 1, 3)]
    if rng.random() < 0.5 and rows > least[0] and columns > least[1]:
        # Fewer control points than data in both directions: with as many as
        # data t2spline interpolates on the averaging knots (Eq. 9.8), where
        # geomdl keeps Eq. 9.69's knots; and geomdl's least squares needs an
        # interior control point in each direction (at least 3).
        control = [rng.randint(least[0], rows - 1), rng.randint(least[1], columns - 1)]
    return {
        "degree": [p, q],
        "net": net,
        "control": control,
        "centripetal": rng.random() < 0.5,
        "mode": "independent" if rng.random() < 0.5 else "valid",
    }


def geomdl_fit(case: dict, layer: str):
    net = case["net"]
    rows, columns = len(net), len(net[0])
    points = [[layer_value(net[i][j][a], layer) for a in AXES] for i in range(rows) for j in range(columns)]
    p, q = case["degree"]
    if case["control"] is None:
        return fitting.interpolate_surface(points, rows, columns, p, q, centripetal=case["centripetal"])
    m, n = case["control"]
    return fitting.approximate_surface(
        points, rows, columns, p, q, ctrlpts_size_u=m, ctrlpts_size_v=n, centripetal=case["centripetal"]
    )


def run_fit(binary: str, case: dict, folder: Path):
    data = {"degree": case["degree"], "lower_height": 0.5, "points": case["net"]}
    path = folder / "net.json"
    path.write_text(json.dumps(data))
    args = [binary, "fit", str(path), "-q", "--fuzzy-fit", case["mode"],
            "--parametrization", "centripetal" if case["centripetal"] else "chord"]
    if case["control"] is not None:
        args += ["--control-points", f"{case['control'][0]},{case['control'][1]}"]
    done = subprocess.run(args, capture_output=True, text=True)
    return done


def compare(case: dict, job: dict, layers: list) -> list:
    problems = []
    for layer in layers:
        surface = geomdl_fit(case, layer)
        scale = max(1.0, max(abs(c) for pt in surface.ctrlpts for c in pt))
        if layer == "crisp":
            for direction, want in (("u", surface.knotvector_u), ("v", surface.knotvector_v)):
                got = job["knots"][direction]
                if len(got) != len(want) or max(abs(a - b) for a, b in zip(got, want)) > TOLERANCE:
                    problems.append(f"knots.{direction}: {got} != geomdl {want}")
        rows = job["points"]
        got = [[layer_value(pt[a], layer) for a in AXES] for row in rows for pt in row]
        if len(got) != len(surface.ctrlpts):
            problems.append(f"{layer}: {len(got)} control points, geomdl {len(surface.ctrlpts)}")
            continue
        error = max(abs(a - b) for g, w in zip(got, surface.ctrlpts) for a, b in zip(g, w)) / scale
        if error > TOLERANCE:
            problems.append(f"{layer}: control points differ by {error:.3e} (relative)")
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--cases", type=int, default=200)
    parser.add_argument("--seed", type=int, default=20261207)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    failures = 0
    counts = {"interpolation": 0, "least squares": 0, "all seven layers": 0, "refused (order)": 0}
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for k in range(args.cases):
            case = random_case(rng)
            done = run_fit(args.bin, case, folder)
            if done.returncode != 0:
                if case["mode"] == "independent" and "breaks the order" in done.stderr:
                    counts["refused (order)"] += 1
                    continue
                print(f"case {k}: t2spline fit failed: {done.stderr.strip()}")
                failures += 1
                continue
            job = json.loads(done.stdout)
            layers = LAYERS if case["mode"] == "independent" else ["crisp"]
            counts["interpolation" if case["control"] is None else "least squares"] += 1
            if len(layers) == 7:
                counts["all seven layers"] += 1
            problems = compare(case, job, layers)
            if problems:
                failures += 1
                print(f"case {k} (degree {case['degree']}, {len(case['net'])} x {len(case['net'][0])}, "
                      f"control {case['control']}, centripetal {case['centripetal']}):")
                for line in problems:
                    print("   ", line)
    print(f"check_fit_surface: {args.cases} nets, {failures} mismatches; " +
          ", ".join(f"{name} {count}" for name, count in counts.items()))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
