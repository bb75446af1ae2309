"""A run of many jobs as docs/output.md shows it: its transcript run as
printed, the summary's columns (with `h`, where the distance is largest and
the description) read back by pyarrow and equal to each job's result, and
the jobs of a folder in natural order (`a2` before `a10`)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import EXAMPLE, ROOT

pq = pytest.importorskip("pyarrow.parquet")


def lines_folder(tmp_path: Path) -> Path:
    """`lines/` of docs/output.md: the example as a.json, a broken b.json,
    the 3-D test job as c.json."""
    lines = tmp_path / "lines"
    lines.mkdir()
    shutil.copy(EXAMPLE, lines / "a.json")
    (lines / "b.json").write_text('{\n  "order": 2,\n  "alhpa": 0.5\n}\n')
    shutil.copy(ROOT / "fixtures" / "spiral-3d.json", lines / "c.json")
    return lines


def test_the_transcript_of_a_run_of_many_jobs(cli: Path, tmp_path: Path) -> None:
    text = (ROOT / "docs" / "output.md").read_text()
    block = re.search(r"```text\n(\$ t2spline run lines/\*\.json -o results\n.*?)```", text, re.S)
    assert block, "docs/output.md has no transcript of a run of many jobs"
    shown = block.group(1)
    lines_folder(tmp_path)
    done = subprocess.run(
        [str(cli), "run", "lines/a.json", "lines/b.json", "lines/c.json", "-o", "results"],
        cwd=tmp_path, capture_output=True, text=True,
    )
    summary = (tmp_path / "results" / "summary.csv").read_text()
    got = (
        "$ t2spline run lines/*.json -o results\n" + done.stderr
        + f"$ echo $?\n{done.returncode}\n$ cat results/summary.csv\n" + summary
    )
    assert got == shown


def test_the_summary_has_each_job_s_height_and_largest_distance(cli: Path, tmp_path: Path) -> None:
    lines_folder(tmp_path)
    surface = json.loads((ROOT / "examples" / "fuzzy-terrain.json").read_text())
    surface["alpha"] = 0.3
    (tmp_path / "lines" / "d.json").write_text(json.dumps(surface))
    subprocess.run(
        [str(cli), "run", "--jobs", "lines", "-o", "results", "--parquet", "parquet"],
        cwd=tmp_path, capture_output=True,
    )
    rows = pq.read_table(tmp_path / "parquet" / "summary.parquet").to_pylist()
    assert [r["name"] for r in rows] == ["a", "b", "c", "d"]
    for row in rows:
        if row["status"] != "ok":
            assert row["h"] is None and row["error_max_at"] is None and row["description"] is None
            continue
        result = json.loads((tmp_path / "results" / f"{row['name']}.json").read_text())
        job = json.loads((tmp_path / "lines" / f"{row['name']}.json").read_text())
        assert row["description"] == result.get("description")
        at = result["error"]["max_at"]
        want_at = (at[0], at[1]) if isinstance(at, list) else (at, None)
        assert (row["error_max_at"], row["error_max_at_v"]) == want_at
        heights = [
            x.get("lower_height", job.get("lower_height"))
            for p in (job["points"] if row["name"] != "d" else [q for r in job["points"] for q in r])
            for x in p.values()
        ]
        assert row["h"] == min(h for h in heights if h is not None)


def test_the_jobs_of_a_folder_go_in_natural_order(cli: Path, tmp_path: Path) -> None:
    folder = tmp_path / "sweep"
    folder.mkdir()
    names = [f"a{k}" for k in (0, 1, 2, 10, 11, 20, 100)]
    job = json.loads(EXAMPLE.read_text())
    for k, name in enumerate(reversed(names)):
        (folder / f"{name}.json").write_text(json.dumps(dict(job, alpha=k / 10, samples=3)))
    subprocess.run([str(cli), "run", "--jobs", str(folder), "-o", str(tmp_path / "out")], check=True)
    summary = (tmp_path / "out" / "summary.csv").read_text().splitlines()[1:]
    assert [line.split(",")[0] for line in summary] == names


def test_many_jobs_into_one_parquet_table(cli: Path, tmp_path: Path) -> None:
    """`--parquet FILE.parquet`: every job's samples in one table, with `job`
    and `alpha`, one schema whatever the regime (tables of two sweeps
    concatenate), each job's rows equal to its own `--parquet` file."""
    pa = pytest.importorskip("pyarrow")
    pc = pytest.importorskip("pyarrow.compute")
    folder = tmp_path / "sweep"
    folder.mkdir()
    job = json.loads(EXAMPLE.read_text())
    alphas = {f"a{k}": k / 10 for k in range(11)}
    for name, a in alphas.items():
        (folder / f"{name}.json").write_text(json.dumps(dict(job, alpha=a, samples=9)))
    (folder / "broken.json").write_text('{"order": 2}')
    done = subprocess.run(
        [str(cli), "run", "--jobs", str(folder), "-o", str(tmp_path / "out"), "--parquet", str(tmp_path / "all.parquet")],
        capture_output=True, text=True,
    )
    assert done.returncode == 2, done.stderr
    table = pq.read_table(tmp_path / "all.parquet")
    names = list(alphas)
    assert table.column("job").to_pylist() == [n for n in names for _ in range(9)]
    assert table.column("alpha").to_pylist() == [alphas[n] for n in names for _ in range(9)]
    assert (tmp_path / "out" / "summary.parquet").is_file()
    for name in ("a3", "a8"):  # below and above h = 0.6
        single = tmp_path / f"{name}.parquet"
        subprocess.run([str(cli), "run", str(folder / f"{name}.json"), "--parquet", str(single), "-o", str(tmp_path / f"{name}.json")], check=True)
        theirs = pq.read_table(single)
        mine = table.filter(pc.equal(table.column("job"), name))
        for column in table.column_names[2:]:
            if column in theirs.column_names:
                assert mine.column(column).to_pylist() == theirs.column(column).to_pylist(), (name, column)
            else:
                assert mine.column(column).null_count == 9, (name, column)
    # Another sweep's table has the same schema: they concatenate.
    other = tmp_path / "other"
    other.mkdir()
    (other / "z.json").write_text(json.dumps(dict(job, alpha=0.9, samples=4)))
    (other / "y.json").write_text(json.dumps(dict(job, alpha=0.2, samples=4)))
    subprocess.run([str(cli), "run", "--jobs", str(other), "-o", str(tmp_path / "o2"), "--parquet", str(tmp_path / "two.parquet")], check=True)
    both = pa.concat_tables([table, pq.read_table(tmp_path / "two.parquet")])
    assert both.num_rows == 11 * 9 + 8


