"""Curves with fuzzy weights from the command line (docs/method.md §16,
docs/jobs.md "Fuzzy weights"), checked against independent implementations:
the solution curve against scipy's B-splines through the stage-4 points and
weights; the exact envelope against PyIT2FLS's Karnik–Mendel algorithm at
every sample parameter; the memberships of random points against scipy's
linear-programming solver (`linprog`) on the feasibility problem in the
weights at a grid of parameters."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any, Dict, Tuple

import numpy as np
import pytest
from scipy.interpolate import BSpline
from scipy.optimize import linprog

from conftest import ROOT, cli_run

JOB = ROOT / "examples" / "fuzzy-weights.json"
AXES = ("x", "y")
# (left, right) feet of each membership function in a job's number.
FEET = {"upper": "upper", "primary": "primary", "lower": "lower"}


def job() -> Dict[str, Any]:
    data: Dict[str, Any] = json.loads(JOB.read_text())
    return data


def number(value: Any, height: float) -> Dict[str, Any]:
    """A number of the job as a dict with every key (a bare number is crisp)."""
    if isinstance(value, (int, float)):
        v = float(value)
        return {"crisp": v, "upper": [v, v], "primary": [v, v], "lower": [v, v], "lower_height": height}
    out = dict(value)
    out.setdefault("lower_height", height)
    return out


def cut(n: Dict[str, Any], function: str, alpha: float) -> Tuple[float, float] | None:
    """The cut of a number under a membership function at alpha
    (docs/method.md §2): `e + s·(crisp − e)`, `s = alpha`, or `alpha/h` for
    the lower function, which has no cut above its height."""
    c = n["crisp"]
    left, right = n[FEET[function]]
    s = alpha
    if function == "lower":
        if alpha > n["lower_height"]:
            return None
        s = alpha / n["lower_height"]
    return (left + s * (c - left), right + s * (c - right))


def knots(result: Dict[str, Any]) -> np.ndarray:
    return np.asarray(result["knots"], dtype=float)


def basis(result: Dict[str, Any], t: float) -> np.ndarray:
    """Every B-spline basis function of the job at t (scipy)."""
    u, p = knots(result), result["degree"]
    n = len(u) - p - 1
    return np.array([BSpline(u, np.eye(n)[i], p, extrapolate=False)(t) for i in range(n)]).clip(min=0.0)


@pytest.fixture(scope="module")
def result(cli: Path) -> Dict[str, Any]:
    return cli_run(cli, JOB)


def test_the_solution_is_the_rational_spline_of_the_stage_4_points_and_weights(
    cli: Path, result: Dict[str, Any]
) -> None:
    stages = result["weight_stages"]
    assert result["weights"] == stages["crisp"] == [1.0, 1.0, 3.0, 1.0]
    assert stages["layers"]["upper_left"][2] == 2.0 and stages["layers"]["upper_right"][2] == 4.5
    # The third weight is cut, reduced and defuzzified as a coordinate with
    # the same number is: put that number into a point's x and compare.
    j = job()
    j["points"][0]["x"] = j["weights"][2]
    j["weights"] = [1, 1, 3, 1]
    done = subprocess.run(
        [str(cli), "run", "-"], input=json.dumps(j), capture_output=True, text=True, check=True
    )
    twin_result = json.loads(done.stdout)["control_points"]
    assert stages["defuzzified"][2] == twin_result["defuzzified"][0][0]
    assert stages["type_reduced_left"][2] == twin_result["type_reduced_left"][0][0]
    assert stages["alpha_cut"]["upper_right"][2] == twin_result["alpha_cut"]["upper_right"][0][0]
    # The sampled solution: Σ wᵢNᵢPᵢ / Σ wᵢNᵢ with scipy's B-splines.
    u, p = knots(result), result["degree"]
    w = np.asarray(stages["defuzzified"])
    pts = np.asarray(result["control_points"]["defuzzified"])
    t = np.asarray(result["curves"]["params"])
    den = BSpline(u, w, p)(t)
    num = BSpline(u, pts * w[:, None], p)(t)
    np.testing.assert_allclose(np.asarray(result["curves"]["defuzzified"]), num / den[:, None], rtol=0, atol=1e-12)


def test_the_envelope_is_pyit2fls_karnik_mendel_at_every_parameter(result: Dict[str, Any]) -> None:
    pyit2fls = pytest.importorskip("pyit2fls")
    j = job()
    h = j["lower_height"]
    alpha = result["alpha"]
    weights = [number(w, h) for w in j["weights"]]
    envelope = result["curves"]["envelope"]
    assert envelope["lower"] is None  # alpha 0.8 is above every lower height 0.6
    for function in ("upper", "primary"):
        left = np.asarray(envelope[function]["left"])
        right = np.asarray(envelope[function]["right"])
        for i, t in enumerate(result["curves"]["params"]):
            n = basis(result, t)
            active = [k for k in range(len(n)) if n[k] > 0.0]
            for a, axis in enumerate(AXES):
                rows = []
                for k in active:
                    lo, hi = cut(number(j["points"][k][axis], h), function, alpha)  # type: ignore[misc]
                    w_lo, w_hi = cut(weights[k], function, alpha)  # type: ignore[misc]
                    rows.append([lo, hi, w_lo * n[k], w_hi * n[k]])
                l, r = pyit2fls.KM_algorithm(np.asarray(rows))
                scale = max(1.0, abs(l), abs(r))
                assert abs(left[i][a] - l) <= 1e-12 * scale, (function, t, axis, left[i][a], l)
                assert abs(right[i][a] - r) <= 1e-12 * scale, (function, t, axis, right[i][a], r)


def feasible(j: Dict[str, Any], t_basis: np.ndarray, q: np.ndarray, function: str, alpha: float) -> bool:
    """Whether weights and points inside their cuts place the curve at q at
    the parameter of the basis values (the linear feasibility problem in the
    weights of docs/method.md §15), by scipy's `linprog`."""
    h = j["lower_height"]
    active = [k for k in range(len(t_basis)) if t_basis[k] > 0.0]
    bounds, rows_lo, rows_hi = [], [], []
    for k in active:
        wc = cut(number(j["weights"][k], h), function, alpha)
        pc = [cut(number(j["points"][k][axis], h), function, alpha) for axis in AXES]
        if wc is None or any(c is None for c in pc):
            return False
        bounds.append(wc)
        rows_lo.append([t_basis[k] * (c[0] - qa) for c, qa in zip(pc, q)])  # type: ignore[index]
        rows_hi.append([t_basis[k] * (c[1] - qa) for c, qa in zip(pc, q)])  # type: ignore[index]
    lo, hi = np.asarray(rows_lo).T, np.asarray(rows_hi).T
    # Σ wᵢNᵢ(P̲ᵢ − q) ≤ 0 and −Σ wᵢNᵢ(P̄ᵢ − q) ≤ 0 for each coordinate.
    a_ub = np.vstack([lo, -hi])
    res = linprog(np.zeros(len(active)), A_ub=a_ub, b_ub=np.zeros(len(a_ub)), bounds=bounds, method="highs")
    assert res.status in (0, 2), res.message
    return bool(res.status == 0)


