"""Every kind of error: job problems as the CLI's lines (`JobError`),
settings named by their keyword, unreadable files as `OSError`, wrong shapes
and dtypes naming the argument, the core's rules naming their place, and a
panic that becomes a `RuntimeError`."""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any, Callable, Dict

import numpy as np
import pytest

import t2spline

from conftest import EXAMPLE, cli_errors

JOB: Dict[str, Any] = json.loads(EXAMPLE.read_text())


def broken_job() -> Dict[str, Any]:
    """The example with four problems: a misspelt key, a broken order, a
    weight too many, decreasing knots."""
    job = copy.deepcopy(JOB)
    job["alhpa"] = job.pop("alpha")
    job["points"][2]["y"]["lower"] = [4.9, 4.3]
    job["weights"].append(1)
    job["knots"] = [0, 0, 0.7, 0.2, 1, 1, 1]
    return job


def test_a_dict_job_gives_the_cli_lines_with_the_dict_as_file(cli: Path, tmp_path: Path) -> None:
    job = broken_job()
    path = tmp_path / "job.json"
    path.write_text(json.dumps(job, indent=2))
    want = [line.replace(str(path), "<dict>") for line in cli_errors(cli, path)]
    assert len(want) >= 4
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(job)
    assert isinstance(e.value, ValueError)
    assert e.value.problems == want
    assert str(e.value) == "\n".join(want)


@pytest.mark.parametrize(
    "text",
    [
        json.dumps(broken_job(), indent=1),
        '{"order": 2, "alpha": 0.5,}',  # JSON syntax
        '{"order": 2, "alpha": NaN, "points": []}',  # not JSON
        '{"order": 2, "order": 3}',  # duplicate key
        "[1, 2]",
    ],
)
def test_a_job_file_gives_exactly_the_cli_lines(cli: Path, tmp_path: Path, text: str) -> None:
    path = tmp_path / "job.json"
    path.write_text(text)
    want = cli_errors(cli, path)
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(path)
    assert e.value.problems == want
    with pytest.raises(t2spline.JobError) as e:
        t2spline.FuzzyCurve.from_job(str(path))
    assert e.value.problems == want


def test_a_file_that_is_not_utf8_is_a_job_error_as_for_the_cli(cli: Path, tmp_path: Path) -> None:
    path = tmp_path / "job.json"
    path.write_bytes(b'{"order": 2, "description": "\xff\xfe"}')
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(path)
    assert e.value.problems == cli_errors(cli, path)


RULE = "is not a finite number (NaN and infinity are refused)"


def place(job: Dict[str, Any], word: str) -> str:
    """`<dict>:LINE:COLUMN` of the key whose value `json.dumps` writes as
    `word` (the first), as the validator places a member."""
    text = json.dumps(job, indent=2)
    line = text[: text.index(word)].count("\n")
    key = text.split("\n")[line]
    return f"<dict>:{line + 1}:{len(key) - len(key.lstrip()) + 1}"


def test_nan_and_infinity_in_a_dict_job_are_named_with_place_and_rule() -> None:
    for bad, word, shown in ((float("nan"), "NaN", "NaN"), (float("inf"), "Infinity", "inf"),
                             (-np.inf, "-Infinity", "-inf")):
        job = copy.deepcopy(JOB)
        job["points"][1]["x"]["crisp"] = bad
        with pytest.raises(t2spline.JobError) as e:
            t2spline.run(job)
        assert e.value.problems == [f"{place(job, word)}: points[1].x.crisp: {shown} {RULE}"]
    # An infinite weight, a NaN inside a numpy array, every one of them.
    job = copy.deepcopy(JOB)
    job["weights"] = np.array([1.0, np.inf, 3.0, 1.0])
    job["points"][0]["y"]["upper"] = np.array([np.nan, 1.5])
    job["alpha"] = np.float64("nan")
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(job)
    assert [p.split(": ", 1)[1] for p in e.value.problems] == [
        f"weights[1]: inf {RULE}", f"alpha: NaN {RULE}", f"points[0].y.upper[0]: NaN {RULE}",
    ]
    assert all(p.startswith("<dict>:") and "JSON syntax" not in p for p in e.value.problems)