def test_many_jobs_into_one_json_lines_file(cli: Path, tmp_path: Path) -> None:
    """`--jsonl FILE`: a JSON object per line, per job and parameter, with
    the keys and the values of the one Parquet table (`null` where a job
    lacks a column): the lines read with `json` are the table's rows as
    pyarrow reads them, for curves below and above h, a surface and a
    failing job alike; one job's `--jsonl` is its lines of the many."""
    folder = tmp_path / "jobs"
    folder.mkdir()
    job = json.loads(EXAMPLE.read_text())
    for name, a in [("a2", 0.3), ("a10", 0.8), ("a1", 0.6)]:
        (folder / f"{name}.json").write_text(json.dumps(dict(job, alpha=a, samples=7)))
    shutil.copy(ROOT / "fixtures" / "spiral-3d.json", folder / "c.json")
    surface = json.loads((ROOT / "examples" / "fuzzy-terrain.json").read_text())
    (folder / "d.json").write_text(json.dumps(dict(surface, alpha=0.2, samples=[3, 4])))
    (folder / "e.json").write_text(json.dumps(dict(job, type_reduction="centroid", samples=5)))
    (folder / "broken.json").write_text('{"order": 2}')
    done = subprocess.run(
        [str(cli), "run", "--jobs", str(folder), "-o", str(tmp_path / "out"),
         "--parquet", str(tmp_path / "all.parquet"), "--jsonl", str(tmp_path / "all.jsonl")],
        capture_output=True, text=True,
    )
    assert done.returncode == 2, done.stderr
    text = (tmp_path / "all.jsonl").read_text()
    assert text.endswith("}\n")
    lines = [json.loads(line) for line in text.splitlines()]
    table = pq.read_table(tmp_path / "all.parquet")
    assert lines == table.to_pylist()
    # One schema: every line has the table's keys in its order.
    assert all(list(line) == table.column_names for line in lines)
    jobs = [line["job"] for line in lines]
    assert sorted(set(jobs), key=jobs.index) == ["a1", "a2", "a10", "c", "d", "e"]
    assert {line["alpha"] for line in lines if line["job"] == "e"} == {None}
    assert {line["alpha"] for line in lines if line["job"] == "a10"} == {0.8}
    # A single job writes its own lines, named after its file.
    one = tmp_path / "one.jsonl"
    subprocess.run(
        [str(cli), "run", str(folder / "a10.json"), "-o", str(tmp_path / "a10.json"), "--jsonl", str(one)],
        check=True,
    )
    mine = [json.loads(line) for line in one.read_text().splitlines()]
    theirs = [line for line in lines if line["job"] == "a10"]
    assert len(mine) == 7
    assert mine == theirs


