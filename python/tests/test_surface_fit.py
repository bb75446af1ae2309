"""Nets in Python by the command's code: `fuzzify` of a net's readings given
as arrays or as a long table, and of a raster array cut into blocks, gives
the data file `t2spline fuzzify` writes for the same readings as a file, bit
for bit; `fit` of a net of fuzzy data points gives a `FuzzySurface`;
`fit_job` gives the job `t2spline fit` writes; bad arguments are named."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest

import t2spline
from conftest import ROOT

READINGS = ROOT / "examples" / "beach-readings.csv"


def cli_json(cli: Path, *args: str) -> Any:
    done = subprocess.run([str(cli), *args], capture_output=True, check=True, text=True)
    return json.loads(done.stdout)


def net_readings(rows: int = 4, cols: int = 5, count: int = 6, seed: int = 7) -> np.ndarray:
    """Readings `(rows, cols, count, 3)` of a gently curved net, some missing."""
    rng = np.random.default_rng(seed)
    i, j = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
    station = np.stack([10.0 * j, 8.0 * i, np.sin(i) + 0.3 * j], axis=-1)
    readings = station[:, :, None, :] + rng.normal(0.0, [0.02, 0.02, 0.05], (rows, cols, count, 3))
    readings = np.round(readings, 4)   # as a survey records them
    readings[0, 1, 2, 1] = np.nan       # one coordinate missing: the reading is left out
    readings[-1, -2, 0, :] = np.nan
    return readings


def long_table(readings: np.ndarray, seed: int = 3) -> Dict[str, List[Any]]:
    """The readings as a long table, stations interleaved as a log in time
    order has them (each station's readings keep their order), NaN readings
    left in."""
    rows, cols, count, _ = readings.shape
    order = [(i, j, k) for k in range(count) for i in range(rows) for j in range(cols)]
    rng = np.random.default_rng(seed)
    # Shuffle stations within each round of readings: per station the order holds.
    table: Dict[str, List[Any]] = {"row": [], "col": [], "x": [], "y": [], "z": []}
    for k in range(count):
        stations = [(i, j) for i in range(rows) for j in range(cols)]
        for s in rng.permutation(len(stations)):
            i, j = stations[s]
            table["row"].append(i)
            table["col"].append(j)
            for axis, name in enumerate("xyz"):
                table[name].append(float(readings[i, j, k, axis]))
    assert len(table["row"]) == len(order)
    return table


def write_csv(path: Path, table: Dict[str, List[Any]]) -> None:
    lines = ["row,col,x,y,z"]
    for i, j, x, y, z in zip(*(table[c] for c in ["row", "col", "x", "y", "z"])):
        if not any(np.isnan([x, y, z])):
            lines.append(f"{i},{j},{x!r},{y!r},{z!r}")
    path.write_text("\n".join(lines) + "\n")


def same_data(got: Dict[str, Any], want: Dict[str, Any], source: str, name: str) -> None:
    """The command's data file with its file name in the description read as
    `name` (how Python names arrays, tables, rasters); every number equal."""
    want = dict(want)
    want["description"] = want["description"].replace(source, name, 1)
    assert list(got) == list(want)
    assert got == want


@pytest.mark.parametrize(
    "options, flags",
    [
        ({}, []),
        ({"degree": (2, 1), "tolerance": 0.01, "alpha": 0.4}, ["--degree", "2,1", "--tolerance", "0.01", "--alpha", "0.4"]),
        ({"order": 3, "lower_height": 0.6}, ["--order", "3", "--lower-height", "0.6"]),
    ],
)
def test_a_net_from_arrays_and_tables_is_the_command_on_the_csv(
    cli: Path, tmp_path: Path, options: Dict[str, Any], flags: List[str]
) -> None:
    readings = net_readings()
    table = long_table(readings)
    csv = tmp_path / "net.csv"
    write_csv(csv, table)
    want = cli_json(cli, "fuzzify", str(csv), *flags)
    same_data(t2spline.fuzzify(readings, **options), want, str(csv), "<array>")
    same_data(t2spline.fuzzify(table, **options), want, str(csv), "<table>")
    # The readings file itself, through the same function.
    assert t2spline.fuzzify(csv, **options) == want
    assert np.array(want.get("degree", want.get("order"))).shape == (2,)
    assert len(want["points"]) == 4 and all(len(row) == 5 for row in want["points"])


def test_a_net_from_pandas_and_pyarrow_tables(cli: Path, tmp_path: Path) -> None:
    readings = net_readings(3, 4, 5, seed=11)
    table = long_table(readings)
    csv = tmp_path / "net.csv"
    write_csv(csv, table)
    want = cli_json(cli, "fuzzify", str(csv), "--degree", "2")
    pd = pytest.importorskip("pandas")
    same_data(t2spline.fuzzify(pd.DataFrame(table), degree=2), want, str(csv), "<table>")
    pa = pytest.importorskip("pyarrow")
    same_data(t2spline.fuzzify(pa.table(table), degree=2), want, str(csv), "<table>")


@pytest.mark.parametrize("shape, block", [((12, 15), 3), ((13, 11), 2)])
def test_a_raster_array_is_the_command_on_the_npy(cli: Path, tmp_path: Path, shape: Any, block: int) -> None:
    rng = np.random.default_rng(5)
    y, x = np.mgrid[0 : shape[0], 0 : shape[1]]
    raster = 100.0 + 0.5 * x - 0.25 * y + rng.normal(0.0, 0.1, shape)
    raster[1, 2] = np.nan
    raster[4, 0] = np.nan
    npy = tmp_path / "dem.npy"
    np.save(npy, raster)
    origin, spacing = (500000.5, 4200000.25), (1.0, -1.0)
    want = cli_json(
        cli, "fuzzify", str(npy), "--block", str(block), "--degree", "2",
        "--origin", ",".join(map(repr, origin)), "--spacing", ",".join(map(repr, spacing)),
    )
    kwargs: Dict[str, Any] = {"block": block, "origin": origin, "spacing": spacing, "degree": 2}
    left_out = shape[0] % block or shape[1] % block
    if left_out:
        with pytest.warns(UserWarning, match="fill no whole block"):
            got = t2spline.fuzzify(raster, **kwargs)
    else:
        got = t2spline.fuzzify(raster, **kwargs)
    same_data(got, want, str(npy), "<raster>")
    # The .npy file through Python too, and float32 arrays as numpy widens them.
    if left_out:
        with pytest.warns(UserWarning):
            assert t2spline.fuzzify(npy, **kwargs) == want
    else:
        assert t2spline.fuzzify(npy, **kwargs) == want


def fuzzy_net(rows: int = 6, cols: int = 5) -> Dict[str, Any]:
    u, v = np.meshgrid(np.linspace(0.0, 1.0, rows), np.linspace(0.0, 1.0, cols), indexing="ij")
    crisp = np.stack([4.0 * u, 3.0 * v, np.sin(2.0 * u) * np.cos(v)], axis=-1)
    s = np.array([-0.2, 0.25])
    wobble = 1.0 + 0.3 * np.sin(7.0 * u + 3.0 * v)[..., None, None]
    return {
        "crisp": crisp,
        "upper": crisp[..., None] + s * wobble,
        "primary": crisp[..., None] + 0.6 * s * wobble,
        "lower": crisp[..., None] + 0.3 * s,
        "lower_height": 0.5,
    }


def test_fit_of_a_net_interpolates_the_crisp_net() -> None:
    net = fuzzy_net()
    surface, summary = t2spline.fit(**net, degree=(3, 2))
    assert isinstance(surface, t2spline.FuzzySurface)
    assert surface.crisp.shape == (6, 5, 3)
    assert summary["net"] == {"data": [6, 5], "control": [6, 5]}
    assert summary["data_points"] == 30 and summary["mode"] == "valid"
    assert summary["deviations"]["crisp"]["max"] < 1e-9
    # The surface passes through the crisp data, at some parameters: every data
    # point is on the crisp surface.
    crisp = surface.crisp_surface()
    for point in net["crisp"].reshape(-1, 3)[::7]:
        _, _, _, distance = crisp.closest_point(point)
        assert distance < 1e-8


def test_fit_of_a_net_by_least_squares() -> None:
    net = fuzzy_net(8, 7)
    surface, summary = t2spline.fit(**net, degree=2, control_points=(5, 4), parametrization="centripetal")
    assert surface.crisp.shape == (5, 4, 3)
    assert summary["net"] == {"data": [8, 7], "control": [5, 4]}
    assert summary["control_points"] == 20
    assert 0.0 < summary["deviations"]["crisp"]["max"] < 0.1
    _, one = t2spline.fit(**net, degree=2, control_points=4)
    assert one["net"] == {"data": [8, 7], "control": [4, 4]}


def test_fit_of_a_net_names_bad_arguments() -> None:
    net = fuzzy_net()
    with pytest.raises(ValueError, match=r"^control_points\[1\]: 6 is outside \[3, 5\]"):
        t2spline.fit(**net, degree=2, control_points=(4, 6))
    with pytest.raises(ValueError, match=r"^control_points: 2 is outside \[3, 6\]"):
        t2spline.fit(**net, degree=2, control_points=2)
    with pytest.raises(ValueError, match=r"^degree\[1\]: 5 along v is outside \[1, 4\]"):
        t2spline.fit(**net, degree=(2, 5))
    with pytest.raises(ValueError, match=r"^degree: 0 along u is outside \[1, 5\]"):
        t2spline.fit(**net, degree=0)
    with pytest.raises(TypeError, match=r"^degree: expected an int or a pair"):
        t2spline.fit(**net, degree="2")  # type: ignore[call-overload]
    with pytest.raises(ValueError, match=r"^upper: expected shape \(6, 5, 3, 2\)"):
        t2spline.fit(**{**net, "upper": net["upper"][:, :4]}, degree=2)
    flat = {k: (v[..., :2, :] if k in ("upper", "primary", "lower") else v) for k, v in net.items()}
    flat["crisp"] = net["crisp"][..., :2]
    with pytest.raises(ValueError, match=r"^crisp: a net of data points needs x, y and z"):
        t2spline.fit(**flat, degree=2)
    curve = {k: (v[0] if isinstance(v, np.ndarray) else v) for k, v in net.items()}
    with pytest.raises(ValueError, match=r"^degree: a pair \(p, q\) is for a net"):
        t2spline.fit(**curve, degree=(2, 2))
    with pytest.raises(ValueError, match=r"^control_points: a pair \(nu, nv\) is for a net"):
        t2spline.fit(**curve, degree=2, control_points=(3, 3))


@pytest.mark.parametrize(
    "options, flags",
    [
        ({}, []),
        ({"control_points": (3, 4), "parametrization": "uniform"}, ["--control-points", "3,4", "--parametrization", "uniform"]),
        ({"control_points": 3, "mode": "valid", "alpha": 0.3}, ["--control-points", "3", "--fuzzy-fit", "valid", "--alpha", "0.3"]),
    ],
)
def test_fit_job_is_the_job_the_command_writes_for_a_net(
    cli: Path, tmp_path: Path, options: Dict[str, Any], flags: List[str]
) -> None:
    data = t2spline.fuzzify(net_readings(), degree=(2, 1))
    path = tmp_path / "data.json"
    path.write_text(json.dumps(data))
    want = cli_json(cli, "fit", str(path), "-q", *flags)
    assert t2spline.fit_job(data, **options) == want
    assert t2spline.fit_job(path, **options) == want
    # The job runs, as a surface.
    result = t2spline.run(want, alpha=0.5, samples=5)
    assert result["surfaces"]["crisp"].shape == (5, 5, 3)


def test_fit_job_of_a_curve_and_its_errors(cli: Path, tmp_path: Path) -> None:
    data = t2spline.fuzzify(READINGS, tolerance=0.02, alpha=0.5)
    path = tmp_path / "data.json"
    path.write_text(json.dumps(data))
    cases: List[Any] = [
        ({}, []),
        ({"control_points": 8, "parametrization": "centripetal"}, ["--control-points", "8", "--parametrization", "centripetal"]),
    ]
    for options, flags in cases:
        assert t2spline.fit_job(data, **options) == cli_json(cli, "fit", str(path), "-q", *flags)
    with pytest.raises(ValueError, match=r"^control_points: 20 is outside \[4, 13\]"):
        t2spline.fit_job(data, control_points=20)
    with pytest.raises(ValueError, match=r"^control_points: a pair"):
        t2spline.fit_job(data, control_points=(5, 5))
    with pytest.raises(ValueError, match=r"^parametrization: "):
        t2spline.fit_job(data, parametrization="chords")  # type: ignore[arg-type]
    with pytest.raises(t2spline.JobError, match=r"^<dict>:\d+:\d+: "):
        t2spline.fit_job({**data, "degree": 0})
    with pytest.raises(t2spline.JobError, match="breaks the order of the seven values"):
        t2spline.fit_job(data, mode="independent")
    with pytest.raises(TypeError, match=r"^data: expected a dict"):
        t2spline.fit_job([1, 2])  # type: ignore[arg-type]


def test_fuzzify_names_bad_readings() -> None:
    readings = net_readings(3, 3, 4)
    with pytest.raises(ValueError, match=r"^readings: expected shape \(rows, cols, readings, 3\)"):
        t2spline.fuzzify(readings[..., :2])
    with pytest.raises(ValueError, match=r"^readings\[0, 0, 1, 2\] = inf is not a finite number"):
        t2spline.fuzzify(np.where(np.arange(36).reshape(3, 3, 4, 1) * 3 + np.arange(3) == 5, np.inf, readings))
    few = readings.copy()
    few[1, 2, 1:] = np.nan
    with pytest.raises(t2spline.JobError, match=r"station \(1, 2\)"):
        t2spline.fuzzify(few, degree=1)
    with pytest.raises(ValueError, match=r"^degree: <array>: a net of 3 × 3 stations has 3 row\(s\), but degree 3"):
        t2spline.fuzzify(readings)
    with pytest.raises(ValueError, match=r"^block: only for a raster"):
        t2spline.fuzzify(readings, block=2, degree=1)
    table = long_table(readings)
    with pytest.raises(ValueError, match=r"^readings: the table has no column `z`"):
        t2spline.fuzzify({k: v for k, v in table.items() if k != "z"})
    gap = {k: [x for x, i, j in zip(v, table["row"], table["col"]) if (i, j) != (1, 1)] for k, v in table.items()}
    with pytest.raises(ValueError, match=r"^readings: station \(1, 1\): missing"):
        t2spline.fuzzify(gap, degree=1)
    with pytest.raises(ValueError, match=r"^readings\[\"row\"\]\[0\] = -1 is not a whole number from 0"):
        t2spline.fuzzify({**table, "row": [-1] + table["row"][1:]}, degree=1)
    with pytest.raises(ValueError, match=r"^readings\[\"col\"\]\[1\] = 0.5 is not a whole number from 0"):
        t2spline.fuzzify({**table, "col": [0, 0.5] + table["col"][2:]}, degree=1)
    raster = np.ones((6, 6))
    with pytest.raises(ValueError, match=r"^block: a 2-D array of shape \(6, 6\) is a raster"):
        t2spline.fuzzify(raster)
    with pytest.raises(ValueError, match=r"^block: 1: a block of K × K cells needs K of at least 2"):
        t2spline.fuzzify(raster, block=1)
    with pytest.raises(ValueError, match=r"^origin: a raster given as an array"):
        t2spline.fuzzify(raster, block=2, spacing=(1, 1))
    with pytest.raises(ValueError, match=r"^spacing: the steps dx and dy must not be 0"):
        t2spline.fuzzify(raster, block=2, origin=(0, 0), spacing=(1, 0))
    with pytest.raises(TypeError, match=r"^origin: expected a pair"):
        t2spline.fuzzify(raster, block=2, origin=0, spacing=(1, 1))  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^origin, spacing: only for a raster given as an array or a \.npy file"):
        t2spline.fuzzify(READINGS, origin=(0, 0))
    with pytest.raises(ValueError, match=r"^degree: a pair P,Q is for a net"):
        t2spline.fuzzify(READINGS, degree=(2, 2))
    with pytest.raises(TypeError, match=r"^readings: expected the path"):
        t2spline.fuzzify(object())