def test_every_entry_point_of_a_dict_job_names_nan_and_infinity() -> None:
    job = copy.deepcopy(JOB)
    job["weights"][2] = float("inf")
    want = [f"{place(job, 'Infinity')}: weights[2]: inf {RULE}"]
    for call in (t2spline.run, t2spline.FuzzyCurve.from_job,
                 lambda j: t2spline.run(j, samples=5, alpha=0.5, type_reduction="centroid")):
        with pytest.raises(t2spline.JobError) as e:
            call(job)
        assert e.value.problems == want
    surface = json.loads((EXAMPLE.parent / "fuzzy-terrain.json").read_text())
    surface["points"][1][2]["z"]["crisp"] = float("nan")
    for entry in (t2spline.run, t2spline.FuzzySurface.from_job):
        with pytest.raises(t2spline.JobError) as e:
            entry(surface)
        (problem,) = e.value.problems
        assert problem == f"{place(surface, 'NaN')}: points[1][2].z.crisp: NaN {RULE}"
    # A string holding the words is text, not a number.
    job = copy.deepcopy(JOB)
    job["description"] = "NaN and -Infinity"
    assert t2spline.run(job)["description"] == "NaN and -Infinity"


def test_a_missing_alpha_is_placed_as_the_cli_places_it(cli: Path, tmp_path: Path) -> None:
    job = copy.deepcopy(JOB)
    del job["alpha"]
    path = tmp_path / "job.json"
    path.write_text(json.dumps(job, indent=2))
    (want,) = cli_errors(cli, path)
    assert want == f"{path}:1:1: alpha: missing: give it in the job file or with --alpha"
    with pytest.raises(t2spline.JobError) as e:
        t2spline.run(path)
    assert e.value.problems == [f"{path}:1:1: alpha: missing: give it in the job or as alpha="]
    assert t2spline.run(path, alpha=0.5)["alpha"] == 0.5


@pytest.mark.parametrize(
    "kwargs, option",
    [
        ({"samples": 1}, ["--samples", "1"]),
        ({"samples": 10**7}, ["--samples", "10000000"]),
        ({"alpha": 1.5}, ["--alpha", "1.5"]),
        ({"alpha": -0.25}, ["--alpha", "-0.25"]),
        ({"derivatives": 17}, ["--derivatives", "17"]),
        ({"derivatives": 0}, ["--derivatives", "0"]),
        ({"derivatives": 5, "samples": 1_000_000}, ["--derivatives", "5", "--samples", "1000000"]),
    ],
)
def test_settings_name_their_keyword_with_the_cli_rule(
    cli: Path, kwargs: Dict[str, Any], option: list
) -> None:
    (want,) = cli_errors(cli, EXAMPLE, *option)
    with pytest.raises(ValueError) as e:
        t2spline.run(EXAMPLE, **kwargs)
    assert not isinstance(e.value, t2spline.JobError)
    # The CLI names the option (`--samples: …`), Python the keyword (`samples: …`).
    assert "--" + str(e.value) == want


def test_derivatives_beyond_a_float_name_the_keyword(cli: Path, tmp_path: Path) -> None:
    # A knot span of 1e-140 and a coordinate of 1e148: the third derivative
    # is about 1e148 / (1e-140)^3, far beyond 1.8e308.
    def number(c: float) -> Dict[str, Any]:
        return {"crisp": c, "upper": [c - 1, c + 1], "primary": [c - 0.5, c + 0.5], "lower": [c, c]}

    steep = {"crisp": 1e148, "upper": [1e148, 1e148], "primary": [1e148, 1e148], "lower": [1e148, 1e148]}
    job = {"order": 3, "alpha": 0.5, "lower_height": 0.5, "samples": 5,
           "knots": [0, 0, 0, 1e-140, 1, 1],
           "points": [{"x": number(0), "y": number(0)}, {"x": steep, "y": number(2)},
                      {"x": number(2), "y": number(1)}]}
    path = tmp_path / "steep.json"
    path.write_text(json.dumps(job))
    (want,) = cli_errors(cli, path, "--derivatives", "3")
    with pytest.raises(ValueError) as e:
        t2spline.run(job, derivatives=3)
    assert "--" + str(e.value) == want
    assert "is beyond the range of a 64-bit float" in want
    assert np.isfinite(t2spline.run(job)["curves"]["crisp"]).all()


