"""The command-line tool started from Python: a standard output that Python
discards (`subprocess.DEVNULL`, which opens /dev/null read-write) or that a
shell sends to /dev/null (`1<>/dev/null`, `>/dev/null`) is open, so every
command succeeds; only a standard output closed from the start (`>&-`) is
exit 4."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path
from typing import List

import pytest

from conftest import EXAMPLE, ROOT

DATA = ROOT / "examples" / "fit-measurements.json"

pytestmark = pytest.mark.skipif(os.name != "posix", reason="/dev/null and sh")


def commands(out: Path) -> List[List[str]]:
    """One of each kind of command: results, checks, fits, figures, reports."""
    return [
        ["run", str(EXAMPLE)],
        ["validate", str(EXAMPLE)],
        ["fit", "-q", str(DATA)],
        ["plot", str(EXAMPLE), "-o", str(out / "plots"), "--format", "svg"],
        ["report", str(EXAMPLE), "-o", str(out / "report")],
    ]


@pytest.mark.parametrize("k", range(5), ids=["run", "validate", "fit", "plot", "report"])
def test_a_standard_output_discarded_by_python_is_open(cli: Path, tmp_path: Path, k: int) -> None:
    args = commands(tmp_path)[k]
    done = subprocess.run(
        [str(cli), *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True
    )
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""


def sh(cli: Path, redirect: str, args: List[str]) -> subprocess.CompletedProcess[str]:
    """`t2spline ARGS` run by sh with standard output redirected."""
    return subprocess.run(
        ["sh", "-c", f'exec "$0" "$@" {redirect}', str(cli), *args],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )


@pytest.mark.parametrize("redirect", ["1<>/dev/null", ">/dev/null"])
def test_a_standard_output_on_dev_null_is_open(cli: Path, tmp_path: Path, redirect: str) -> None:
    for args in commands(tmp_path):
        done = sh(cli, redirect, args)
        assert done.returncode == 0, (args, done.stderr)
        assert done.stderr == "", args
    assert (tmp_path / "plots" / "stage1-fuzzy.svg").is_file()


def test_only_a_closed_standard_output_is_exit_4(cli: Path, tmp_path: Path) -> None:
    for args in commands(tmp_path)[:3]:
        done = sh(cli, ">&-", args)
        assert done.returncode == 4, (args, done.stderr)
        assert "t2spline: <stdout>: cannot write: standard output is closed" in done.stderr
