"""How much the Python front end costs over the Rust engine, measured in one run.

Two comparisons, each against the command-line tool built from the same
sources (``cargo build --release --bin t2spline``):

1. Sampling the seven layer curves of the benchmark curve at 10⁶ parameters
   on one thread: ``FuzzyCurve.sample(1_000_000)`` on
   ``t2spline.benchmark_curve()`` against
   ``t2spline bench --case fuzzy --points 1000000 --threads 1 --compare``,
   and the seven layer surfaces of ``t2spline.benchmark_surface()`` on a
   1000 × 1000 grid against ``--case surface-fuzzy``. Python allocates its
   output on every run (numpy arrays that own the engine's buffers, large
   ones in huge-page mappings); the Rust side times fresh arrays and arrays
   it reuses. Each reports the median of five runs after one warm-up run;
   the Python side runs in a child process with ``RAYON_NUM_THREADS=1`` (the
   engine's thread pool then has one thread, as ``--threads 1`` gives the
   Rust side).
2. A whole job at 10⁶ samples: ``t2spline.run(job, samples=1_000_000)``
   against ``t2spline run job --samples 1000000 -o FILE`` (the JSON result
   written to a file), wall time of the whole command.

The machine is shared and noisy, so the two sides alternate round by round
and every figure is a ratio within one round; the median ratio is reported.

    python python/bench/bench_sampling.py [--bin target/release/t2spline] [--rounds 5]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
POINTS = 1_000_000
RUNS = 5


def rust_sampling(binary: Path, case: str) -> tuple[float, float]:
    """Median seconds of `t2spline bench --case CASE --compare`: fresh, reused."""
    out = subprocess.run(
        [str(binary), "bench", "--case", case, "--points", str(POINTS), "--threads", "1", "--compare"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    lines = [line for line in out.splitlines() if line.startswith("bench ")]
    seconds = [float(dict(f.split("=", 1) for f in line.split() if "=" in f)["seconds"]) for line in lines]
    return seconds[0], seconds[1]


def python_sampling(surface: bool) -> float:
    """Median seconds of `FuzzyCurve.sample` (or `FuzzySurface.sample` on a
    1000 × 1000 grid) in a child process on one thread."""
    side = round(POINTS**0.5)
    model, call = (
        ("benchmark_surface", f"sample({side}, {side})") if surface else ("benchmark_curve", f"sample({POINTS})")
    )
    code = (
        "import json, statistics, time, t2spline\n"
        f"c = t2spline.{model}()\n"
        f"c.{call}\n"
        "times = []\n"
        f"for _ in range({RUNS}):\n"
        "    start = time.perf_counter()\n"
        f"    s = c.{call}\n"
        "    del s\n"
        "    times.append(time.perf_counter() - start)\n"
        "print(json.dumps(statistics.median(times)))\n"
    )
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    out = subprocess.run(
        [sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env
    ).stdout
    return float(json.loads(out))


def rust_run(binary: Path, job: Path, folder: Path) -> float:
    """Seconds of `t2spline run` writing its JSON result to a file."""
    target = folder / "result.json"
    start = time.perf_counter()
    subprocess.run(
        [str(binary), "run", str(job), "--samples", str(POINTS), "-o", str(target)],
        check=True,
    )
    seconds = time.perf_counter() - start
    target.unlink()
    return seconds


def python_run(job: Path) -> float:
    """Seconds of `t2spline.run` returning the same result as numpy arrays."""
    import t2spline

    start = time.perf_counter()
    result = t2spline.run(job, samples=POINTS)
    seconds = time.perf_counter() - start
    del result
    return seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", type=Path, default=ROOT / "target/release/t2spline")
    parser.add_argument("--job", type=Path, default=ROOT / "examples/paper-alg-1-1.json")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    if not args.bin.exists():
        sys.exit(f"{args.bin}: not found; build it with `cargo build --release --bin t2spline`")

    ratios: dict[str, list[float]] = {"fuzzy": [], "surface-fuzzy": []}
    against_reused: dict[str, list[float]] = {"fuzzy": [], "surface-fuzzy": []}
    for k in range(args.rounds):
        for case in ratios:
            (fresh, reused), python = rust_sampling(args.bin, case), python_sampling(case == "surface-fuzzy")
            ratios[case].append(python / fresh)
            against_reused[case].append(python / reused)
            print(
                f"{case} round {k + 1}: rust fresh {fresh * 1e3:.1f} ms, rust reused {reused * 1e3:.1f} ms, "
                f"python {python * 1e3:.1f} ms, python / rust fresh {python / fresh:.3f}, "
                f"python / rust reused {python / reused:.3f}"
            )

    runs = []
    with tempfile.TemporaryDirectory() as folder:
        python_run(args.job)  # warm-up: imports, first use of the memory
        for k in range(args.rounds):
            rust, python = rust_run(args.bin, args.job, Path(folder)), python_run(args.job)
            runs.append(python / rust)
            print(
                f"run round {k + 1}: t2spline run -o FILE {rust:.3f} s, t2spline.run {python:.3f} s, "
                f"ratio {python / rust:.3f}"
            )

    for case, what in [("fuzzy", "10^6 parameters, 7 layers"), ("surface-fuzzy", "1000 x 1000 grid, 7 layers")]:
        print(
            f"sampling {what}, 1 thread: python / rust fresh = {statistics.median(ratios[case]):.3f} "
            f"(goal <= 1.2), python / rust reused = {statistics.median(against_reused[case]):.3f} "
            f"(median of {args.rounds} rounds)"
        )
    print(
        f"run at 10^6 samples: t2spline.run / `t2spline run -o FILE` = "
        f"{statistics.median(runs):.3f} (median of {args.rounds} rounds; goal < 1)"
    )


if __name__ == "__main__":
    main()