def test_settings_the_cli_cannot_take() -> None:
    with pytest.raises(ValueError, match=r"^samples: samples = -5: at least 2 are needed"):
        t2spline.run(EXAMPLE, samples=-5)
    with pytest.raises(ValueError, match=r"^alpha: alpha = NaN is outside \[0, 1\]"):
        t2spline.run(EXAMPLE, alpha=float("nan"))
    with pytest.raises(ValueError, match=r"^alpha: alpha = inf is outside \[0, 1\]"):
        t2spline.run(EXAMPLE, alpha=float("inf"))


def test_wrong_types_are_type_errors_naming_the_argument() -> None:
    with pytest.raises(TypeError, match="^job: expected a dict"):
        t2spline.run(42)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="^job: expected a dict"):
        t2spline.run(b"job.json")  # type: ignore[arg-type]
    # A number of the wrong type: the message names the keyword and what it
    # takes (every function's: test_keywords.py).
    with pytest.raises(TypeError, match=r"^samples: expected an int or a pair \(u, v\) of ints, got str$"):
        t2spline.run(EXAMPLE, samples="3")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"^alpha: expected a real number \(float or int\), got str$"):
        t2spline.run(EXAMPLE, alpha="high")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^degree: 18446744073709551616 is outside the range of a 64-bit"):
        t2spline.NurbsCurve([[0, 0], [1, 1]], degree=2**64)
    job = copy.deepcopy(JOB)
    job["weights"] = {1, 2}
    with pytest.raises(TypeError, match=r"^job: weights: a value of type set has no form in a job file$"):
        t2spline.run(job)


def test_unreadable_files_are_os_errors(tmp_path: Path) -> None:
    missing = tmp_path / "no" / "job.json"
    with pytest.raises(FileNotFoundError) as e:
        t2spline.run(missing)
    assert e.value.filename == str(missing)
    assert str(e.value) == f"[Errno 2] No such file or directory: '{missing}'"
    with pytest.raises(IsADirectoryError):
        t2spline.run(tmp_path)


# --- objects: shapes, dtypes, values ----------------------------------------

C = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
S = np.array([-0.5, 0.8])


def fuzzy(**changes: Any) -> t2spline.FuzzyCurve:
    args: Dict[str, Any] = dict(
        crisp=C, upper=C[..., None] + S, primary=C[..., None] + 0.5 * S,
        lower=C[..., None] + 0.2 * S, lower_height=0.6, degree=2,
    )
    args.update(changes)
    return t2spline.FuzzyCurve(**args)


