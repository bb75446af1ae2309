"""Throughput of many jobs from Python: `run_many`, `run_table`, and the Dask
recipe of docs/scale.md on a `LocalCluster` of 1 and of 2 worker processes,
against a baseline measured in the same run (`run` called once per job in a
Python loop).

The jobs are the paper's example at alphas 0, 0.01, …, 1 repeated (101
samples each), written as a Parquet dataset of 8 partitions with columns
`id` and `job`. The Dask figures are wall times of `run_dataset` (read,
map, write) with the cluster already started; each figure is the median of
`--rounds` rounds, and the ratios are to the loop of `run` of the same
round. The machine is shared, so the ratios are the figures to read.

    python python/bench/bench_scale.py [--jobs 20000] [--rounds 3]
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any, Callable, Dict, List

import pyarrow as pa  # type: ignore[import-untyped]
import pyarrow.parquet as pq  # type: ignore[import-untyped]

import t2spline

ROOT = Path(__file__).resolve().parents[2]
PARTITIONS = 8


def recipe() -> Dict[str, Any]:
    """The recipe block of docs/scale.md, executed."""
    text = (ROOT / "docs" / "scale.md").read_text()
    block = re.search(r"<!-- recipe: run by python/tests/test_dask.py -->\n```python\n(.*?)```", text, re.S)
    assert block
    names: Dict[str, Any] = {"__name__": "recipe"}
    exec(compile(block.group(1), "docs/scale.md", "exec"), names)
    return names


def timed(work: Callable[[], object]) -> float:
    start = time.perf_counter()
    work()
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=20_000)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    from distributed import Client, LocalCluster

    base = json.loads((ROOT / "examples" / "paper-alg-1-1.json").read_text())
    texts = [json.dumps(dict(base, alpha=(k % 101) / 100)) for k in range(args.jobs)]
    dicts = [json.loads(t) for t in texts]
    table = pa.table({"id": pa.array(range(args.jobs), pa.int64()), "job": texts})
    run_dataset = recipe()["run_dataset"]
    figures: Dict[str, List[float]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        jobs = Path(tmp) / "jobs"
        jobs.mkdir()
        per = -(-args.jobs // PARTITIONS)
        for p in range(PARTITIONS):
            pq.write_table(table.slice(p * per, per), jobs / f"part.{p}.parquet")
        clusters = {
            n: LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None)
            for n in (1, 2)
        }
        try:
            for r in range(args.rounds):
                loop = timed(lambda: [t2spline.run(d) for d in dicts])
                cases: Dict[str, Callable[[], object]] = {
                    "run_many": lambda: t2spline.run_many(texts),
                    "run_table": lambda: t2spline.run_table(table),
                }
                for n, cluster in clusters.items():
                    def dask(n: int = n, cluster: Any = cluster) -> None:
                        with Client(cluster):
                            run_dataset(str(jobs), str(Path(tmp) / f"out-{n}-{r}"))
                    cases[f"dask, {n} worker{'s' if n > 1 else ''}"] = dask
                figures.setdefault("run, a loop", []).append(loop)
                for name, work in cases.items():
                    figures.setdefault(name, []).append(timed(work))
                figures.setdefault("_loop", []).append(loop)
        finally:
            for cluster in clusters.values():
                cluster.close()
    loops = figures.pop("_loop")
    print(f"{args.jobs} jobs (paper example, 101 samples), median of {args.rounds} rounds")
    print(f"{'case':<22} {'seconds':>8} {'jobs/s':>9} {'vs loop':>8}")
    for name, seconds in figures.items():
        ratio = statistics.median(l / s for l, s in zip(loops, seconds))
        s = statistics.median(seconds)
        print(f"{name:<22} {s:8.3f} {args.jobs / s:9.0f} {ratio:8.2f}")


if __name__ == "__main__":
    main()
