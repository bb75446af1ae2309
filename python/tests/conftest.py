"""Shared fixtures: the command-line tool built from this checkout (the
reference the bindings must equal bit for bit), random valid jobs, and a
comparison of a result dict with the CLI's JSON."""

from __future__ import annotations

import json
import math
import os
import subprocess
from pathlib import Path
from typing import Any, Dict, List, Optional

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "paper-alg-1-1.json"


@pytest.fixture(scope="session")
def cli() -> Path:
    """`t2spline`, built from this checkout (cargo does nothing when it is
    up to date); `T2SPLINE_BIN` names another build."""
    given = os.environ.get("T2SPLINE_BIN")
    if given:
        return Path(given)
    subprocess.run(
        ["cargo", "build", "--release", "--quiet", "--bin", "t2spline"], cwd=ROOT, check=True
    )
    return ROOT / "target" / "release" / "t2spline"


def cli_run(cli: Path, job: Path, *args: str) -> Dict[str, Any]:
    """The JSON result of `t2spline run JOB ARGS`."""
    out = subprocess.run(
        [str(cli), "run", str(job), *args], check=True, capture_output=True, text=True
    ).stdout
    result: Dict[str, Any] = json.loads(out)
    return result


def cli_errors(cli: Path, job: Path, *args: str) -> List[str]:
    """The error lines of `t2spline run JOB ARGS`, without the `t2spline: `
    prefix; the run must fail with exit code 2 (invalid input)."""
    done = subprocess.run(
        [str(cli), "run", str(job), *args], capture_output=True, text=True
    )
    assert done.returncode == 2, (done.returncode, done.stderr)
    return [line.removeprefix("t2spline: ") for line in done.stderr.splitlines()]


def bits(a: np.ndarray) -> np.ndarray:
    """The bit patterns of a float64 array (NaN canonical), for exact
    comparison."""
    a = np.where(np.isnan(a), np.nan, a)
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def assert_same(got: Any, want: Any, path: str = "result") -> None:
    """`got` (from `t2spline.run`) is `want` (the CLI's JSON) with every list
    of numbers an equal float64 array: same keys in the same order, the same
    numbers bit for bit, NaN where the JSON has null inside a point."""
    if isinstance(want, dict):
        assert isinstance(got, dict), path
        assert list(got) == list(want), f"{path}: keys {list(got)} != {list(want)}"
        for key in want:
            assert_same(got[key], want[key], f"{path}.{key}")
    elif isinstance(got, np.ndarray):
        assert got.dtype == np.float64, f"{path}: dtype {got.dtype}"
        expected = np.array(
            json.loads(json.dumps(want).replace("null", "NaN")), dtype=np.float64
        )
        assert got.shape == expected.shape, f"{path}: shape {got.shape} != {expected.shape}"
        assert np.array_equal(bits(got), bits(expected)), f"{path}: values differ"
    elif isinstance(want, list):
        assert isinstance(got, list) and len(got) == len(want), path
        for k, (g, w) in enumerate(zip(got, want)):
            assert_same(g, w, f"{path}[{k}]")
    elif isinstance(want, float):
        assert isinstance(got, float), f"{path}: {type(got)}"
        assert got == want or (math.isnan(got) and math.isnan(want)), f"{path}: {got} != {want}"
    else:
        assert type(got) is type(want) and got == want, f"{path}: {got!r} != {want!r}"


def random_job(rng: np.random.Generator) -> Dict[str, Any]:
    """A random valid job: 2-D or 3-D, order 1–5, clamped or random knots,
    weights or none, heights per number or at the top level, alpha anywhere in
    [0, 1] (at times exactly a height, 0 or 1), unequal spreads, some zero."""
    dim = int(rng.integers(2, 4))
    order = int(rng.integers(1, 6))
    n = order + int(rng.integers(0, 7))
    heights = [float(h) for h in rng.choice([0.3, 0.5, 0.75, 1.0], size=2)]
    per_number = bool(rng.integers(0, 2))

    def side() -> List[float]:
        # Distances from the crisp value of lower, primary and upper ends.
        steps = rng.exponential(0.5, size=3) * rng.integers(0, 2, size=3)
        return [float(v) for v in np.cumsum(steps)]

    def number() -> Dict[str, Any]:
        c = float(rng.uniform(-10, 10))
        left, right = side(), side()
        x: Dict[str, Any] = {
            "crisp": c,
            "upper": [c - left[2], c + right[2]],
            "primary": [c - left[1], c + right[1]],
            "lower": [c - left[0], c + right[0]],
        }
        if per_number:
            x["lower_height"] = float(rng.choice(heights))
        return x

    axes = "xyz"[:dim]
    job: Dict[str, Any] = {"points": [{a: number() for a in axes} for _ in range(n)]}
    if rng.integers(0, 2):
        job["order"] = order
    else:
        job["degree"] = order - 1
    if not per_number:
        job["lower_height"] = heights[0]
    if rng.integers(0, 2):
        job["weights"] = [float(w) for w in rng.uniform(0.2, 5.0, size=n)]
    if rng.integers(0, 2) and n > order:
        interior = np.sort(rng.uniform(0.0, 1.0, size=n - order))
        if n - order >= 2 and rng.integers(0, 2):
            interior[1] = interior[0]  # a repeated knot
        job["knots"] = [0.0] * order + [float(u) for u in interior] + [1.0] * order
    choice = int(rng.integers(0, 4))
    alpha: Optional[float] = [float(rng.uniform()), heights[0], 0.0, 1.0][choice]
    job["alpha"] = alpha
    job["samples"] = int(rng.integers(2, 300))
    if rng.integers(0, 2):
        job["description"] = f"random job of order {order}"
    return job
