"""How big and how quick the pictures in notebooks are (``_repr_html_``).

For the shipped example (``examples/paper-alg-1-1.json``): its fuzzy curve
(stage 1), its solution at the job's alpha (stages 1–4) and one fuzzy
number; for a large curve (3000 control points, drawn thinned) and the
seabed surface (``examples/salish-sea-seabed.json``, a 30 × 40 net drawn on
a thinned grid). Each line gives the size of the HTML in kB and the median
time of ``--rounds`` calls after one warm-up call. The targets are at most
150 kB and about 50 ms for the example's solution; they are reported, not
checked (the machine is shared and noisy).

    python python/bench/bench_repr.py [--rounds 11]
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path
from typing import Callable, List, Tuple

import numpy as np

import t2spline

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "paper-alg-1-1.json"
SEABED = ROOT / "examples" / "salish-sea-seabed.json"


def large_curve(n: int = 3000) -> t2spline.FuzzyCurve:
    """A cubic wave of ``n`` control points with spreads of 0.1."""
    t = np.linspace(0.0, 60.0, n)
    crisp = np.stack([t, np.sin(t)], axis=1)
    spread = np.array([-0.1, 0.1])
    return t2spline.FuzzyCurve(
        crisp,
        crisp[..., None] + spread,
        crisp[..., None] + 0.6 * spread,
        crisp[..., None] + 0.3 * spread,
        lower_height=0.6,
        degree=3,
    )


def measure(draw: Callable[[], object], rounds: int) -> Tuple[float, float]:
    """The HTML's size in kB and the median time in ms of ``rounds`` calls."""
    html = draw()
    assert isinstance(html, str)
    times: List[float] = []
    for _ in range(rounds):
        start = time.perf_counter()
        draw()
        times.append(time.perf_counter() - start)
    return len(html.encode("utf-8")) / 1000.0, 1000.0 * statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=11)
    args = parser.parse_args()
    curve = t2spline.FuzzyCurve.from_job(str(EXAMPLE))
    solution = curve.solve(0.8)
    number = curve.point(0)[0]
    big = large_curve()
    seabed = t2spline.FuzzySurface.from_job(str(SEABED))
    cases: List[Tuple[str, Callable[[], object], int]] = [
        ("example: solution (stages 1-4)", solution._repr_html_, args.rounds),
        ("example: fuzzy curve (stage 1)", curve._repr_html_, args.rounds),
        ("example: fuzzy number", number._repr_html_, args.rounds),
        ("example: region at 0.2", curve.region(0.2)._repr_html_, args.rounds),  # type: ignore[union-attr]
        ("3000-point curve (stage 1, thinned)", big._repr_html_, max(1, args.rounds // 4)),
        ("seabed 30 x 40 (stage 1, thinned)", seabed._repr_html_, max(1, args.rounds // 4)),
    ]
    print(f"{'picture':40} {'size kB':>9} {'median ms':>10}")
    for name, draw, rounds in cases:
        size, ms = measure(draw, rounds)
        print(f"{name:40} {size:9.1f} {ms:10.1f}")


if __name__ == "__main__":
    main()
