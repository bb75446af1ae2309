"""An alpha a few ulps above a number's lower height (a sweep by
`np.linspace(0, 1, 21)`, whose 13th level is 0.6000000000000001, past the
paper's jump at h = 0.6) is said: a `UserWarning` from `run` and `run_many`,
the row's message in `run_table`, a note on standard error from the
command-line tool; an alpha at the height, or well above it, is not."""

from __future__ import annotations

import json
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

import t2spline
from conftest import EXAMPLE

SWEEP = float(np.linspace(0, 1, 21)[12])
NOTE = (
    "alpha 0.6000000000000001 lies 1 ulp above the lower height 0.6 of a number: the run "
    "takes alpha > h there (no lower cut, two-term averages), on the other side of the jump "
    "from alpha = 0.6"
)


def test_the_sweep_s_level_lies_past_the_jump() -> None:
    assert SWEEP == 0.6000000000000001
    with pytest.warns(UserWarning) as said:
        past = t2spline.run(EXAMPLE, alpha=SWEEP, samples=11)
    assert [str(w.message) for w in said] == [NOTE]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        at = t2spline.run(EXAMPLE, alpha=0.6, samples=11)
        above = t2spline.run(EXAMPLE, alpha=0.61, samples=11)
    # The jump the note speaks of: the regime and the error change.
    assert (past["regime"], at["regime"], above["regime"]) == ("alpha > h", "alpha <= h", "alpha > h")
    assert past["error"]["max"] != at["error"]["max"]


def test_many_jobs_name_the_job() -> None:
    job = json.loads(EXAMPLE.read_text())
    jobs = [dict(job, alpha=a) for a in np.linspace(0, 1, 21)]
    with pytest.warns(UserWarning) as said:
        t2spline.run_many(jobs)
    assert [str(w.message) for w in said] == [f"jobs[12]: {NOTE}"]


def test_a_table_s_row_carries_the_note() -> None:
    pa = pytest.importorskip("pyarrow")
    text = EXAMPLE.read_text()
    job = json.loads(text)
    texts = [json.dumps(dict(job, alpha=a)) for a in (0.5, SWEEP, 0.6)]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rows = t2spline.run_table(pa.table({"job": texts})).to_pylist()
    assert [r["status"] for r in rows] == ["ok"] * 3
    assert [r["message"] for r in rows] == [None, NOTE, None]


def test_the_command_line_tool_notes_it(cli: Path, tmp_path: Path) -> None:
    done = subprocess.run(
        [str(cli), "run", str(EXAMPLE), "--alpha", repr(SWEEP), "-o", str(tmp_path / "r.json")],
        capture_output=True, text=True,
    )
    assert done.returncode == 0
    assert done.stderr == f"t2spline run: note: {NOTE}\n"
    done = subprocess.run(
        [str(cli), "run", str(EXAMPLE), "--alpha", "0.6", "-o", str(tmp_path / "r.json")],
        capture_output=True, text=True,
    )
    assert (done.returncode, done.stderr) == (0, "")
    # In a run of many jobs, the note names its job.
    folder = tmp_path / "jobs"
    folder.mkdir()
    job = json.loads(EXAMPLE.read_text())
    for name, a in [("a", 0.5), ("b", SWEEP)]:
        (folder / f"{name}.json").write_text(json.dumps(dict(job, alpha=a)))
    done = subprocess.run(
        [str(cli), "run", "--jobs", str(folder), "-o", str(tmp_path / "out")],
        capture_output=True, text=True,
    )
    assert done.returncode == 0
    assert done.stderr == f"t2spline run: {folder / 'b.json'}: note: {NOTE}\n"


def test_the_result_carries_the_note(cli: Path, tmp_path: Path) -> None:
    # Python's result dict: a `note` key after `regime`, only near the height.
    with pytest.warns(UserWarning):
        past = t2spline.run(EXAMPLE, alpha=SWEEP, samples=11)
    assert past["note"] == NOTE
    keys = list(past)
    assert keys[keys.index("regime") + 1] == "note"
    for alpha in (0.6, 0.61, 0.5):
        assert "note" not in t2spline.run(EXAMPLE, alpha=alpha, samples=11)
    # The result file `t2spline run` writes, and its standard output.
    out = tmp_path / "r.json"
    done = subprocess.run(
        [str(cli), "run", str(EXAMPLE), "--alpha", repr(SWEEP), "--samples", "11", "-o", str(out)],
        capture_output=True, text=True,
    )
    assert done.returncode == 0, done.stderr
    written = json.loads(out.read_text())
    assert written["note"] == NOTE
    assert list(written) == keys
    shown = subprocess.run(
        [str(cli), "run", str(EXAMPLE), "--alpha", repr(SWEEP), "--samples", "11"],
        capture_output=True, text=True,
    )
    assert shown.stdout.encode() == out.read_bytes()
    plain = subprocess.run(
        [str(cli), "run", str(EXAMPLE), "--alpha", "0.6", "--samples", "11"],
        capture_output=True, text=True,
    )
    assert plain.returncode == 0 and "note" not in json.loads(plain.stdout)
