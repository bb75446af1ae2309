"""Checks `t2spline fuzzify` against numpy's percentiles, live.

Random readings files (2-D and 3-D, 1-30 stations of 2-40 readings, values
of any magnitude, ties, written as spreadsheets write them: comma or
semicolon with decimal commas, CRLF, a byte-order mark, quoted fields) go
through `t2spline fuzzify --tolerance T --lower-height H`; every number of
the data file must equal numpy's `percentile(v, [10, 25, 50, 75, 90])` (its
default, linear: Hyndman and Fan's type 7) and `min(v) - T`, `max(v) + T`
bit for bit.

Nets likewise: random readings of the stations of a net (`row,col,x,y,z`,
2-6 rows of 2-6 stations, the rows of the file shuffled as a log in time
order interleaves them), and random rasters (`.npy` arrays with NaN cells,
read in K x K blocks with `--block K`), each number of the data file's
rows of points against numpy's percentiles of the station's (or block's)
readings, and a block's x and y its centre.

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


def net_case(rng, folder, case, bin_):
    """A net's readings file, shuffled; every number against numpy."""
    rows, cols = rng.randint(2, 6), rng.randint(2, 6)
    scale = 10.0 ** rng.randint(-4, 6)
    stations = {}
    lines = []
    for i in range(rows):
        for j in range(cols):
            n = rng.randint(2, 12)
            centre = [j * scale, i * scale, rng.uniform(-1, 1) * scale]
            readings = []
            for _ in range(n):
                if readings and rng.random() < 0.2:
                    readings.append(list(readings[-1]))
                else:
                    readings.append([c + rng.gauss(0, 0.05 * scale) for c in centre])
            stations[(i, j)] = readings
            lines += [f"{i},{j}," + ",".join(repr(v) for v in r) for r in readings]
    rng.shuffle(lines)
    path = Path(folder) / f"n{case}.csv"
    path.write_text("row,col,x,y,z\n" + "\n".join(lines) + "\n", encoding="utf-8")
    tolerance = rng.choice([0.0, rng.uniform(0, 1)])
    out = subprocess.run(
        [bin_, "fuzzify", str(path), "--tolerance", repr(tolerance), "--degree", "1"],
        capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert data["degree"] == [1, 1]
    assert len(data["points"]) == rows
    numbers = 0
    for i, row in enumerate(data["points"]):
        assert len(row) == cols
        for j, point in enumerate(row):
            for axis, key in enumerate("xyz"):
                v = np.array([r[axis] for r in stations[(i, j)]])
                numbers += compare(point[key], v, tolerance, (case, i, j, key))
    return numbers


def raster_case(rng, folder, case, bin_):
    """A `.npy` raster with NaN cells in K x K blocks; z against numpy, x
    and y the block's centre."""
    k = rng.randint(2, 4)
    rows, cols = rng.randint(2, 5) * k + rng.randint(0, k - 1), rng.randint(2, 5) * k
    scale = 10.0 ** rng.randint(-3, 5)
    a = np.array([[rng.gauss(0, scale) for _ in range(cols)] for _ in range(rows)])
    for _ in range(rng.randint(0, rows * cols // (k * k))):
        a[rng.randrange(rows), rng.randrange(cols)] = np.nan
    x0, y0, dx, dy = rng.uniform(-1e3, 1e3), rng.uniform(-1e3, 1e3), rng.choice([0.5, 1.0, 2.0]), -1.0
    path = Path(folder) / f"g{case}.npy"
    np.save(path, a.astype("<f8") if rng.random() < 0.5 else a.astype("<f4"))
    a = np.load(path).astype(np.float64)
    out = subprocess.run(
        [bin_, "fuzzify", str(path), "--block", str(k), "--degree", "1",
         "--origin", f"{x0!r},{y0!r}", "--spacing", f"{dx!r},{dy!r}"],
        capture_output=True, text=True)
    blocks = [[a[i * k:(i + 1) * k, j * k:(j + 1) * k] for j in range(cols // k)]
              for i in range(rows // k)]
    if any(np.count_nonzero(~np.isnan(b)) < 2 for row in blocks for b in row):
        assert out.returncode == 2 and "percentiles need at least 2" in out.stderr, out
        return 0
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    numbers = 0
    for i, row in enumerate(blocks):
        for j, b in enumerate(row):
            point = data["points"][i][j]
            xs = [x0 + dx * c for c in (j * k, (j + 1) * k - 1)]
            ys = [y0 + dy * r for r in (i * k, (i + 1) * k - 1)]
            for key, ends in (("x", xs), ("y", ys)):
                c = ends[0] + (ends[1] - ends[0]) / 2.0
                assert point[key] == {"crisp": c, "upper": [c, c], "primary": [c, c],
                                      "lower": [c, c]}, (case, i, j, key, point[key], c)
            numbers += compare(point["z"], b[~np.isnan(b)].ravel(), 0.0, (case, i, j, "z"))
    return numbers


def compare(n, v, tolerance, where):
    """One fuzzy number of the data file against numpy's statistics of `v`."""
    q = np.percentile(v, [10, 25, 50, 75, 90])
    want = {"crisp": q[2], "lower": [q[1], q[3]], "primary": [q[0], q[4]],
            "upper": [v.min() - tolerance, v.max() + tolerance]}
    got = {k: n[k] for k in want}
    assert json.dumps(got) == json.dumps(
        {k: (float(w) if np.isscalar(w) else [float(x) for x in w])
         for k, w in want.items()}), (where, got, want)
    return 1


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
        for case in range(args.cases // 3):
            for kind in (net_case, raster_case):
                try:
                    numbers += kind(rng, folder, case, args.bin)
                    passed += 1
                except AssertionError as e:
                    failed += 1
                    print(f"FAIL {kind.__name__} {case}: {e}", file=sys.stderr)
    print(f"fuzzify: {numbers} fuzzy numbers equal to numpy {np.__version__} bit for bit")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
