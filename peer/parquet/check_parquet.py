"""Peer check of `t2spline run --parquet`: the Parquet files read by pyarrow,
polars and DuckDB, compared with the JSON result of the same run to the last
bit (see README.md beside this file).

usage: check_parquet.py --bin target/release/t2spline [--cases N] [--seed S]
"""

import argparse
import json
import math
import random
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

import duckdb
import polars as pl
import pyarrow as pa
import pyarrow.parquet as pq

LAYERS = ["upper_left", "primary_left", "lower_left", "crisp",
          "lower_right", "primary_right", "upper_right"]
AXES = "xyz"


def bits(x):
    """The bits of a float, so that -0.0 and 0.0 differ and NaN equals NaN."""
    return struct.pack("<d", x)


def same(a, b):
    """Deep equality of JSON values, floats to the last bit."""
    if isinstance(a, float) or isinstance(b, float):
        return isinstance(a, (int, float)) and isinstance(b, (int, float)) \
            and bits(float(a)) == bits(float(b))
    if isinstance(a, list):
        return isinstance(b, list) and len(a) == len(b) and all(map(same, a, b))
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return a == b


def number(r, scale):
    c = r.uniform(-1, 1) * scale
    left = sorted(r.uniform(0, 1) * scale for _ in range(3))
    right = sorted(r.uniform(0, 1) * scale for _ in range(3))
    n = {"crisp": c, "upper": [c - left[2], c + right[2]],
         "primary": [c - left[1], c + right[1]], "lower": [c - left[0], c + right[0]]}
    if r.random() < 0.3:
        n["lower_height"] = r.choice([0.3, 0.6, 1.0])
    return n


def job(r, case):
    """A random curve job: 2-D or 3-D, order 1-5, coordinates from 1e-8 to 1e17."""
    scale = 10.0 ** r.choice([-8, -6, -3, 0, 0, 2, 15, 17])
    dims = r.choice([2, 3])
    n = r.randint(2, 9)
    return {
        "description": f"peer case {case}",
        "order": r.randint(1, min(n, 5)),
        "lower_height": r.choice([0.4, 0.6, 0.9]),
        "alpha": r.choice([0.0, 0.2, 0.6, 0.8, 1.0, round(r.random(), 3)]),
        "weights": [round(r.uniform(0.3, 3), 3) for _ in range(n)],
        "samples": r.randint(2, 300),
        "points": [{a: number(r, scale) for a in AXES[:dims]} for _ in range(n)],
    }


def expected_columns(result):
    """The table the JSON result says the Parquet file holds: name -> values."""
    c = result["curves"]
    cols = {"t": c["params"]}

    def add(prefix, points):
        for a in range(len(points[0])):
            cols[f"{prefix}_{AXES[a]}"] = [p[a] for p in points]

    for layer in LAYERS:
        add(layer, c["crisp"] if layer == "crisp" else c["layers"][layer])
    for layer in LAYERS:
        if layer != "crisp" and c["alpha_cut"][layer] is not None:
            add(f"alpha_cut_{layer}", c["alpha_cut"][layer])
    add("left", c["type_reduced"]["left"])
    add("right", c["type_reduced"]["right"])
    add("defuzzified", c["defuzzified"])
    cols["distance"] = None  # computed: checked apart
    for curve in ("crisp", "defuzzified"):
        for k, points in enumerate(c.get("derivatives", {}).get(curve, [])):
            add(f"{curve}_d{k + 1}", points)
    return cols


def check_distance(table, result, where):
    c = result["curves"]
    for i, d in enumerate(table.column("distance").to_pylist()):
        a, b = c["crisp"][i], c["defuzzified"][i]
        want = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
        if abs(d - want) > 4e-16 * max(want, 1e-300) and not (math.isinf(want) or want < 1e-150):
            raise AssertionError(f"{where}: distance[{i}] = {d!r}, expected {want!r}")


