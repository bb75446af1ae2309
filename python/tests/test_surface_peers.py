"""`NurbsSurface` and `FuzzySurface` against two independent implementations
on random rational surfaces: geomdl 5.4.0 (NURBS-Python, The NURBS Book's
algorithms in pure Python) and splipy (SINTEF's spline library, tensor
products on projective control points `(w·P, w)`). Evaluation (both peers,
`eval` and the grid engine), partial derivatives and normals (geomdl),
the curvature against the fundamental forms of geomdl's derivatives
(neither peer computes surface curvature), knot insertion and degree
elevation (splipy's nets), every layer of a fuzzy surface (geomdl).
Differences are relative to the size of the net."""

from __future__ import annotations

from typing import Any, Dict, List, Tuple

import numpy as np
import pytest
import splipy
from geomdl import NURBS

import t2spline

CASES = 24
TOLERANCE = 1e-12


def random_case(rng: np.random.Generator) -> Dict[str, Any]:
    """Degrees 1–4 per direction, a random domain per direction, clamped
    knots with random interior knots (one repeated when the degree allows it
    without a jump), weights 0.2–5 (log-uniform), coordinates in [-10, 10]."""
    degree, knots = [], []
    for _ in range(2):
        p = int(rng.integers(1, 5))
        a = float(rng.uniform(-3, 3))
        b = a + float(10 ** rng.uniform(-1, 1))
        interior = np.sort(rng.uniform(a, b, int(rng.integers(0, 5))))
        if p >= 2 and len(interior) >= 2 and rng.integers(0, 2):
            interior[1] = interior[0]
        degree.append(p)
        knots.append(np.concatenate([[a] * (p + 1), interior, [b] * (p + 1)]))
    shape = tuple(len(k) - p - 1 for k, p in zip(knots, degree))
    return {
        "degree": degree,
        "knots": knots,
        "points": rng.uniform(-10, 10, (*shape, 3)),
        "weights": np.exp(rng.uniform(np.log(0.2), np.log(5.0), shape)),
    }


def ours(case: Dict[str, Any]) -> t2spline.NurbsSurface:
    return t2spline.NurbsSurface(case["points"], case["weights"], *case["knots"], degree=tuple(case["degree"]))


def geomdl_surface(case: Dict[str, Any]) -> Any:
    """geomdl's control points are u-major (index i·nv + j), weighted."""
    nu, nv = case["weights"].shape
    s = NURBS.Surface(normalize_kv=False)
    s.degree_u, s.degree_v = case["degree"]
    s.ctrlpts_size_u, s.ctrlpts_size_v = nu, nv
    homogeneous = np.concatenate([case["points"] * case["weights"][..., None], case["weights"][..., None]], axis=-1)
    s.ctrlptsw = homogeneous.reshape(-1, 4).tolist()
    s.knotvector_u, s.knotvector_v = (k.tolist() for k in case["knots"])
    return s


def splipy_surface(case: Dict[str, Any]) -> Any:
    """splipy takes the projective points (w·P, w), first direction fastest."""
    bases = [splipy.BSplineBasis(p + 1, k) for p, k in zip(case["degree"], case["knots"])]
    homogeneous = np.concatenate([case["points"] * case["weights"][..., None], case["weights"][..., None]], axis=-1)
    return splipy.Surface(*bases, homogeneous.transpose(1, 0, 2).reshape(-1, 4), rational=True)


def splipy_net(s: Any) -> Tuple[np.ndarray, np.ndarray, List[np.ndarray]]:
    """Points (nu, nv, 3), weights (nu, nv) and knots of a splipy surface."""
    cp = np.asarray(s.controlpoints, dtype=float)
    return cp[..., :-1] / cp[..., -1:], cp[..., -1], [np.asarray(k) for k in s.knots(with_multiplicities=True)]


def probes(rng: np.random.Generator, knots: np.ndarray, p: int) -> np.ndarray:
    """Both ends, every distinct interior knot and random values."""
    a, b = knots[p], knots[-p - 1]
    inner = np.unique(knots[(knots > a) & (knots < b)])
    return np.concatenate([[a, b], inner, rng.uniform(a, b, 4)])


def cases() -> List[Dict[str, Any]]:
    rng = np.random.default_rng(2024)
    return [random_case(rng) for _ in range(CASES)]


def evaluation_errors() -> Dict[str, float]:
    """Largest relative differences of `eval` and `sample` from each peer."""
    rng = np.random.default_rng(11)
    worst = {"geomdl eval": 0.0, "geomdl sample": 0.0, "splipy eval": 0.0, "splipy sample": 0.0}
    for case in cases():
        s, g, sp = ours(case), geomdl_surface(case), splipy_surface(case)
        u = probes(rng, case["knots"][0], case["degree"][0])
        v = probes(rng, case["knots"][1], case["degree"][1])
        scale = np.abs(case["points"]).max()
        at = s.eval(u[:, None], v[None, :])
        grid = s.sample(u, v)
        reference = {
            "geomdl": np.array([[g.evaluate_single([a, b]) for b in v] for a in u]),
            "splipy": np.asarray(sp(u, v)),
        }
        for peer, want in reference.items():
            worst[f"{peer} eval"] = max(worst[f"{peer} eval"], float(np.abs(at - want).max() / scale))
            worst[f"{peer} sample"] = max(worst[f"{peer} sample"], float(np.abs(grid - want).max() / scale))
    return worst


