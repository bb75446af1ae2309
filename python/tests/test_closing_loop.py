"""The loop of the command-line tool closed in Python, by the tool's own
code: `fuzzify` gives the data file `t2spline fuzzify` writes, `to_job`
gives a job that `run` and `t2spline run` run to the same numbers (and
`from_job` reads back), `export` writes the bytes of `t2spline export`, and
`to_json` of a result is the bytes of `t2spline run`'s result file."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Any, Dict

import pytest

import t2spline
from conftest import EXAMPLE, ROOT

TERRAIN = ROOT / "examples" / "fuzzy-terrain.json"
READINGS = ROOT / "examples" / "beach-readings.csv"


def cli_bytes(cli: Path, *args: str, env: Dict[str, str] | None = None) -> bytes:
    done = subprocess.run([str(cli), *args], capture_output=True, check=True, env=env)
    return done.stdout


@pytest.mark.filterwarnings("ignore:.*type reduction centroid does not use alpha")
@pytest.mark.parametrize(
    "job, args",
    [
        (EXAMPLE, {}),
        (EXAMPLE, {"alpha": 0.3, "samples": 7}),   # below h: every lower cut
        (EXAMPLE, {"alpha": 0.9, "derivatives": 2}),  # above h: null lower ends
        (EXAMPLE, {"type_reduction": "centroid"}),
        (TERRAIN, {}),
        (TERRAIN, {"samples": (4, 3), "alpha": 0.7}),
    ],
)
def test_to_json_is_the_bytes_of_the_result_file(cli: Path, tmp_path: Path, job: Path, args: Dict[str, Any]) -> None:
    flags = []
    for key, value in args.items():
        flags += [f"--{key.replace('_', '-')}", ",".join(map(str, value)) if isinstance(value, tuple) else str(value)]
    stdout = cli_bytes(cli, "run", str(job), *flags)
    text = t2spline.to_json(t2spline.run(job, **args))
    assert text.encode() == stdout
    # And the file `-o` writes; and a result of run_many.
    out = tmp_path / "r.json"
    cli_bytes(cli, "run", str(job), *flags, "-o", str(out))
    assert text.encode() == out.read_bytes()
    [many] = t2spline.run_many([job], **args)
    assert isinstance(many, dict)
    assert t2spline.to_json(many) == text


def test_to_json_refuses_what_has_no_json_form() -> None:
    with pytest.raises(TypeError, match=r"result\.x: a value of type object"):
        t2spline.to_json({"x": object()})
    with pytest.raises(ValueError, match=r"result\.y\[1\]: inf is not a finite number"):
        t2spline.to_json({"y": [1.0, float("inf")]})


def test_a_curve_s_job_runs_to_the_same_numbers(cli: Path, tmp_path: Path) -> None:
    given = json.loads(EXAMPLE.read_text())
    curve = t2spline.FuzzyCurve.from_job(EXAMPLE)
    job = curve.to_job(given["alpha"], description=given["description"])
    assert job["alpha"] == 0.8 and job["type_reduction"] == "paper" and job["samples"] == 101
    assert t2spline.FuzzyCurve.from_job(job) == curve
    # `t2spline run` of the job written out: the bytes of the shipped job's run.
    path = tmp_path / "job.json"
    path.write_text(json.dumps(job))
    assert cli_bytes(cli, "run", str(path)) == cli_bytes(cli, "run", str(EXAMPLE))
    assert t2spline.to_json(t2spline.run(job)) == t2spline.to_json(t2spline.run(EXAMPLE))
    # Without alpha the paper's reduction asks for one; the keywords are kept.
    bare = curve.to_job()
    assert "alpha" not in bare
    with pytest.raises(t2spline.JobError, match="alpha: missing"):
        t2spline.run(bare)
    other = curve.to_job(samples=5, type_reduction="nie-tan")
    assert (other["samples"], other["type_reduction"]) == (5, "nie-tan")
    assert t2spline.run(other)["curves"]["params"].shape == (5,)
    with pytest.raises(ValueError, match=r"alpha: "):
        curve.to_job(1.5)
    with pytest.raises(ValueError, match=r"samples: must be at least 2"):
        curve.to_job(samples=1)


def test_a_surface_s_job_runs_to_the_same_numbers(cli: Path, tmp_path: Path) -> None:
    given = json.loads(TERRAIN.read_text())
    surface = t2spline.FuzzySurface.from_job(TERRAIN)
    job = surface.to_job(given["alpha"], samples=tuple(given["samples"]), description=given["description"])
    assert job["samples"] == [51, 41]
    assert t2spline.FuzzySurface.from_job(job) == surface
    path = tmp_path / "job.json"
    path.write_text(json.dumps(job))
    assert cli_bytes(cli, "run", str(path)) == cli_bytes(cli, "run", str(TERRAIN))


def test_fuzzify_gives_the_data_file_of_the_command(cli: Path, tmp_path: Path) -> None:
    for options, flags in [
        ({}, []),
        ({"tolerance": 0.05, "alpha": 0.4, "order": 3}, ["--tolerance", "0.05", "--alpha", "0.4", "--order", "3"]),
        ({"lower_height": 0.7, "degree": 2}, ["--lower-height", "0.7", "--degree", "2"]),
    ]:
        data = t2spline.fuzzify(READINGS, **options)
        assert data == json.loads(cli_bytes(cli, "fuzzify", str(READINGS), *flags))
    # The data, fitted by `t2spline fit`, is a job that runs.
    data_file = tmp_path / "data.json"
    data_file.write_text(json.dumps(t2spline.fuzzify(str(READINGS), alpha=0.5)))
    job = tmp_path / "job.json"
    subprocess.run([str(cli), "fit", str(data_file), "-q", "-o", str(job)], check=True)
    assert t2spline.run(job)["alpha"] == 0.5
    # Options out of range are named; the file's problems are a JobError.
    with pytest.raises(ValueError, match=r"^tolerance: "):
        t2spline.fuzzify(READINGS, tolerance=-1)
    with pytest.raises(ValueError, match=r"^degree: a fit needs degree 1 to 31"):
        t2spline.fuzzify(READINGS, degree=0)
    with pytest.raises(ValueError, match=r"^alpha: "):
        t2spline.fuzzify(READINGS, alpha=2)
    bad = tmp_path / "bad.csv"
    bad.write_text("station,x,y\nA,1,2\nA,1,x\n")
    with pytest.raises(t2spline.JobError, match=r"bad\.csv:3:"):
        t2spline.fuzzify(bad)
    with pytest.raises(TypeError, match="readings: expected the path"):
        t2spline.fuzzify(3)  # type: ignore[arg-type]


@pytest.mark.parametrize("name, fmt", [("c.step", None), ("c.dxf", None), ("c.igs", None), ("c.txt", "obj")])
def test_export_writes_the_bytes_of_the_command(cli: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str, fmt: str | None) -> None:
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1800000000")
    mine = tmp_path / "mine" / name
    mine.parent.mkdir()
    t2spline.export(EXAMPLE, mine, format=fmt, alpha=0.3)
    theirs = tmp_path / name
    flags = ["--format", fmt] if fmt else []
    subprocess.run([str(cli), "export", str(EXAMPLE), "-o", str(theirs), "--alpha", "0.3", *flags], check=True, env=dict(os.environ))
    assert mine.read_bytes() == theirs.read_bytes()


def test_export_refuses_before_writing(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"format: missing: the extension of .*c\.txt names no format"):
        t2spline.export(EXAMPLE, tmp_path / "c.txt")
    with pytest.raises(ValueError, match=r'format: unknown format "svg" \(known: dxf, step, iges, obj\)'):
        t2spline.export(EXAMPLE, tmp_path / "c.step", format="svg")  # type: ignore[arg-type]
    with pytest.raises(t2spline.JobError, match="DXF holds NURBS curves"):
        t2spline.export(TERRAIN, tmp_path / "t.dxf")
    assert list(tmp_path.iterdir()) == []
    t2spline.export(TERRAIN, tmp_path / "t.step")
    assert (tmp_path / "t.step").read_text().startswith("ISO-10303-21;")


def test_export_records_the_unit_as_the_command_does(cli: Path, tmp_path: Path) -> None:
    job = json.loads(EXAMPLE.read_text())
    job["units"] = "m"
    env = {**os.environ, "SOURCE_DATE_EPOCH": "0"}
    for given, code in [(None, "6"), ("in", "1")]:
        ours = tmp_path / f"py-{given}.dxf"
        theirs = tmp_path / f"cli-{given}.dxf"
        os.environ["SOURCE_DATE_EPOCH"] = "0"
        try:
            t2spline.export(job, ours, units=given)  # type: ignore[arg-type]
        finally:
            del os.environ["SOURCE_DATE_EPOCH"]
        path = tmp_path / "job.json"
        path.write_text(json.dumps(job))
        extra = ["--units", given] if given else []
        subprocess.run([str(cli), "export", str(path), "-o", str(theirs), *extra], check=True, env=env)
        assert ours.read_bytes() == theirs.read_bytes()
        assert "$INSUNITS\n 70\n" + code + "\n" in ours.read_text()
    with pytest.raises(ValueError, match='units: unknown unit "yd"'):
        t2spline.export(job, tmp_path / "x.dxf", units="yd")  # type: ignore[arg-type]
