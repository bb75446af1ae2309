"""Checks `t2spline fuzzify` against numpy's percentiles, live.

Random readings files (2-D and 3-D, 1-30 stations of 2-40 readings, values
of any magnitude, ties, written as spreadsheets write them: comma or
semicolon with decimal commas, CRLF, a byte-order mark, quoted fields) go
through `t2spline fuzzify --tolerance T --lower-height H`; every number of
the data file must equal numpy's `percentile(v, [10, 25, 50, 75, 90])` (its
default, linear: Hyndman and Fan's type 7) and `min(v) - T`, `max(v) + T`
bit for bit.

    python peer/cad/check_fuzzify.py --bin target/release/t2spline --cases 300
"""

import argparse
import json
import random
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np


def readings(rng, dim):
    scale = 10.0 ** rng.randint(-6, 8)
    stations = []
    for s in range(rng.randint(1, 30)):
        n = rng.randint(2, 40)
        centre = [rng.uniform(-1, 1) * scale for _ in range(dim)]
        rows = []
        for _ in range(n):
            if rows and rng.random() < 0.2:
                rows.append(list(rows[-1]))  # a tie
            else:
                rows.append([c + rng.gauss(0, 0.05 * scale) for c in centre])
        stations.append((f"station {s}", rows))
    return stations


def write(path, stations, dim, rng):
    semicolon = rng.random() < 0.4
    sep, end = (";" if semicolon else ","), ("\r\n" if rng.random() < 0.5 else "\n")
    bom = "\ufeff" if rng.random() < 0.3 else ""
    head = sep.join(["station", "x", "y", "z"][: dim + 1])

    def number(v):
        text = repr(v)
        if semicolon and rng.random() < 0.5 and "e" not in text:
            text = text.replace(".", ",")
        return f'"{text}"' if rng.random() < 0.2 or "," in text else text

    lines = [bom + head]
    for name, rows in stations:
        for row in rows:
            station = f'"{name}"' if rng.random() < 0.5 else name
            lines.append(sep.join([station] + [number(v) for v in row]))
    Path(path).write_text(end.join(lines) + end, encoding="utf-8")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--cases", type=int, default=300)
    parser.add_argument("--seed", type=int, default=20261201)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    passed = failed = numbers = 0
    with tempfile.TemporaryDirectory() as folder:
        for case in range(args.cases):
            dim = 2 + case % 2
            stations = readings(rng, dim)
            tolerance = rng.choice([0.0, rng.uniform(0, 1)])
            height = rng.choice([0.5, rng.uniform(0.05, 1)])
            path = Path(folder) / f"r{case}.csv"
            write(path, stations, dim, rng)
            try:
                out = subprocess.run(
                    [args.bin, "fuzzify", str(path), "--tolerance", repr(tolerance),
                     "--lower-height", repr(height), "--degree", "1"],
                    capture_output=True, text=True)
                if len(stations) < 2:
                    # One station cannot make a curve of degree 1.
                    assert out.returncode == 2 and "--degree" in out.stderr, out
                    passed += 1
                    continue
                assert out.returncode == 0, out.stderr
                data = json.loads(out.stdout)
                assert data["lower_height"] == height
                for (name, rows), point in zip(stations, data["points"], strict=True):
                    for axis, key in enumerate("xyz"[:dim]):
                        v = np.array([r[axis] for r in rows])
                        q = np.percentile(v, [10, 25, 50, 75, 90])
                        n = point[key]
                        want = {"crisp": q[2], "lower": [q[1], q[3]], "primary": [q[0], q[4]],
                                "upper": [v.min() - tolerance, v.max() + tolerance]}
                        got = {k: n[k] for k in want}
                        assert json.dumps(got) == json.dumps(
                            {k: (float(w) if np.isscalar(w) else [float(x) for x in w])
                             for k, w in want.items()}), (case, name, key, got, want)
                        numbers += 1
                passed += 1
            except AssertionError as e:
                failed += 1
                print(f"FAIL case {case}: {e}", file=sys.stderr)
    print(f"fuzzify: {numbers} fuzzy numbers equal to numpy {np.__version__} bit for bit")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
