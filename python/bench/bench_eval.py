"""Evaluating a curve at many arbitrary parameters: ``NurbsCurve.eval``
against scipy's ``BSpline.__call__``, measured in one run.

The same non-rational cubic (a plane curve of 100 control points on a
clamped uniform knot vector) is built in both libraries, and both evaluate
it at the same 10⁶ parameters drawn uniformly from its domain, unsorted:
scipy's ``BSpline.__call__`` (de Boor, one thread) against t2spline's
``eval`` (de Boor at each parameter, in chunks on the thread pool) and
``sample`` (the sampling engine: the power form of each span). Each side
is timed in a child process, t2spline on one thread
(``RAYON_NUM_THREADS=1``) and on its default pool; the sides alternate round
by round on a shared, noisy machine, every figure is a ratio within one
round, and the median ratio is reported. Before timing, the values are
compared (they agree to 1e-12).

    python python/bench/bench_eval.py [--rounds 5] [--points 1000000]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from typing import Callable, Dict, List, Optional

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


def seconds_of(f: Callable[[np.ndarray], object], t: np.ndarray) -> float:
    """The least of three timed calls after a warm-up call."""
    f(t)
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        f(t)
        best = min(best, time.perf_counter() - start)
    return best


def ours(count: int, method: str) -> float:
    import t2spline

    points, knots = curve_data()
    curve = t2spline.NurbsCurve(points, knots=knots, degree=DEGREE)
    return seconds_of(getattr(curve, method), parameters(count))


def theirs(count: int) -> float:
    from scipy.interpolate import BSpline  # type: ignore[import-untyped]

    points, knots = curve_data()
    spline = BSpline(knots, points, DEGREE, extrapolate=False)
    return seconds_of(spline, parameters(count))


def in_child(side: str, count: int, threads: Optional[int]) -> float:
    """Seconds of one side (`theirs`, or one of our methods), timed in a
    fresh process (one thread if asked)."""
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
    parser.add_argument("--child", choices=["eval", "sample", "theirs"], help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(theirs(args.points) if args.child == "theirs" else ours(args.points, args.child))
        return
    difference = check_agreement(args.points)
    if difference > 1e-12:
        sys.exit(f"t2spline and scipy disagree by {difference:.3g}")
    ratios: Dict[str, List[float]] = {}
    for _ in range(args.rounds):
        scipy_s = in_child("theirs", args.points, None)
        for method in ("eval", "sample"):
            for threads in (1, None):
                name = f"{method}, {'one thread' if threads else 'thread pool'}"
                ratios.setdefault(name, []).append(in_child(method, args.points, threads) / scipy_s)
    print(
        f"{args.points} unsorted parameters, cubic of {CONTROL_POINTS} points "
        f"(largest difference from scipy {difference:.2g}); last round scipy {scipy_s * 1e3:.1f} ms"
    )
    for name, values in ratios.items():
        rounds = ", ".join(f"{r:.2f}" for r in values)
        print(f"  t2spline {name} / scipy: median {statistics.median(values):.2f}  (rounds {rounds})")

if __name__ == "__main__":
    main()
