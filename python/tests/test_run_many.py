"""`run_many`: many jobs (dicts, texts, paths) on all cores, each result
equal to `run`'s for that job bit for bit, in the jobs' order; a failing job
becomes its exception with its index, or raises under errors="raise"."""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest

import t2spline
from conftest import EXAMPLE, assert_same, bits, cli_run, random_job
from test_gil import longest_stall


def assert_equal_results(got: Any, want: Any, path: str = "result") -> None:
    """Two results of `run`: the same keys in the same order, arrays equal
    bit for bit, the same scalars."""
    if isinstance(want, dict):
        assert isinstance(got, dict) and list(got) == list(want), path
        for key in want:
            assert_equal_results(got[key], want[key], f"{path}.{key}")
    elif isinstance(want, np.ndarray):
        assert isinstance(got, np.ndarray) and got.shape == want.shape, path
        assert np.array_equal(bits(got), bits(want)), path
    elif isinstance(want, list):
        assert isinstance(got, list) and len(got) == len(want), path
        for k, (g, w) in enumerate(zip(got, want)):
            assert_equal_results(g, w, f"{path}[{k}]")
    else:
        assert type(got) is type(want) and (got == want or got != got), f"{path}: {got!r} != {want!r}"


@pytest.fixture(scope="module")
def jobs() -> List[Dict[str, Any]]:
    rng = np.random.default_rng(2024)
    out: List[Dict[str, Any]] = []
    while len(out) < 40:
        job = random_job(rng)
        try:
            t2spline.run(job)
        except t2spline.JobError:
            continue  # a random repeated knot beyond the order
        out.append(job)
    return out


def test_each_result_is_run_s_in_order(jobs: List[Dict[str, Any]], tmp_path: Path) -> None:
    paths = []
    for k, job in enumerate(jobs[:10]):
        paths.append(tmp_path / f"job{k}.json")
        paths[-1].write_text(json.dumps(job))
    given: List[Any] = list(jobs) + [json.dumps(j, indent=1) for j in jobs[10:20]] + paths
    want = [t2spline.run(j) for j in jobs] + [t2spline.run(j) for j in jobs[10:20]]
    want += [t2spline.run(p) for p in paths]
    got = t2spline.run_many(given)
    assert len(got) == len(want)
    for k, (g, w) in enumerate(zip(got, want)):
        assert_equal_results(g, w, f"jobs[{k}]")
    # A generator is a sequence of jobs too.
    assert len(t2spline.run_many(j for j in jobs[:3])) == 3


def test_the_keywords_apply_to_every_job(jobs: List[Dict[str, Any]]) -> None:
    some = jobs[:8]
    got = t2spline.run_many(some, samples=17, alpha=0.35)
    for g, job in zip(got, some):
        assert_equal_results(g, t2spline.run(job, samples=17, alpha=0.35))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the jobs' alphas, unused by nie-tan
        got = t2spline.run_many(some, derivatives=2, type_reduction="nie-tan")
        for g, job in zip(got, some):
            assert_equal_results(g, t2spline.run(job, derivatives=2, type_reduction="nie-tan"))


def test_the_results_are_the_command_line_tool_s(cli: Path) -> None:
    [result] = t2spline.run_many([EXAMPLE], samples=9, alpha=0.6)
    assert_same(result, cli_run(cli, EXAMPLE, "--samples", "9", "--alpha", "0.6"))


def test_a_failing_job_becomes_its_error_with_its_index(
    jobs: List[Dict[str, Any]], tmp_path: Path
) -> None:
    bad = {"order": 2, "alhpa": 0.5, "points": []}
    nan = json.loads(json.dumps(jobs[1]))
    nan["points"][0]["x"]["crisp"] = float("nan")
    missing = tmp_path / "missing.json"
    given: List[Any] = [jobs[0], bad, nan, missing, 42, '{"order": 2', jobs[2]]
    got = t2spline.run_many(given)
    assert_equal_results(got[0], t2spline.run(jobs[0]))
    assert_equal_results(got[6], t2spline.run(jobs[2]))
    kinds = [t2spline.JobError, t2spline.JobError, FileNotFoundError, TypeError, t2spline.JobError]
    for k, kind in zip(range(1, 6), kinds):
        assert isinstance(got[k], kind), (k, got[k])
        assert got[k].index == k
    # The messages are run's, the dict or text named by its place in the list.
    with pytest.raises(t2spline.JobError) as alone:
        t2spline.run(bad)
    assert got[1].problems == [p.replace("<dict>", "<jobs[1]>") for p in alone.value.problems]
    assert got[1].problems[0] == "<jobs[1]>:3:3: alhpa: unknown key (did you mean `alpha`?)"
    assert got[2].problems[0].startswith("<jobs[2]>:")
    assert "NaN is not a finite number" in got[2].problems[0]
    assert got[3].filename == str(missing)
    assert got[5].problems[0].startswith("<jobs[5]>:1:")


def test_errors_raise_raises_the_first_in_order(jobs: List[Dict[str, Any]]) -> None:
    given: List[Any] = [jobs[0], jobs[1], {"points": []}, 7]
    with pytest.raises(t2spline.JobError) as raised:
        t2spline.run_many(given, errors="raise")
    assert raised.value.index == 2
    assert raised.value.problems[0].startswith("<jobs[2]>:")
    assert len(t2spline.run_many(jobs[:2], errors="raise")) == 2


def test_bad_keywords_are_refused(jobs: List[Dict[str, Any]]) -> None:
    with pytest.raises(ValueError, match="errors: expected 'collect' or 'raise', got 'ignore'"):
        t2spline.run_many(jobs[:1], errors="ignore")
    # A count out of range is each job's setting, refused as run refuses it.
    [refused] = t2spline.run_many(jobs[:1], samples=1)
    assert isinstance(refused, ValueError) and refused.index == 0
    assert str(refused) == "samples: samples = 1: at least 2 are needed (both ends of the domain)"
    with pytest.raises(TypeError, match="alpha"):
        t2spline.run_many(jobs[:1], alpha="high")
    with pytest.raises(TypeError):
        t2spline.run_many(3)
    assert t2spline.run_many([]) == []


def test_an_unused_alpha_is_named_with_its_job() -> None:
    job = json.loads(EXAMPLE.read_text())
    plain = dict(job, type_reduction="centroid")
    with pytest.warns(UserWarning, match=r"^jobs\[1\]: type reduction centroid does not use alpha; the job's alpha 0.8 is ignored"):
        t2spline.run_many([dict(job, type_reduction="paper"), plain])


def test_a_thread_runs_while_many_jobs_run() -> None:
    stall, duration = longest_stall(lambda: t2spline.run_many([EXAMPLE] * 8, samples=200_000))
    assert stall < 0.5 * duration, (stall, duration)
