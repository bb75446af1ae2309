"""Evaluating a curve at many arbitrary parameters: ``NurbsCurve.eval``
against scipy's ``BSpline.__call__``, measured in one run.

The same non-rational cubic (a plane curve of 100 control points on a
clamped uniform knot vector) is built in both libraries, and both evaluate
it at the same 10⁶ parameters drawn uniformly from its domain, unsorted. The
two sides alternate round by round on a shared, noisy machine, and every
figure is a ratio within one round; the median ratio is reported. scipy
evaluates on one thread; t2spline is timed on one thread
(``RAYON_NUM_THREADS=1`` in a child process) and with its default thread
pool. Before timing, the two results are compared (they agree to 1e-12).

    python python/bench/bench_eval.py [--rounds 5] [--points 1000000]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time

import numpy as np

CONTROL_POINTS = 100
DEGREE = 3


def curve_data() -> tuple[np.ndarray, np.ndarray]:
    """The control points (a wave) and the clamped uniform knots."""
    n = CONTROL_POINTS
    x = np.linspace(0.0, 10.0, n)
    points = np.column_stack([x, np.sin(x) + 0.1 * np.cos(7.0 * x)])
    inner = np.linspace(0.0, 1.0, n - DEGREE + 1)
    knots = np.concatenate([[0.0] * DEGREE, inner, [1.0] * DEGREE])
    return points, knots


def parameters(count: int) -> np.ndarray:
    return np.random.default_rng(7).uniform(0.0, 1.0, count)


def seconds_of(f, t: np.ndarray) -> float:
    """The least of three timed calls after a warm-up call."""
    f(t)
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        f(t)
        best = min(best, time.perf_counter() - start)
    return best


def ours(count: int) -> float:
    import t2spline

    points, knots = curve_data()
    curve = t2spline.NurbsCurve(points, knots=knots, degree=DEGREE)
    return seconds_of(curve.eval, parameters(count))


def theirs(count: int) -> float:
    from scipy.interpolate import BSpline

    points, knots = curve_data()
    spline = BSpline(knots, points, DEGREE, extrapolate=False)
    return seconds_of(spline, parameters(count))


def in_child(side: str, count: int, threads: int | None) -> float:
    """Seconds of one side, timed in a fresh process (one thread if asked)."""
    env = dict(os.environ)
    if threads is not None:
        env["RAYON_NUM_THREADS"] = str(threads)
    out = subprocess.run(
        [sys.executable, __file__, "--child", side, "--points", str(count)],
        check=True,
        capture_output=True,
        text=True,
        env=env,
    ).stdout
    return float(out.strip())


def check_agreement(count: int) -> float:
    """The largest difference between the two libraries' values."""
    import t2spline
    from scipy.interpolate import BSpline

    points, knots = curve_data()
    t = parameters(min(count, 100_000))
    a = t2spline.NurbsCurve(points, knots=knots, degree=DEGREE).eval(t)
    b = BSpline(knots, points, DEGREE, extrapolate=False)(t)
    return float(np.abs(a - b).max())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--child", choices=["ours", "theirs"], help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print((ours if args.child == "ours" else theirs)(args.points))
        return
    difference = check_agreement(args.points)
    if difference > 1e-12:
        sys.exit(f"t2spline and scipy disagree by {difference:.3g}")
    one, pool = [], []
    for _ in range(args.rounds):
        scipy_s = in_child("theirs", args.points, None)
        one.append(in_child("ours", args.points, 1) / scipy_s)
        pool.append(in_child("ours", args.points, None) / scipy_s)
    print(
        f"eval of {args.points} unsorted parameters, cubic of {CONTROL_POINTS} points "
        f"(largest difference from scipy {difference:.2g}); last round scipy {scipy_s * 1e3:.1f} ms"
    )
    print(f"  t2spline / scipy, one thread:  median {statistics.median(one):.2f}  (rounds {', '.join(f'{r:.2f}' for r in one)})")
    print(f"  t2spline / scipy, thread pool: median {statistics.median(pool):.2f}  (rounds {', '.join(f'{r:.2f}' for r in pool)})")


if __name__ == "__main__":
    main()
