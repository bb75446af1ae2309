"""The console script `t2spline` that the package installs: the command
itself, with the same results as the `t2spline` that cargo builds (PNG
aside: the package's figures are SVG)."""

import json
import os
import subprocess
import sys
from pathlib import Path

from conftest import EXAMPLE


def script() -> Path:
    """The console script beside this interpreter (the virtual
    environment's `bin/`, or `Scripts\\` on Windows)."""
    folder = Path(sys.executable).parent
    for name in ("t2spline", "t2spline.exe"):
        if (folder / name).exists():
            return folder / name
    raise AssertionError(f"no t2spline script in {folder}")


def test_the_script_is_the_command(cli: Path, tmp_path: Path) -> None:
    ours = subprocess.run([str(script()), "--version"], capture_output=True, text=True, check=True)
    theirs = subprocess.run([str(cli), "--version"], capture_output=True, text=True, check=True)
    assert ours.stdout == theirs.stdout
    ran = [
        json.loads(subprocess.run([str(c), "run", str(EXAMPLE), "--samples", "11"], capture_output=True,
                                  text=True, check=True).stdout)
        for c in (script(), cli)
    ]
    assert ran[0] == ran[1]
    # An error: the same lines and exit code.
    bad = tmp_path / "bad.json"
    bad.write_text('{"order": 2, "points": []}')
    errors = [subprocess.run([str(c), "validate", str(bad)], capture_output=True, text=True) for c in (script(), cli)]
    assert errors[0].returncode == errors[1].returncode == 2
    assert errors[0].stderr == errors[1].stderr


def test_the_script_draws_svg_figures(tmp_path: Path) -> None:
    out = tmp_path / "figures"
    env = {**os.environ, "SOURCE_DATE_EPOCH": "0"}
    done = subprocess.run([str(script()), "plot", str(EXAMPLE), "-o", str(out)], capture_output=True,
                          text=True, env=env)
    assert done.returncode == 0, done.stderr
    files = sorted(p.suffix for p in out.iterdir())
    assert files and set(files) == {".svg"}, files
    png = subprocess.run([str(script()), "plot", str(EXAMPLE), "-o", str(tmp_path / "png"), "--format", "png"],
                         capture_output=True, text=True)
    assert png.returncode != 0 and "no PNG support" in png.stderr, png.stderr