def derivative_errors() -> Dict[str, float]:
    """Largest differences of the partial derivatives (relative to the
    largest value of each order in the case, at least the net's size) and of
    the unit normals from geomdl's."""
    rng = np.random.default_rng(12)
    worst = {"derivatives": 0.0, "normal": 0.0, "normals compared": 0.0}
    for case in cases():
        s, g = ours(case), geomdl_surface(case)
        order = max(case["degree"]) + 1
        u = probes(rng, case["knots"][0], case["degree"][0])
        v = probes(rng, case["knots"][1], case["degree"][1])
        mine = s.derivatives(u[:, None], v[None, :], order=order)
        theirs = np.array([[g.derivatives(a, b, order) for b in v] for a in u])
        for total in range(order + 1):
            pairs = [(k, total - k) for k in range(total + 1)]
            want = np.stack([theirs[:, :, k, l] for k, l in pairs])
            got = np.stack([mine[:, :, k, l] for k, l in pairs])
            scale = max(float(np.abs(want).max()), float(np.abs(case["points"]).max()))
            worst["derivatives"] = max(worst["derivatives"], float(np.abs(got - want).max() / scale))
        cross = np.cross(theirs[:, :, 1, 0], theirs[:, :, 0, 1])
        length = np.linalg.norm(cross, axis=-1)
        regular = length > 1e-6 * np.abs(theirs[:, :, 1, 0]).max() * np.abs(theirs[:, :, 0, 1]).max()
        # Where S_u × S_v (nearly) vanishes the normal is undefined or
        # ill-conditioned; such cases are not compared.
        if regular.all():
            normals = s.normal(u[:, None], v[None, :])
            worst["normal"] = max(worst["normal"], float(np.abs(normals - cross / length[..., None]).max()))
            worst["normals compared"] += 1
    return worst


def classical_curvature(d: np.ndarray) -> Tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """K, H, (k1, k2) and the principal directions from partial derivatives
    ``d[..., k, l, :]`` by the fundamental forms (do Carmo §3-3), the
    directions from numpy's eigenvectors of the Weingarten matrix I⁻¹·II."""
    su, sv, suu, suv, svv = d[..., 1, 0, :], d[..., 0, 1, :], d[..., 2, 0, :], d[..., 1, 1, :], d[..., 0, 2, :]
    n = np.cross(su, sv)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    dot = lambda a, b: (a * b).sum(-1)  # noqa: E731
    first = np.stack([np.stack([dot(su, su), dot(su, sv)], -1), np.stack([dot(su, sv), dot(sv, sv)], -1)], -2)
    second = np.stack([np.stack([dot(suu, n), dot(suv, n)], -1), np.stack([dot(suv, n), dot(svv, n)], -1)], -2)
    values, vectors = np.linalg.eig(np.linalg.solve(first, second))
    values, vectors = values.real, vectors.real
    order = np.argsort(-values, axis=-1)
    principal = np.take_along_axis(values, order, -1)
    vectors = np.take_along_axis(vectors, order[..., None, :], -1)
    directions = vectors[..., 0, :, None] * su[..., None, :] + vectors[..., 1, :, None] * sv[..., None, :]
    directions /= np.linalg.norm(directions, axis=-1, keepdims=True)
    return np.linalg.det(second) / np.linalg.det(first), principal.sum(-1) / 2, principal, directions


