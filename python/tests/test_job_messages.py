"""Every bad job held in `fixtures/bad-jobs/` gives the same problems from
Python as from the command line: as a file, exactly the lines of `t2spline
run FILE`; as a dict (the file's JSON through `json.loads`, so `NaN` and
`Infinity` become floats), the same places and rules, each line
`<dict>:LINE:COLUMN: PLACE: RULE` of the `json.dumps(job, indent=2)` text.
The fixtures named `text-*` hold problems of the text itself (syntax,
duplicate keys, numbers beyond a float), which a dict cannot have. The
Rust side (`crates/t2spline-cli/tests/job_messages.rs`) holds the command
line and the I/O library to the same lines."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import List

import pytest

import t2spline

from conftest import ROOT, cli_errors

BAD_JOBS = sorted((ROOT / "fixtures" / "bad-jobs").glob("*.json"))
PLACED = re.compile(r"^(?:<dict>|.+\.json):\d+:\d+: ")


def rules(lines: List[str]) -> List[str]:
    """The lines without the file, line and column: `PLACE: RULE`."""
    return [PLACED.sub("", line, count=1) for line in lines]


def test_the_fixtures_are_there() -> None:
    assert len(BAD_JOBS) >= 60


@pytest.mark.parametrize("path", BAD_JOBS, ids=lambda p: p.stem)
def test_a_bad_job_file_gives_the_cli_lines(cli: Path, path: Path) -> None:
    want = cli_errors(cli, path)
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(path)
    assert e.value.problems == want


@pytest.mark.parametrize(
    "path", [p for p in BAD_JOBS if not p.stem.startswith("text-")], ids=lambda p: p.stem
)
def test_a_bad_job_dict_gives_the_cli_places_and_rules(cli: Path, path: Path) -> None:
    want = cli_errors(cli, path)
    job = json.loads(path.read_text())
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(job)
    got = e.value.problems
    assert all(line.startswith("<dict>:") for line in got if PLACED.match(line)), got
    assert rules(got) == rules(want)


def test_nan_and_infinity_read_alike_from_a_file_and_a_dict(cli: Path) -> None:
    path = ROOT / "fixtures" / "bad-jobs" / "non-finite-words.json"
    rule = "is not a finite number (NaN and infinity are refused)"
    want = [f"alpha: -inf {rule}", f"points[1].x.crisp: NaN {rule}", f"weights[1]: inf {rule}"]
    assert rules(cli_errors(cli, path)) == want
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(json.loads(path.read_text()))
    assert rules(e.value.problems) == want


def test_a_dict_value_with_no_form_in_a_job_file_is_named_by_its_place() -> None:
    job = json.loads((ROOT / "examples" / "paper-alg-1-1.json").read_text())
    job["points"][1]["x"]["crisp"] = {1.5}
    with pytest.raises(TypeError, match=r"^job: points\[1\]\.x\.crisp: a value of type set has no "
                                        r"form in a job file$"):
        t2spline.run(job)
    job["points"][1]["x"]["crisp"] = 1.0
    job["knots"] = {(0, 1): [0, 1]}
    with pytest.raises(TypeError, match=r"^job: knots: a key of type tuple is not a string$"):
        t2spline.run(job)


def test_to_json_writes_places_as_the_job_reader_does() -> None:
    with pytest.raises(TypeError, match=r'^result\["a b"\]\[1\]: a value of type set has no form in JSON$'):
        t2spline.to_json({"a b": [1, {2}]})
    with pytest.raises(ValueError, match=r"^result\.y\[1\]: inf is not a finite number"):
        t2spline.to_json({"y": [1.0, float("inf")]})