@pytest.mark.parametrize(
    "changes, kind, message",
    [
        ({"crisp": C[:, 0]}, ValueError,
         "crisp: expected shape (n, 2) or (n, 3): n points in the plane or in space, got (4,)"),
        ({"crisp": np.zeros((4, 4))}, ValueError, "crisp: expected shape (n, 2) or (n, 3)"),
        ({"upper": C}, ValueError,
         "upper: expected shape (4, 2, 2): [left, right] per coordinate of crisp, got (4, 2)"),
        ({"lower": np.zeros((3, 2, 2))}, ValueError, "lower: expected shape (4, 2, 2)"),
        ({"lower_height": [0.5, 0.6, 0.7]}, ValueError,
         "lower_height: expected a number or an array that broadcasts to shape (4, 2): "
         "one per coordinate of crisp, got (3,)"),
        ({"lower_height": np.ones((4, 2, 1))}, ValueError, "lower_height: expected a number"),
        ({"crisp": C.astype(str)}, TypeError,
         "crisp: expected real numbers (float64), got an array of dtype <U32"),
        ({"crisp": C.astype(complex)}, TypeError, "crisp: expected real numbers"),
        ({"primary": np.ones((4, 2, 2), dtype=bool)}, TypeError, "primary: expected real numbers"),
        ({"crisp": [[0, 0], [1]]}, ValueError, "crisp: cannot be read as an array of numbers"),
        ({"crisp": np.where(C == 2.0, np.nan, C)}, ValueError,
         "crisp[1, 1] = NaN is not a finite number (NaN and infinity are refused)"),
        ({"weights": [1, 1, np.inf, 1]}, ValueError, "weights[2] = inf is not a finite number"),
        ({"weights": [[1, 1, 1, 1]]}, ValueError, "weights: expected a 1-D array, got shape (1, 4)"),
        ({"weights": [1, -1, 1, 1]}, ValueError, "weights[1] = -1 must be finite and greater than 0"),
        ({"weights": [1, 1, 1]}, ValueError, "weights: expected 4 (one per control point), got 3"),
        ({"degree": 4}, ValueError, "a curve of order 5 needs at least 5 control points, got 4"),
        ({"degree": 40}, ValueError, "degree: 40 is outside [0, 31]"),
        ({"degree": None}, ValueError, "degree: missing: give degree or order (or knots)"),
        ({"order": 3}, ValueError, "degree, order: give one of them, not both"),
        ({"knots": [0, 0, 0, 0.7, 0.2, 1, 1]}, ValueError, "knots[4] = 0.2 is less than knots[3] = 0.7"),
        ({"lower_height": 1.5}, ValueError, "points[0].x: lower_height = 1.5 is outside (0, 1]"),
        ({"lower": C[..., None] + np.array([0.1, 0.2])}, ValueError,
         "points[0].x: the order lower.left <= crisp is broken: 0.1 > 0"),
    ],
)
def test_fuzzy_curve_arguments(changes: Dict[str, Any], kind: type, message: str) -> None:
    with pytest.raises(kind) as e:
        fuzzy(**changes)
    assert str(e.value).startswith(message), str(e.value)


def test_integer_arrays_and_lists_are_numbers() -> None:
    c = C.astype(np.int64)
    a = t2spline.FuzzyCurve(c, c[..., None] + [-1, 2], c[..., None] + [-1, 1], c[..., None] + [0, 0],
                            lower_height=[[0.5, 1]] * 4, order=2)
    b = t2spline.FuzzyCurve(c.tolist(), (c[..., None] + [-1, 2]).tolist(),
                            (c[..., None] + [-1, 1]).tolist(), (c[..., None] + [0, 0]).tolist(),
                            lower_height=np.array([[0.5, 1.0]] * 4), degree=1)
    assert a == b and a.knots.tolist() == [0, 0, 1 / 3, 2 / 3, 1, 1]


@pytest.mark.parametrize(
    "call, kind, message",
    [
        (lambda c: c.sample(-1), ValueError, "params: a count of uniform parameters must be at least 0, got -1"),
        (lambda c: c.sample(10**12), ValueError, "params: 1000000000000 parameters would take"),
        (lambda c: c.sample([[0.5]]), ValueError, "params: expected a count (int) or a 1-D array"),
        (lambda c: c.solve(0.5).sample(10**12), ValueError, "params: 1000000000000 parameters would take"),
        (lambda c: c.crisp_curve().sample(10**12), ValueError, "params: 1000000000000 parameters would"),
        (lambda c: c.uniform_params(10**10), ValueError, "count: 10000000000 parameters would take"),
        (lambda c: c.uniform_params(-2), ValueError, "count: must be at least 0, got -2"),
        (lambda c: c.sample([0.5, 1.5]), ValueError, "parameter t = 1.5 is outside the domain [0, 1]"),
        (lambda c: c.sample(True), TypeError, "params: expected real numbers"),
        (lambda c: c.eval_layers(np.nan), ValueError, "t = NaN is not a finite number"),
        (lambda c: c.solve(1.5), ValueError, "alpha = 1.5 is outside [0, 1]"),
        (lambda c: c.layer_curve("upper"), ValueError, "layer: expected one of upper_left, "),
        (lambda c: c.insert_knot(0.5, times=0), ValueError, "times: must be at least 1, got 0"),
        (lambda c: c.insert_knot(0.5, times=4), ValueError, "cannot insert knot 0.5 4 times"),
        (lambda c: c.split_at(1.0), ValueError, "cannot split at t = 1"),
        (lambda c: c.point(4), ValueError, "index: 4 is outside [0, 3]"),
        (lambda c: c.crisp_curve().eval(2.0), ValueError, "parameter t = 2 is outside the domain [0, 1]"),
        (lambda c: c.crisp_curve().derivatives(0.5, order=65), ValueError, "derivative order = 65 is outside [0, 64]"),
        (lambda c: c.crisp_curve().closest_point([1, 2, 3]), ValueError,
         "point: expected shape (2,) or (m, 2), got (3,)"),
        (lambda c: c.crisp_curve().param_at_length(-1.0), ValueError, "arc length -1 is outside"),
        (lambda c: c.solve(0.5).type_reduced_curve("middle"), ValueError,
         "side: expected 'left' or 'right', got \"middle\""),
        (lambda c: c.point(0)[0].membership(0.0, which="outer"), ValueError,  # type: ignore[arg-type]
         "which: expected 'upper', 'primary' or 'lower'"),
    ],
)
def test_method_arguments(call: Callable[[t2spline.FuzzyCurve], Any], kind: type, message: str) -> None:
    with pytest.raises(kind) as e:
        call(fuzzy())
    assert str(e.value).startswith(message), str(e.value)