def curvature_errors() -> Dict[str, float]:
    """Largest differences of `curvature` from the fundamental forms of
    geomdl's derivatives, relative to the largest principal curvature of the
    case: K (relative to its square), H, k1 and k2; the principal directions
    (the sine of the angle) where k1 − k2 is at least a tenth of that scale. Points
    where the normal is (nearly) singular, as in `derivative_errors`, are
    not compared."""
    rng = np.random.default_rng(14)
    worst = {"gaussian": 0.0, "mean": 0.0, "principal": 0.0, "directions": 0.0, "points compared": 0.0}
    for case in cases():
        s, g = ours(case), geomdl_surface(case)
        u = probes(rng, case["knots"][0], case["degree"][0])
        v = probes(rng, case["knots"][1], case["degree"][1])
        theirs = np.array([[g.derivatives(a, b, 2) for b in v] for a in u])
        su, sv = theirs[:, :, 1, 0], theirs[:, :, 0, 1]
        length = np.linalg.norm(np.cross(su, sv), axis=-1)
        regular = length > 1e-6 * np.linalg.norm(su, axis=-1) * np.linalg.norm(sv, axis=-1)
        if not regular.any():
            continue
        k, h, principal, directions = (x[regular] for x in classical_curvature(theirs))
        c = s.curvature(np.broadcast_to(u[:, None], regular.shape)[regular],
                        np.broadcast_to(v[None, :], regular.shape)[regular])
        scale = max(float(np.abs(c["principal"]).max()), 1e-3)
        worst["gaussian"] = max(worst["gaussian"], float(np.abs(c["gaussian"] - k).max()) / scale**2)
        worst["mean"] = max(worst["mean"], float(np.abs(c["mean"] - h).max()) / scale)
        worst["principal"] = max(worst["principal"], float(np.abs(c["principal"] - principal).max()) / scale)
        apart = c["principal"][:, 0] - c["principal"][:, 1] >= 0.1 * scale
        # The sine of the angle between the two, whatever their signs.
        sine = np.linalg.norm(np.cross(c["directions"][apart], directions[apart]), axis=-1)
        if sine.size:
            worst["directions"] = max(worst["directions"], float(sine.max()))
        worst["points compared"] += int(regular.sum())
    return worst


def operation_errors() -> Dict[str, float]:
    """Largest differences of the nets after knot insertion (twice at a
    random parameter) and degree elevation (by one) in each direction from
    splipy's nets, points relative to the net's size, weights to the
    largest weight, knots exactly."""
    rng = np.random.default_rng(13)
    worst = {"insertion": 0.0, "elevation": 0.0}
    for case in cases():
        s = ours(case)
        for k, direction in enumerate("uv"):
            a, b = s.domain[k]
            t = float(rng.uniform(a, b))
            for name, mine, peer in (
                ("insertion", s.insert_knot(t, times=2, direction=direction), splipy_surface(case)),
                ("elevation", s.elevate_degree(direction=direction), splipy_surface(case)),
            ):
                if name == "insertion":
                    peer.insert_knot([t, t], direction=k)
                else:
                    peer.raise_order(*(1, 0) if k == 0 else (0, 1))
                points, weights, knots = splipy_net(peer)
                for got, want in zip((mine.knots_u, mine.knots_v), knots):
                    assert got.shape == want.shape
                    assert np.abs(got - want).max() <= 1e-14 * max(1.0, float(np.abs(want).max()))
                assert mine.control_points.shape == points.shape
                error = max(float(np.abs(mine.control_points - points).max() / np.abs(points).max()),
                            float(np.abs(mine.weights - weights).max() / weights.max()))
                worst[name] = max(worst[name], error)
    return worst


def test_evaluation_equals_geomdl_and_splipy() -> None:
    worst = evaluation_errors()
    assert max(worst.values()) <= TOLERANCE, worst


def test_derivatives_and_normals_equal_geomdl() -> None:
    worst = derivative_errors()
    assert worst["derivatives"] <= 1e-10, worst
    assert worst["normal"] <= 1e-10, worst
    assert worst["normals compared"] >= CASES // 2, worst


def test_curvature_equals_the_fundamental_forms_of_geomdls_derivatives() -> None:
    worst = curvature_errors()
    assert max(worst["gaussian"], worst["mean"], worst["principal"]) <= 1e-10, worst
    assert worst["directions"] <= 1e-10, worst
    assert worst["points compared"] >= 10 * CASES, worst


def test_insertion_and_elevation_give_splipys_nets() -> None:
    worst = operation_errors()
    assert max(worst.values()) <= 1e-11, worst


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_every_layer_of_a_fuzzy_surface_equals_geomdl(seed: int) -> None:
    rng = np.random.default_rng(seed)
    case = random_case(rng)
    crisp = case["points"]
    left = np.cumsum(rng.uniform(0, 1, (*crisp.shape, 3)), axis=-1)
    right = np.cumsum(rng.uniform(0, 1, (*crisp.shape, 3)), axis=-1)
    feet = [np.stack([crisp - left[..., k], crisp + right[..., k]], axis=-1) for k in (2, 1, 0)]
    fuzzy = t2spline.FuzzySurface(crisp, *feet, lower_height=0.5, weights=case["weights"],
                                  knots_u=case["knots"][0], knots_v=case["knots"][1])
    u = probes(rng, case["knots"][0], case["degree"][0])
    v = probes(rng, case["knots"][1], case["degree"][1])
    layers = fuzzy.sample(u, v)
    scale = np.abs(fuzzy.upper).max()
    for name in ("upper_left", "primary_left", "lower_left", "crisp", "lower_right", "primary_right",
                 "upper_right"):
        g = geomdl_surface(dict(case, points=fuzzy.layer_control_points(name)))
        want = np.array([[g.evaluate_single([a, b]) for b in v] for a in u])
        assert np.abs(layers[name] - want).max() <= TOLERANCE * scale, name
