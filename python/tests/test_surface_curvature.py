"""`NurbsSurface.curvature` and `FuzzySurface.curvatures`: closed forms (a
sphere octant, a quarter cylinder), the frame of principal directions,
numpy broadcasting and the shapes of every array, errors, and a cross-check
against the fundamental forms computed in numpy from central differences of
`eval` (independent of the Rust derivatives)."""

from __future__ import annotations

from typing import Tuple

import numpy as np
import pytest

import t2spline
from t2spline.types import SurfaceCurvature

W = np.sqrt(0.5)


def sphere_octant(r: float) -> t2spline.NurbsSurface:
    """The quarter circle from (r, 0, 0) to the pole (0, 0, r) in u, revolved
    a quarter turn about z in v; the row u = 1 is the pole."""
    meridian = [(r, 0.0, 1.0), (r, r, W), (0.0, r, 1.0)]
    turn = [(1.0, 0.0, 1.0), (1.0, 1.0, W), (0.0, 1.0, 1.0)]
    net = [[[x * c, x * s, z] for c, s, _ in turn] for x, z, _ in meridian]
    weights = [[a * b for _, _, b in turn] for _, _, a in meridian]
    return t2spline.NurbsSurface(net, weights, degree=2)


def quarter_cylinder(r: float) -> t2spline.NurbsSurface:
    net = [[[r, 0, 0], [r, 0, 3]], [[r, r, 0], [r, r, 3]], [[0, r, 0], [0, r, 3]]]
    return t2spline.NurbsSurface(net, [[1, 1], [W, W], [1, 1]], degree=(2, 1))


def assert_frame(c: SurfaceCurvature, n: np.ndarray, tol: float) -> None:
    """Unit, orthogonal, tangent directions, (e1, e2, n) right-handed."""
    e1, e2 = c["directions"][..., 0, :], c["directions"][..., 1, :]
    np.testing.assert_allclose(np.linalg.norm(e1, axis=-1), 1.0, rtol=0, atol=tol)
    np.testing.assert_allclose(np.linalg.norm(e2, axis=-1), 1.0, rtol=0, atol=tol)
    for x in ((e1 * e2).sum(-1), (e1 * n).sum(-1), (e2 * n).sum(-1)):
        np.testing.assert_allclose(x, 0.0, rtol=0, atol=tol)
    np.testing.assert_allclose(np.cross(e1, e2), n, rtol=0, atol=tol)


@pytest.mark.parametrize("r", [1.0, 0.3, 25.0])
def test_a_sphere_has_k_one_over_r_squared_everywhere(r: float) -> None:
    s = sphere_octant(r)
    u = np.linspace(0, 0.9, 10)[:, None]
    v = np.linspace(0, 1, 7)[None, :]
    c = s.curvature(u, v)
    n = s.normal(u, v)
    # The normal points inward here: the sphere bends toward it, H = +1/r.
    np.testing.assert_allclose((n * s.eval(u, v)).sum(-1), -r, rtol=1e-14)
    np.testing.assert_allclose(c["gaussian"], 1 / r**2, rtol=1e-13)
    np.testing.assert_allclose(c["mean"], 1 / r, rtol=1e-13)
    np.testing.assert_allclose(c["principal"], 1 / r, rtol=1e-13)
    assert_frame(c, n, 1e-14)
    # Umbilic everywhere: e1 is S_u normalised.
    su = s.derivatives(u, v)[..., 1, 0, :]
    np.testing.assert_allclose(c["directions"][..., 0, :],
                               su / np.linalg.norm(su, axis=-1, keepdims=True), rtol=0, atol=1e-14)


@pytest.mark.parametrize("r", [2.0, 0.5])
def test_a_cylinder_bends_only_around_its_axis(r: float) -> None:
    s = quarter_cylinder(r)
    u, v = np.linspace(0, 1, 9), np.linspace(0, 1, 9)[::-1]
    c = s.curvature(u, v)
    np.testing.assert_allclose(c["gaussian"], 0.0, rtol=0, atol=1e-14 / r**2)
    np.testing.assert_allclose(c["mean"], -1 / (2 * r), rtol=1e-14)
    np.testing.assert_allclose(c["principal"][:, 0], 0.0, rtol=0, atol=1e-14 / r)
    np.testing.assert_allclose(c["principal"][:, 1], -1 / r, rtol=1e-14)
    # Zero curvature along the axis z.
    np.testing.assert_allclose(c["directions"][:, 0], [[0, 0, 1]] * 9, rtol=0, atol=1e-14)
    assert_frame(c, s.normal(u, v), 1e-14)


def test_shapes_follow_numpy_broadcasting() -> None:
    s = sphere_octant(1.0)
    one = s.curvature(0.3, 0.4)
    assert set(one) == {"gaussian", "mean", "principal", "directions"}
    assert one["gaussian"].shape == () and one["mean"].shape == ()
    assert one["principal"].shape == (2,) and one["directions"].shape == (2, 3)
    assert all(a.dtype == np.float64 for a in one.values())
    grid = s.curvature(np.linspace(0, 0.5, 3)[:, None], np.linspace(0, 1, 4))
    assert grid["gaussian"].shape == (3, 4) and grid["principal"].shape == (3, 4, 2)
    assert grid["directions"].shape == (3, 4, 2, 3)
    assert float(grid["mean"][1, 2]) == float(s.curvature(0.25, 2 / 3)["mean"])
    empty = s.curvature(np.zeros((0, 2)), 0.5)
    assert empty["directions"].shape == (0, 2, 2, 3)
    with pytest.raises(ValueError, match="do not broadcast"):
        s.curvature([0.1, 0.2, 0.3], [0.1, 0.2])


