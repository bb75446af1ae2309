"""The documentation runs: every example in the docstrings (the extension's,
the package's, the plotting module's), the interactive examples (`>>>`) of
`docs/python.md`, and the notebook-style example in `docs/`."""

from __future__ import annotations

import doctest
import inspect
import os
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

import t2spline  # noqa: E402
import t2spline._t2spline  # noqa: E402
import t2spline.plot  # noqa: E402

from conftest import ROOT  # noqa: E402


@pytest.mark.parametrize(
    "module, least",
    [(t2spline, 40), (t2spline._t2spline, 10), (t2spline.plot, 5)],
    ids=lambda m: getattr(m, "__name__", str(m)),
)
def test_docstring_examples(module: ModuleType, least: int) -> None:
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in finder.find(module, globs=dict(vars(t2spline))):
        runner.run(test)
    failed, attempted = runner.summarize(verbose=False)
    assert failed == 0
    # The examples are there: a finder that found nothing would pass as well.
    assert attempted >= least


def test_the_examples_of_the_python_page(monkeypatch: pytest.MonkeyPatch) -> None:
    """The `>>>` examples of docs/python.md, run from the repository root
    (they read `examples/`)."""
    monkeypatch.chdir(ROOT)
    failed, attempted = doctest.testfile(
        os.fspath(ROOT / "docs" / "python.md"), module_relative=False,
        optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE, report=True,
    )
    assert failed == 0
    assert attempted >= 15


def test_every_public_item_has_a_docstring() -> None:
    checked = 0
    for name in t2spline.__all__:
        item = getattr(t2spline, name)
        if name == "__version__":
            continue
        assert item.__doc__ and len(item.__doc__) > 40, name
        members = vars(item).items() if isinstance(item, type) else []
        for attr, member in members:
            if attr.startswith("_"):
                continue
            if callable(member) or inspect.isdatadescriptor(member):
                assert member.__doc__, f"{name}.{attr}"
                checked += 1
    assert checked >= 70


def test_the_notebook_example_runs(tmp_path: Path) -> None:
    done = subprocess.run(
        [sys.executable, str(ROOT / "docs" / "python-example.py"), str(tmp_path)],
        capture_output=True, text=True,
    )
    assert done.returncode == 0, done.stderr
    assert "max distance 0.0224" in done.stdout
    for figure in ("stages.png", "distance-vs-alpha.png", "number.png"):
        assert (tmp_path / figure).read_bytes()[:4] == b"\x89PNG", figure