def test_fuzzy_number_rules_are_the_cores() -> None:
    with pytest.raises(ValueError, match=r"^the order upper.left <= primary.left is broken: 0.7 > 0.6$"):
        t2spline.FuzzyNumber(1.0, (0.7, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    with pytest.raises(ValueError, match=r"^crisp = NaN is not a finite number$"):
        t2spline.FuzzyNumber(float("nan"), (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.6)
    with pytest.raises(ValueError, match=r"lower_height = 0 is outside \(0, 1\]"):
        t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), (0.8, 1.3), 0.0)
    with pytest.raises(ValueError, match=r"^upper: expected shape \(2,\): \(left, right\), got \(3,\)$"):
        t2spline.FuzzyNumber(1.0, (0.4, 1.9, 2.0), (0.6, 1.6), (0.8, 1.3), 0.6)
    with pytest.raises(TypeError, match=r"^lower: expected real numbers \(float64\)"):
        t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, 1.6), "ab", 0.6)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^primary\[1\] = inf is not a finite number"):
        t2spline.FuzzyNumber(1.0, (0.4, 1.9), (0.6, np.inf), (0.8, 1.3), 0.6)
    assert t2spline.FuzzyNumber(1, np.array([0.4, 1.9]), [0.6, 1.6], (0.8, 1.3), 0.6).upper == (0.4, 1.9)


def test_fit_arguments() -> None:
    flat = C[..., None] + [0.0, 0.0]
    with pytest.raises(ValueError, match=r"^parametrization: unknown parametrization"):
        t2spline.fit(C, C[..., None] + S, flat, flat, 0.5, degree=2,
                     parametrization="chordal")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^mode: unknown fuzzy fit `best`"):
        t2spline.fit(C, C[..., None] + S, flat, flat, 0.5, degree=2,
                     mode="best")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^control points: 9 is outside \[3, 4\]"):
        t2spline.fit(C, C[..., None] + S, flat, flat, 0.5, degree=2, control_points=9)


def test_a_panic_becomes_a_runtime_error_and_python_goes_on() -> None:
    with pytest.raises(RuntimeError, match=r"^internal error: the Rust code panicked: boom \(please report"):
        t2spline._t2spline._panic_for_tests("boom")
    assert t2spline.run(EXAMPLE, samples=2)["curves"]["crisp"].shape == (2, 2)


# --- surfaces: arguments and methods name their place ------------------------

NET = np.array([[[0, 0, 0], [0, 1, 0], [0, 2, 1]],
                [[1, 0, 0], [1, 1, 1], [1, 2, 0]],
                [[2, 0, 1], [2, 1, 0], [2, 2, 2]]], dtype=float)


def nurbs_surface(**changes: Any) -> t2spline.NurbsSurface:
    args: Dict[str, Any] = dict(control_points=NET, degree=1)
    args.update(changes)
    return t2spline.NurbsSurface(**args)


def fuzzy_surface(**changes: Any) -> t2spline.FuzzySurface:
    args: Dict[str, Any] = dict(
        crisp=NET, upper=NET[..., None] + S, primary=NET[..., None] + 0.5 * S,
        lower=NET[..., None] + 0.2 * S, lower_height=0.6, degree=1,
    )
    args.update(changes)
    return t2spline.FuzzySurface(**args)


