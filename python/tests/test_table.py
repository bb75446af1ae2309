"""`run_table`: an Arrow table of job texts (pyarrow, or anything with the
PyCapsule interface) to a pyarrow table of one summary row per job, equal to
`run`'s numbers, and the samples of every job as one long table of one
schema, equal to the `t2spline run --parquet` file read by pyarrow."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any, Dict, List, Optional

import numpy as np
import pytest

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

import t2spline  # noqa: E402
from conftest import EXAMPLE, ROOT, bits, cli_errors, random_job  # noqa: E402

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"


def valid_jobs(seed: int, n: int) -> List[Dict[str, Any]]:
    rng = np.random.default_rng(seed)
    out: List[Dict[str, Any]] = []
    while len(out) < n:
        job = random_job(rng)
        try:
            t2spline.run(job)
        except t2spline.JobError:
            continue  # a random repeated knot beyond the order
        out.append(job)
    return out


def least_height(job: Dict[str, Any]) -> float:
    """The smallest lower height of a job's numbers, from its dict."""
    heights = [
        x.get("lower_height", job.get("lower_height"))
        for p in job["points"]
        for x in (p.values() if isinstance(p, dict) else [])
    ]
    return float(min(h for h in heights if h is not None))


@pytest.fixture(scope="module")
def jobs() -> List[Dict[str, Any]]:
    return valid_jobs(31, 30) + [json.loads(EXAMPLE.read_text())]


def same(a: Optional[float], b: Optional[float]) -> bool:
    return a == b or (a is None and b is None)


def test_one_summary_row_per_job_with_run_s_numbers(
    cli: Path, tmp_path: Path, jobs: List[Dict[str, Any]]
) -> None:
    texts: List[Optional[str]] = [json.dumps(j) for j in jobs]
    bad = '{"order": 2, "alhpa": 0.5, "points": []}'
    texts.insert(3, bad)
    texts.insert(5, None)
    table = pa.table({"job": pa.array(texts, pa.string())})
    summary = t2spline.run_table(table)
    assert summary.column_names == ["job", *t2spline.table.SUMMARY_COLUMNS]
    assert summary.schema.field("error_max").type == pa.float64()
    rows = summary.to_pylist()
    assert [r["job"] for r in rows] == list(range(len(texts)))
    for k, (row, text) in enumerate(zip(rows, texts)):
        if text is None or "alhpa" in text:
            assert row["status"] == "invalid" and row["error_max"] is None, row
            continue
        job = json.loads(text)
        want = t2spline.run(job)
        assert row["status"] == "ok" and row["message"] is None
        assert row["regime"] == want["regime"]
        assert row["type_reduction"] == want["type_reduction"]
        assert same(row["alpha"], want["alpha"] if want["alpha_used"] else None)
        assert row["error_max"] == want["error"]["max"]
        assert row["error_max_at"] == want["error"]["max_at"]
        assert row["error_max_at_v"] is None
        assert row["error_rms"] == want["error"]["rms"]
        assert row["h"] == least_height(job)
    # The message is the command-line tool's lines for the same text, the
    # job named by its row.
    path = tmp_path / "bad.json"
    path.write_text(bad)
    lines = cli_errors(cli, path)
    assert len(lines) == 2
    assert rows[3]["message"] == "; ".join(line.replace(str(path), "<row 3>") for line in lines)
    assert rows[3]["message"].startswith("<row 3>:1:14: alhpa: unknown key")
    assert rows[5]["message"] == "<row 5>: no job (null)"


def test_a_surface_s_largest_distance_is_at_u_and_v() -> None:
    table = pa.table({"job": [TERRAIN.read_text()]})
    [row] = t2spline.run_table(table, alpha=0.3).to_pylist()
    want = t2spline.run(TERRAIN, alpha=0.3)
    assert (row["error_max_at"], row["error_max_at_v"]) == tuple(want["error"]["max_at"])
    assert row["error_max"] == want["error"]["max"]


def test_an_id_column_is_carried_through_and_keywords_apply(jobs: List[Dict[str, Any]]) -> None:
    ids = [f"line-{k}" for k in range(len(jobs))]
    table = pa.table({"id": ids, "other": list(range(len(jobs))), "text": [json.dumps(j) for j in jobs]})
    summary, samples = t2spline.run_table(table, column="text", samples=True, sample_count=7, alpha=0.5)
    assert summary.column("job").to_pylist() == ids
    assert samples.num_rows == 7 * len(jobs)
    assert samples.column("job").to_pylist() == [i for i in ids for _ in range(7)]
    for row, job in zip(summary.to_pylist(), jobs):
        want = t2spline.run(job, samples=7, alpha=0.5)
        assert (row["error_max"], row["alpha"]) == (want["error"]["max"], 0.5)
    without = t2spline.run_table(table, column="text", id=None)
    assert without.column("job").to_pylist() == list(range(len(jobs)))


def test_the_samples_are_the_parquet_file_s(cli: Path, tmp_path: Path, jobs: List[Dict[str, Any]]) -> None:
    """Each job's rows of the long table hold the columns of `t2spline run
    --parquet` bit for bit; the columns it lacks are null."""
    chosen = jobs[:6] + [json.loads(TERRAIN.read_text())]
    texts = [json.dumps(j) for j in chosen]
    summary, samples = t2spline.run_table(pa.table({"job": texts}), samples=True)
    names = samples.column_names
    assert names[:4] == ["job", "t", "u", "v"] and names[-1] == "distance"
    assert all(samples.schema.field(n).type == pa.float64() for n in names[1:])
    job_of = samples.column("job").to_numpy()
    for k, text in enumerate(texts):
        path = tmp_path / f"j{k}.json"
        path.write_text(text)
        out = tmp_path / f"j{k}.parquet"
        subprocess.run([str(cli), "run", str(path), "--parquet", str(out), "-o", str(tmp_path / f"j{k}.out.json")], check=True)
        theirs = pq.read_table(out)
        mine = samples.filter(pa.array(job_of == k))
        assert mine.num_rows == theirs.num_rows
        for name in names[1:]:
            column = mine.column(name)
            if name in theirs.column_names:
                assert column.null_count == 0, name
                assert np.array_equal(bits(column.to_numpy()), bits(theirs.column(name).to_numpy())), name
            else:
                assert column.null_count == mine.num_rows, name