def check_table(path, result, where):
    """pyarrow: names, types, values to the last bit, metadata; polars: the same values."""
    table = pq.read_table(path)
    want = expected_columns(result)
    if table.column_names != list(want):
        raise AssertionError(f"{where}: columns {table.column_names} != {list(want)}")
    for name, values in want.items():
        field = table.schema.field(name)
        if field.type != pa.float64() or field.nullable and table.column(name).null_count:
            raise AssertionError(f"{where}: {name} is {field.type}, nulls {table.column(name).null_count}")
        if values is not None:
            got = table.column(name).to_pylist()
            bad = [i for i, (g, w) in enumerate(zip(got, values)) if bits(g) != bits(float(w))]
            if len(got) != len(values) or bad:
                i = bad[0] if bad else None
                raise AssertionError(f"{where}: {name}[{i}] {got[i]!r} != {values[i]!r}")
    check_distance(table, result, where)
    meta = {k.decode(): json.loads(v) for k, v in table.schema.metadata.items()}
    keys = [k for k in result if k not in ("curves", "surfaces")]
    if sorted(meta) != sorted(keys):
        raise AssertionError(f"{where}: metadata keys {sorted(meta)} != {sorted(keys)}")
    for k in keys:
        if not same(meta[k], result[k]):
            raise AssertionError(f"{where}: metadata {k} differs from the JSON")
    frame = pl.read_parquet(path)
    if frame.columns != table.column_names or frame.height != table.num_rows:
        raise AssertionError(f"{where}: polars reads another shape")
    for name in frame.columns:
        p = [bits(x) for x in frame[name].to_list()]
        a = [bits(x) for x in table.column(name).to_pylist()]
        if p != a:
            raise AssertionError(f"{where}: polars reads other values in {name}")
    return table.num_rows


def run(binary, *args):
    out = subprocess.run([binary, *args], capture_output=True, text=True)
    return out.returncode, out.stdout, out.stderr


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--cases", type=int, default=200)
    ap.add_argument("--seed", type=int, default=2027)
    args = ap.parse_args()
    r = random.Random(args.seed)
    print(f"pyarrow {pa.__version__}, polars {pl.__version__}, duckdb {duckdb.__version__}")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        jobs = tmp / "jobs"
        jobs.mkdir()
        rows = values = 0
        for case in range(args.cases):
            spec = job(r, case)
            path = jobs / f"case{case:04d}.json"
            path.write_text(json.dumps(spec))
            extra = ["--derivatives", str(r.randint(1, 3))] if r.random() < 0.3 else []
            code, out, err = run(args.bin, "run", str(path), "-o", str(tmp / "r.json"),
                                 "--parquet", str(tmp / "r.parquet"), *extra)
            if code != 0:
                raise AssertionError(f"case {case}: exit {code}: {err}")
            result = json.loads((tmp / "r.json").read_text())
            n = check_table(tmp / "r.parquet", result, f"case {case}")
            rows += n
            values += n * len(expected_columns(result))
        print(f"{args.cases} results: {rows} rows, {values} values equal to the JSON "
              "to the last bit in pyarrow and polars")

        # Many jobs in one run, one of them bad: the summary in DuckDB.
        (jobs / "broken.json").write_text('{"order": 2, "alhpa": 1}')
        out_dir = tmp / "out"
        code, _, err = run(args.bin, "run", "--jobs", str(jobs), "-o", str(out_dir),
                           "--parquet", str(out_dir))
        if code != 2 or "broken.json:1:14: alhpa" not in err:
            raise AssertionError(f"run of many: exit {code}: {err}")
        summary = out_dir / "summary.parquet"
        got = duckdb.sql(f"select name, status, error_max, error_rms from '{summary}' "
                         "order by name").fetchall()
        if len(got) != args.cases + 1 or got[0][:2] != ("broken", "invalid") or got[0][2] is not None:
            raise AssertionError(f"summary: {got[:3]}")
        for name, status, emax, erms in got[1:]:
            result = json.loads((out_dir / f"{name}.json").read_text())
            if status != "ok" or bits(emax) != bits(result["error"]["max"]) \
                    or bits(erms) != bits(result["error"]["rms"]):
                raise AssertionError(f"summary row {name}: {status} {emax} {erms}")
        one = out_dir / "case0000.parquet"
        (count, biggest), = duckdb.sql(f"select count(*), max(distance) from '{one}'").fetchall()
        if count != pq.read_table(one).num_rows or biggest != max(pq.read_table(one).column("distance").to_pylist()):
            raise AssertionError("DuckDB reads another table")
        csv = pl.read_csv(out_dir / "summary.csv")
        if csv["name"].to_list() != [g[0] for g in got]:
            raise AssertionError("summary.csv and summary.parquet list other jobs")
        print(f"run of {args.cases + 1} jobs: summary.parquet in DuckDB and summary.csv in "
              "polars agree with every result file")
    print("parquet peer check passed")


if __name__ == "__main__":
    try:
        main()
    except AssertionError as e:
        print(f"FAILED: {e}", file=sys.stderr)
        sys.exit(1)