def test_memberships_agree_with_linear_programming(cli: Path, tmp_path: Path, result: Dict[str, Any]) -> None:
    rng = np.random.default_rng(3)
    queries = np.column_stack([rng.uniform(1.0, 6.0, 16), rng.uniform(1.0, 4.8, 16)])
    csv = tmp_path / "q.csv"
    csv.write_text("x,y\n" + "".join(f"{float(x)!r},{float(y)!r}\n" for x, y in queries))
    done = subprocess.run([str(cli), "membership", str(JOB), str(csv)], capture_output=True, text=True, check=True)
    lines = done.stdout.strip().splitlines()
    assert lines[0] == "x,y,upper,primary,lower"
    grades = np.asarray([[float(v) for v in line.split(",")[2:]] for line in lines[1:]])
    j = job()
    grid = np.linspace(0.0, 1.0, 201)
    bases = [basis(result, t) for t in grid]
    # The crisp curve on a fine grid: near the crisp curve a grade peaks
    # sharply in t, close to the parameter of the nearest crisp point.
    fine = np.linspace(0.0, 1.0, 20001)
    u, p, w = knots(result), result["degree"], np.asarray(result["weights"])
    crisp = np.asarray(result["control_points"]["crisp"])
    curve = BSpline(u, crisp * w[:, None], p)(fine) / BSpline(u, w, p)(fine)[:, None]
    checked = 0
    for q, (upper, primary, _) in zip(queries, grades):
        near = fine[np.argmin(np.hypot(*(curve - q).T))]
        local = [basis(result, t) for t in np.linspace(max(near - 0.01, 0.0), min(near + 0.01, 1.0), 201)]
        for function, g in (("upper", upper), ("primary", primary)):
            # Above the grade: no parameter reaches q.
            if g < 0.98:
                assert not any(feasible(j, n, q, function, g + 0.01) for n in bases + local), (q, function, g)
                checked += 1
            # Below it: some parameter does.
            if g > 0.05:
                assert any(feasible(j, n, q, function, g - 0.02) for n in local + bases), (q, function, g)
                checked += 1
    assert checked >= 16
