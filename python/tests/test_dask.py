"""The Dask recipe of docs/scale.md, run as written: a Parquet dataset of
20 000 jobs in 8 partitions read by `dask.dataframe.read_parquet`, mapped
with `run_table` on a `distributed.LocalCluster` of 2 worker processes,
written as a Parquet dataset; every row is there once, and a sample of rows
equals `t2spline run`'s results for those jobs."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path
from typing import Any, Callable, Dict, List

import numpy as np
import pytest

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")
pytest.importorskip("dask.dataframe")
distributed = pytest.importorskip("distributed")

import t2spline  # noqa: E402
from conftest import EXAMPLE, ROOT, random_job  # noqa: E402

JOBS, PARTITIONS = 20_000, 8


def recipe_text() -> str:
    """The recipe's code block of docs/scale.md."""
    text = (ROOT / "docs" / "scale.md").read_text()
    block = re.search(
        r"<!-- recipe: run by python/tests/test_dask.py -->\n```python\n(.*?)```", text, re.S
    )
    assert block, "docs/scale.md has no recipe block"
    return block.group(1)


def recipe() -> Dict[str, Any]:
    """The recipe's code block of docs/scale.md, executed as a module (its
    guard keeps its main part from running): its functions."""
    names: Dict[str, Any] = {"__name__": "recipe"}
    exec(compile(recipe_text(), "docs/scale.md", "exec"), names)
    return names


def test_the_recipe_runs_as_a_script_on_two_worker_processes(tmp_path: Path) -> None:
    """Saved as a file and run as the page says: it writes its dataset,
    runs it on two worker processes and writes one summary per job, the
    numbers of run_table in this process."""
    script = tmp_path / "recipe.py"
    script.write_text(recipe_text())
    out = subprocess.run(
        [sys.executable, str(script), "jobs", "results"],
        cwd=tmp_path, capture_output=True, text=True, timeout=600,
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().endswith("4000 jobs run"), out.stdout
    results = pq.read_table(tmp_path / "results").sort_by("job")
    assert results.column("job").to_pylist() == list(range(4000))
    assert set(results.column("status").to_pylist()) == {"ok"}
    jobs = pq.read_table(tmp_path / "jobs").sort_by("id")
    expected = t2spline.run_table(jobs)
    assert results.column("error_max").to_pylist() == expected.column("error_max").to_pylist()


def base_jobs() -> List[Dict[str, Any]]:
    """Valid jobs of every kind the recipe meets: random curves in the plane
    and in space, the paper's example, a surface."""
    rng = np.random.default_rng(5)
    out: List[Dict[str, Any]] = [json.loads(EXAMPLE.read_text())]
    while len(out) < 12:
        job = random_job(rng)
        job["samples"] = 21
        try:
            t2spline.run(job)
        except t2spline.JobError:
            continue
        out.append(job)
    surface = json.loads((ROOT / "examples" / "fuzzy-terrain.json").read_text())
    surface["samples"] = [5, 5]
    out.append(surface)
    return out


def job_text(k: int, bases: List[Dict[str, Any]]) -> str:
    """Job `k`: a base job at its own alpha; every 997th is broken."""
    if k % 997 == 500:
        return '{"order": 2, "points": []}'
    job = dict(bases[k % len(bases)], alpha=(k % 101) / 100)
    return json.dumps(job)


def write_jobs(folder: Path) -> List[str]:
    bases = base_jobs()
    texts = [job_text(k, bases) for k in range(JOBS)]
    folder.mkdir()
    per = JOBS // PARTITIONS
    for p in range(PARTITIONS):
        ids = np.arange(p * per, (p + 1) * per, dtype=np.int64)
        part = pa.table({"id": ids, "job": pa.array(texts[p * per : (p + 1) * per], pa.string())})
        pq.write_table(part, folder / f"part.{p}.parquet")
    return texts


def test_the_dask_recipe_on_a_local_cluster_of_two_processes(cli: Path, tmp_path: Path) -> None:
    texts = write_jobs(tmp_path / "jobs")
    run_dataset: Callable[[str, str], None] = recipe()["run_dataset"]
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        run_dataset(str(tmp_path / "jobs"), str(tmp_path / "results"))
    parts = sorted((tmp_path / "results").glob("*.parquet"))
    assert len(parts) == PARTITIONS
    results = pq.read_table(tmp_path / "results").sort_by("job")
    assert results.column_names == ["job", *t2spline.table.SUMMARY_COLUMNS]
    assert results.column("job").to_pylist() == list(range(JOBS))
    status = results.column("status").to_pylist()
    broken = [k for k in range(JOBS) if k % 997 == 500]
    assert [k for k, s in enumerate(status) if s != "ok"] == broken
    assert all(results.column("message")[k].as_py().startswith("<row ") for k in broken)

    # A sample of rows against the command-line tool, run on those jobs.
    rng = np.random.default_rng(11)
    chosen = sorted(int(k) for k in rng.choice(JOBS, size=24, replace=False) if k % 997 != 500)
    folder = tmp_path / "sample"
    folder.mkdir()
    for k in chosen:
        (folder / f"job{k}.json").write_text(texts[k])
    out = tmp_path / "cli"
    subprocess.run([str(cli), "run", "--jobs", str(folder), "-o", str(out)], check=True, capture_output=True)
    rows = results.take(pa.array(chosen)).to_pylist()
    for k, row in zip(chosen, rows):
        want = json.loads((out / f"job{k}.json").read_text())
        assert row["job"] == k
        assert row["error_max"] == want["error"]["max"], k
        assert row["error_rms"] == want["error"]["rms"], k
        at = want["error"]["max_at"]
        if isinstance(at, list):
            assert [row["error_max_at"], row["error_max_at_v"]] == at, k
        else:
            assert (row["error_max_at"], row["error_max_at_v"]) == (at, None), k
        assert row["regime"] == want["regime"], k
        assert row["alpha"] == (want["alpha"] if want["alpha_used"] else None), k
        assert row["type_reduction"] == want["type_reduction"], k


def test_partitions_built_from_pandas_are_mapped_on_two_processes(tmp_path: Path) -> None:
    # `dd.from_pandas` ships each partition to a worker by pickle protocol 5,
    # whose buffers may leave Arrow's 8-byte offsets at odd addresses.
    pd = pytest.importorskip("pandas")
    dd = pytest.importorskip("dask.dataframe")
    bases = base_jobs()
    n = 2_000
    texts = [job_text(k, bases) for k in range(n)]
    frame = pd.DataFrame({"id": np.arange(n, dtype=np.int64), "job": pd.array(texts, dtype="string[pyarrow]")})
    run_partition: Callable[[Any], Any] = recipe()["run_partition"]
    jobs = dd.from_pandas(frame, npartitions=4)
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster):
        meta = run_partition(jobs._meta)
        results = jobs.map_partitions(run_partition, meta=meta).compute()
    results = results.sort_values("job")
    assert results["job"].tolist() == list(range(n))
    broken = [k for k in range(n) if k % 997 == 500]
    assert [int(k) for k, s in zip(results["job"], results["status"]) if s != "ok"] == broken
    expected = t2spline.run_table(pa.table({"id": np.arange(n), "job": texts})).to_pandas()
    np.testing.assert_array_equal(results["error_max"].to_numpy(), expected["error_max"].to_numpy())