def test_only_the_one_table_without_a_result_folder(cli: Path, tmp_path: Path) -> None:
    """Without `-o`, `--parquet FILE.parquet` (or `--jsonl FILE`) writes no
    file per job: the table, and the summary beside it, the same as with
    `-o`; without either, `-o` is asked for."""
    folder = tmp_path / "jobs"
    folder.mkdir()
    job = json.loads(EXAMPLE.read_text())
    for k in range(4):
        (folder / f"a{k}.json").write_text(json.dumps(dict(job, alpha=k / 4, samples=5)))
    both = tmp_path / "both"
    both.mkdir()
    subprocess.run(
        [str(cli), "run", "--jobs", str(folder), "-o", str(both / "out"), "--parquet", str(both / "all.parquet")],
        check=True,
    )
    only = tmp_path / "only"
    only.mkdir()
    subprocess.run(
        [str(cli), "run", "--jobs", str(folder), "--parquet", str(only / "all.parquet"), "--jsonl", str(only / "all.jsonl")],
        check=True,
    )
    assert sorted(p.name for p in only.iterdir()) == ["all.jsonl", "all.parquet", "summary.csv", "summary.parquet"]
    assert pq.read_table(only / "all.parquet").equals(pq.read_table(both / "all.parquet"))
    assert (only / "summary.csv").read_bytes() == (both / "out" / "summary.csv").read_bytes()
    assert pq.read_table(only / "summary.parquet").equals(pq.read_table(both / "out" / "summary.parquet"))
    done = subprocess.run([str(cli), "run", "--jobs", str(folder)], capture_output=True, text=True)
    assert done.returncode == 2
    assert "give a folder for them, -o DIR (or only one table" in done.stderr


def test_the_table_written_group_by_group_is_the_table_of_every_result(cli: Path, tmp_path: Path) -> None:
    """A run with only the one Parquet table writes it a group of jobs at a
    time: over several groups, with derivatives and failing jobs among
    them, it is the table written from every result at once (as with
    `--jsonl` beside it), and its JSON Lines."""
    folder = tmp_path / "jobs"
    folder.mkdir()
    job = json.loads(EXAMPLE.read_text())
    for k in range(300):
        text = '{"order": 2}' if k % 97 == 5 else json.dumps(dict(job, alpha=(k % 11) / 10, samples=3))
        (folder / f"j{k}.json").write_text(text)
    runs = {}
    for name, extra in [("grouped", []), ("whole", ["--jsonl", str(tmp_path / "whole.jsonl")])]:
        done = subprocess.run(
            [str(cli), "run", "--jobs", str(folder), "--derivatives", "2", "--parquet", str(tmp_path / f"{name}.parquet"), *extra],
            capture_output=True, text=True,
        )
        assert done.returncode == 2, done.stderr
        runs[name] = pq.read_table(tmp_path / f"{name}.parquet")
    assert pq.ParquetFile(tmp_path / "grouped.parquet").num_row_groups > 1
    assert runs["grouped"].equals(runs["whole"])
    assert runs["grouped"].num_rows == (300 - 4) * 3
    assert "defuzzified_d2_y" in runs["grouped"].column_names
    lines = [json.loads(line) for line in (tmp_path / "whole.jsonl").read_text().splitlines()]
    assert lines == runs["grouped"].to_pylist()