def test_errors_name_the_parameter_the_singular_normal_and_the_plane() -> None:
    s = sphere_octant(1.0)
    with pytest.raises(ValueError, match="parameter u = 1.5 is outside the domain"):
        s.curvature(1.5, 0.5)
    with pytest.raises(ValueError, match=r"the normal at \(u, v\) = \(1, 0.5\) is undefined"):
        s.curvature([0.5, 1.0], 0.5)  # the pole
    planar = t2spline.NurbsSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]], degree=1)
    with pytest.raises(ValueError, match="^curvature: a surface in the plane has none"):
        planar.curvature(0.5, 0.5)


def fuzzy_sphere() -> t2spline.FuzzySurface:
    """The sphere octant of radius 2 with every coordinate c fuzzy: feet
    0.9c … 1.3c (upper), 0.95c … 1.2c (primary), 0.98c … 1.1c (lower)."""
    crisp = sphere_octant(2.0).control_points

    def feet(a: float, b: float) -> np.ndarray:
        return np.stack([a * crisp, b * crisp], axis=-1)

    return t2spline.FuzzySurface(crisp, feet(0.9, 1.3), feet(0.95, 1.2), feet(0.98, 1.1),
                                 lower_height=0.6, weights=sphere_octant(2.0).weights, degree=2)


def test_a_fuzzy_surface_gives_each_layers_curvature() -> None:
    s = fuzzy_sphere()
    u, v = np.array([[0.1], [0.5]]), np.array([0.0, 0.3, 1.0])
    c = s.curvatures(u, v)
    assert c["gaussian"].shape == (2, 3, 7) and c["principal"].shape == (2, 3, 7, 2)
    assert c["directions"].shape == (2, 3, 7, 2, 3)
    layers = ["upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right",
              "upper_right"]
    scales = [0.9, 0.95, 0.98, 1.0, 1.1, 1.2, 1.3]
    for k, (name, f) in enumerate(zip(layers, scales)):
        own = s.layer_surface(name).curvature(u, v)
        for key in own:
            assert np.array_equal(c[key][:, :, k], own[key]), (name, key)
        np.testing.assert_allclose(c["mean"][:, :, k], 1 / (2 * f), rtol=1e-13)
    with pytest.raises(ValueError, match="^layer upper_left: the normal at"):
        s.curvatures(1.0, 0.5)


def fundamental_forms_by_differences(s: t2spline.NurbsSurface, u: float, v: float,
                                     h: float) -> Tuple[np.ndarray, ...]:
    """K, H, (k1, k2) and the principal directions from central differences
    of `eval` with step h and the classical formulas (do Carmo §3-3), the
    directions from numpy's eigenvectors of the Weingarten matrix I⁻¹·II."""
    def p(a: int, b: int) -> np.ndarray:
        return s.eval(u + a * h, v + b * h)

    su = (p(1, 0) - p(-1, 0)) / (2 * h)
    sv = (p(0, 1) - p(0, -1)) / (2 * h)
    suu = (p(1, 0) - 2 * p(0, 0) + p(-1, 0)) / h**2
    svv = (p(0, 1) - 2 * p(0, 0) + p(0, -1)) / h**2
    suv = (p(1, 1) - p(1, -1) - p(-1, 1) + p(-1, -1)) / (4 * h * h)
    n = np.cross(su, sv)
    n /= np.linalg.norm(n)
    first = np.array([[su @ su, su @ sv], [su @ sv, sv @ sv]])
    second = np.array([[suu @ n, suv @ n], [suv @ n, svv @ n]])
    k = np.linalg.det(second) / np.linalg.det(first)
    values, vectors = np.linalg.eig(np.linalg.solve(first, second))
    order = np.argsort(values)[::-1]
    directions = np.array([vectors[0, i] * su + vectors[1, i] * sv for i in order])
    directions /= np.linalg.norm(directions, axis=-1, keepdims=True)
    return np.array(k), np.array(values.sum() / 2), values[order], directions


def test_curvature_matches_central_differences_of_eval() -> None:
    """Random rational bicubic patches (a wavy graph over the unit grid,
    weights 0.3–3) at interior points. With h = 1e-4 the differences are
    accurate to about h² (truncation) + 1e-16·|S|/h² (rounding), some 1e-7
    relative to the curvature: compared to 1e-5 of the largest principal
    curvature (K to 1e-5 of its square); a direction only where k1 − k2 is at
    least a tenth of that scale, to an angle of 1e-5 (its sine)."""
    rng = np.random.default_rng(7)
    compared = 0
    for _ in range(12):
        grid = np.stack(np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij"), axis=-1)
        net = np.concatenate([grid + rng.uniform(-0.4, 0.4, (4, 4, 2)), rng.uniform(-2, 2, (4, 4, 1))], -1)
        s = t2spline.NurbsSurface(net, rng.uniform(0.3, 3.0, (4, 4)), degree=3)
        for u, v in rng.uniform(0.05, 0.95, (6, 2)):
            c = s.curvature(u, v)
            k, h, principal, directions = fundamental_forms_by_differences(s, u, v, 1e-4)
            scale = max(float(np.abs(c["principal"]).max()), 1e-3)
            assert abs(float(c["gaussian"]) - k) <= 1e-5 * scale**2
            assert abs(float(c["mean"]) - h) <= 1e-5 * scale
            np.testing.assert_allclose(c["principal"], principal, rtol=0, atol=1e-5 * scale)
            if c["principal"][0] - c["principal"][1] >= 0.1 * scale:
                sine = np.linalg.norm(np.cross(c["directions"], directions), axis=-1)
                assert sine.max() <= 1e-5, sine
                compared += 1
    assert compared >= 40