def test_the_table_may_come_by_the_capsule_interface_in_chunks(jobs: List[Dict[str, Any]]) -> None:
    texts = [json.dumps(j) for j in jobs]
    whole = t2spline.run_table(pa.table({"job": texts}))
    # Two chunks, the second a slice with an offset into its buffers.
    second = pa.table({"job": ["padding", *texts[10:]]}).slice(1)
    chunked = pa.concat_tables([pa.table({"job": texts[:10]}), second])
    assert chunked.column("job").num_chunks == 2
    got = t2spline.run_table(chunked)
    assert got.drop_columns("job").equals(whole.drop_columns("job"))
    _, long_whole = t2spline.run_table(pa.table({"job": texts}), samples=True)
    _, long_chunked = t2spline.run_table(chunked, samples=True)
    assert long_chunked.equals(long_whole)
    for kind in (pa.large_string(), pa.string_view()):
        typed = pa.table({"job": pa.array(texts, kind)})
        assert t2spline.run_table(typed).equals(whole)
    reader = pa.RecordBatchReader.from_batches(chunked.schema, chunked.to_batches())
    assert t2spline.run_table(reader).drop_columns("job").equals(whole.drop_columns("job"))
    pandas = pytest.importorskip("pandas")
    frame = pandas.DataFrame({"job": texts})
    assert hasattr(frame, "__arrow_c_stream__")
    assert t2spline.run_table(frame).equals(whole)
    assert t2spline.run_table(pa.table({"job": pa.array([], pa.string())})).num_rows == 0


def test_a_table_without_job_texts_is_refused() -> None:
    with pytest.raises(ValueError, match="the table has no column 'job'"):
        t2spline.run_table(pa.table({"text": ["{}"]}))
    with pytest.raises(TypeError, match="'job' holds int64, not job texts"):
        t2spline.run_table(pa.table({"job": [1, 2]}))
    with pytest.raises(TypeError, match="expected a pyarrow Table"):
        t2spline.run_table([json.dumps({})])
    [row] = t2spline.run_table(pa.table({"job": [EXAMPLE.read_text()]}), sample_count=1).to_pylist()
    assert (row["status"], row["message"]) == (
        "invalid", "samples: samples = 1: at least 2 are needed (both ends of the domain)"
    )
    with pytest.raises(TypeError, match="samples"):
        t2spline.run_table(pa.table({"job": ["{}"]}), sample_count="many")  # type: ignore[arg-type]


def misaligned(texts: List[str]) -> Any:
    """A ``large_string`` array whose 8-byte offsets start at an odd address,
    as pickle protocol 5 and Arrow IPC may hand them over (Arrow allows it)."""
    data = "".join(texts).encode()
    ends = np.cumsum([0] + [len(t.encode()) for t in texts]).astype(np.int64)
    padded = pa.py_buffer(b"\0" + ends.tobytes())
    offsets = padded.slice(1)
    assert offsets.address % 8 != 0
    return pa.Array.from_buffers(pa.large_string(), len(texts), [None, offsets, pa.py_buffer(data)])


def test_every_valid_arrow_layout_of_the_texts_is_read(jobs: List[Dict[str, Any]]) -> None:
    texts = [json.dumps(j) for j in jobs]
    whole = t2spline.run_table(pa.table({"job": texts}))
    layouts = {
        "misaligned large_string": pa.table({"job": misaligned(texts)}),
        "misaligned, sliced": pa.table({"job": misaligned(["pad", *texts, "pad"]).slice(1, len(texts))}),
        "large_string": pa.table({"job": pa.array(texts, pa.large_string())}),
        "string_view": pa.table({"job": pa.array(texts, pa.string_view())}),
        "sliced": pa.table({"job": ["pad", "pad", *texts]}).slice(2),
        "chunked in three": pa.table(
            {"job": pa.chunked_array([texts[:5], texts[5:6], texts[6:]], pa.large_string())}
        ),
    }
    for name, table in layouts.items():
        assert table.num_rows == len(texts), name
        got = t2spline.run_table(table)
        assert got.drop_columns("job").equals(whole.drop_columns("job")), name


def test_arguments_of_the_wrong_kind_are_named() -> None:
    table = pa.table({"job": [EXAMPLE.read_text()]})
    with pytest.raises(TypeError, match=r"^samples: expected True or False .* sample_count="):
        t2spline.run_table(table, samples=5)  # type: ignore[call-overload]
    with pytest.raises(TypeError, match=r"^column: expected the name of a column"):
        t2spline.run_table(table, column=3)  # type: ignore[call-overload]
    with pytest.raises(TypeError, match=r"^id: expected the name of a column"):
        t2spline.run_table(table, id=["x"])  # type: ignore[call-overload]
    for one, kind in [(str(EXAMPLE), "a str"), (EXAMPLE, "a path"), (EXAMPLE.read_bytes(), "bytes"),
                      (json.loads(EXAMPLE.read_text()), "a dict")]:
        with pytest.raises(TypeError, match=rf"^jobs: expected an iterable of jobs .* got {kind}; for one job use t2spline.run"):
            t2spline.run_many(one)  # type: ignore[arg-type]