@pytest.mark.parametrize(
    "make, changes, kind, message",
    [
        (nurbs_surface, {"control_points": NET[0]}, ValueError,
         "control_points: expected shape (nu, nv, 2) or (nu, nv, 3): a net of nu × nv points in the "
         "plane or in space, got (3, 3)"),
        (nurbs_surface, {"control_points": NET.astype(str)}, TypeError,
         "control_points: expected real numbers (float64)"),
        (nurbs_surface, {"control_points": np.where(NET == 2, 1e300, NET)}, ValueError,
         "points[0][2].y: coordinate = 1e300 is outside [-1e150, 1e150]"),
        (nurbs_surface, {"weights": np.ones((3, 2))}, ValueError,
         "weights: expected shape (3, 3): one per control point of the net, got (3, 2)"),
        (nurbs_surface, {"weights": [[1, 1, 1], [0, 1, 1], [1, 1, 1]]}, ValueError,
         "weights[1][0] = 0 must be finite and greater than 0"),
        (nurbs_surface, {"weights": [[1, 1, 1], [1, 1, 1], [1, np.nan, 1]]}, ValueError,
         "weights[2, 1] = NaN is not a finite number"),
        (nurbs_surface, {"degree": (1, 3)}, ValueError,
         "points: a surface of order 4 in v needs at least 4 control points along v, got 3"),
        (nurbs_surface, {"degree": (1, 40)}, ValueError, "degree[1]: 40 is outside [0, 31]"),
        (nurbs_surface, {"degree": 40}, ValueError, "degree: 40 is outside [0, 31]"),
        (nurbs_surface, {"degree": None}, ValueError,
         "degree[0]: missing: give degree or order (or knots_u)"),
        (nurbs_surface, {"degree": None, "knots_u": [0, 0, 0.5, 1, 1]}, ValueError,
         "degree[1]: missing: give degree or order (or knots_v)"),
        (nurbs_surface, {"order": (2, 0), "degree": None}, ValueError, "order[1]: 0 is outside [1, 32]"),
        (nurbs_surface, {"order": 2}, ValueError, "degree, order: give one of them, not both"),
        (nurbs_surface, {"knots_v": [0, 0, 0.7, 0.2, 1]}, ValueError,
         "knots.v[3] = 0.2 is less than knots.v[2] = 0.7"),
        (nurbs_surface, {"knots_v": [0, 0, 0.5, 1]}, ValueError,
         "knots.v: expected 5 values (columns + order in v), got 4"),
        (fuzzy_surface, {"crisp": NET[0]}, ValueError,
         "crisp: expected shape (nu, nv, 2) or (nu, nv, 3)"),
        (fuzzy_surface, {"upper": NET}, ValueError,
         "upper: expected shape (3, 3, 3, 2): [left, right] per coordinate of crisp, got (3, 3, 3)"),
        (fuzzy_surface, {"lower_height": [0.5, 0.6]}, ValueError,
         "lower_height: expected a number or an array that broadcasts to shape (3, 3, 3)"),
        (fuzzy_surface, {"lower": NET[..., None] + np.array([0.1, 0.2])}, ValueError,
         "points[0][0].x: the order lower.left <= crisp is broken: 0.1 > 0"),
        (fuzzy_surface, {"lower_height": np.where(np.arange(3) == 2, 1.5, 0.5)}, ValueError,
         "points[0][0].z: lower_height = 1.5 is outside (0, 1]"),
        (fuzzy_surface, {"weights": [[1, 1, 1], [1, -1, 1], [1, 1, 1]]}, ValueError,
         "weights[1][1] = -1 must be finite and greater than 0"),
        (fuzzy_surface, {"knots_u": [0, 0, 1, 1]}, ValueError,
         "knots.u: expected 5 values (rows + order in u), got 4"),
    ],
)
def test_surface_arguments(make: Callable[..., Any], changes: Dict[str, Any], kind: type, message: str) -> None:
    with pytest.raises(kind) as e:
        make(**changes)
    assert str(e.value).startswith(message), str(e.value)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda s: s.crisp_surface().eval(0.5, 2.0), "parameter v = 2 is outside the domain [0, 1]"),
        (lambda s: s.crisp_surface().eval(np.nan, 0.5), "u = NaN is not a finite number"),
        (lambda s: s.crisp_surface().eval([0.1, 0.2], [0.1, 0.2, 0.3]),
         "u, v: shapes (2,) and (3,) do not broadcast together"),
        (lambda s: s.eval_layers(0.5, [[0.1, 2.0]]), "parameter v = 2 is outside the domain [0, 1]"),
        (lambda s: s.sample(10**6, 10**6), "u, v: a grid of 1000000 × 1000000 parameters would take"),
        (lambda s: s.solve(0.5).sample(10**6, 10**6), "u, v: a grid of 1000000 × 1000000 parameters"),
        (lambda s: s.crisp_surface().sample(-1, 3), "u: a count of uniform parameters must be at least 0"),
        (lambda s: s.sample(3, [[0.5]]), "v: expected a count (int) or a 1-D array of parameters"),
        (lambda s: s.sample([0.5, 1.5], 3), "parameter u = 1.5 is outside the domain [0, 1]"),
        (lambda s: s.uniform_params(3, -2), "count_v: must be at least 0, got -2"),
        (lambda s: s.insert_knot(0.5, direction="w"), "direction: expected 'u' or 'v', got \"w\""),
        (lambda s: s.crisp_surface().insert_knot(0.5, times=3, direction="u"), "in u: cannot insert knot 0.5 3 times"),
        (lambda s: s.insert_knot(1.5, direction="v"), "parameter v = 1.5 is outside the domain [0, 1]"),
        (lambda s: s.elevate_degree(times=0, direction="v"), "times: must be at least 1, got 0"),
        (lambda s: s.split_at(1.0, direction="u"), "cannot split at u = 1: it must lie strictly inside"),
        (lambda s: s.isocurve(-0.1, direction="v"), "parameter v = -0.1 is outside the domain [0, 1]"),
        (lambda s: s.crisp_surface().derivatives(0.5, 0.5, order=65), "derivative order = 65 is outside"),
        (lambda s: s.point(3, 0), "i: 3 is outside [0, 2]"),
        (lambda s: s.point(0, -1), "j: -1 is outside [0, 2]"),
        (lambda s: s.layer_surface("upper"), "layer: expected one of upper_left, "),
        (lambda s: s.solve(0.5).type_reduced_surface("middle"), "side: expected 'left' or 'right'"),
        (lambda s: s.solve(0.5).alpha_cut_surface("crispy"), "layer: expected one of"),
        (lambda s: s.solve(1.5), "alpha = 1.5 is outside [0, 1]"),
        (lambda s: t2spline.NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[0, 0, 0], [0, 1, 0]]], degree=1)
         .normal(0.5, 0.5),
         "the normal at (u, v) = (0.5, 0.5) is undefined: the partial derivatives are parallel or zero"),
    ],
)
def test_surface_method_arguments(call: Callable[[t2spline.FuzzySurface], Any], message: str) -> None:
    with pytest.raises(ValueError) as e:
        call(fuzzy_surface())
    assert str(e.value).startswith(message), str(e.value)


def test_a_fitted_value_beyond_the_limit_is_named_not_called_an_order() -> None:
    # Data near the limit of coordinates (1e150): the cubic interpolant of
    # the crisp values swings to 2.5e150 at control point 1.
    x = np.arange(5) * 1e149
    y = np.array([0.0, 9e149, -9e149, 9e149, 0.0])
    crisp = np.stack([x, y], axis=1)
    spread = np.array([-1e148, 1e148])
    for mode in ("valid", "independent"):
        with pytest.raises(ValueError) as e:
            t2spline.fit(crisp, crisp[..., None] + spread, crisp[..., None] + 0.5 * spread,
                         crisp[..., None] + 0.1 * spread, 0.5, degree=3, mode=mode)
        message = str(e.value)
        assert message.startswith("control point 1, y, layer crisp: the fitted value "), message
        assert "is beyond the limit of coordinates, [-1e150, 1e150]" in message
        assert "order" not in message and "mode=" not in message, message
