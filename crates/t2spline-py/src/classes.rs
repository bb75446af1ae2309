//! The Python classes of curves, surfaces and their solutions: each holds a
//! [`ByDim`] of its core type and carries the class's documentation
//! (`help(t2spline.NurbsSurface)`); its methods live in a module of their
//! own (`nurbs_curve.rs`, `fuzzy_surface.rs`, …). Declared together, so
//! that the method modules can return each other's classes
//! (`FuzzyCurve.solve` a `Solution`, `Solution.fuzzy_curve` a `FuzzyCurve`)
//! without importing each other.

use pyo3::prelude::*;
use t2spline::{FuzzyCurve, FuzzySurface, NurbsCurve, NurbsSurface, Solution, SurfaceSolution};

use crate::dim::{ByDim, Fuzzy, FuzzyNet, Nurbs, NurbsNet, Solved, SolvedNet};

/// `classes! { doc "Name": Class(Family = CoreType); … }`: each class as a
/// frozen, comparable `#[pyclass]` around a `ByDim<Family>`, made from the
/// core type of either dimension with `into()`.
macro_rules! classes {
    ($($(#[$doc:meta])* $name:literal: $class:ident($family:ident = $core:ident);)*) => {
        $(
            $(#[$doc])*
            #[pyclass(frozen, eq, module = "t2spline", name = $name)]
            #[derive(Clone, Debug, PartialEq)]
            pub(crate) struct $class(pub(crate) ByDim<$family>);

            impl From<$core<2>> for $class {
                fn from(value: $core<2>) -> Self {
                    $class(value.into())
                }
            }

            impl From<$core<3>> for $class {
                fn from(value: $core<3>) -> Self {
                    $class(value.into())
                }
            }
        )*
    };
}

classes! {
/// A rational B-spline curve in the plane or in space (docs/method.md §6, paper
/// Def. 5.1)::
///
///     C(t) = Σᵢ wᵢ Nᵢ,ₚ(t) Pᵢ / Σᵢ wᵢ Nᵢ,ₚ(t),   t in [U[p], U[n]]
///
/// with ``n`` control points ``Pᵢ``, weights ``wᵢ > 0``, degree ``p`` (order
/// ``k = p + 1``) and a knot vector ``U`` of ``n + k`` non-decreasing values
/// (default: clamped uniform). At an interior knot of full multiplicity the
/// value from the right is taken; at the right end of the domain the last
/// non-empty span is used.
///
/// Parameters
/// ----------
/// control_points : array_like, shape (n, 2) or (n, 3)
/// weights : array_like, shape (n,), optional
///     Default: all 1.
/// knots : array_like, shape (n + degree + 1,), optional
///     Default: clamped uniform.
/// degree, order : int, optional
///     Exactly one of them (``order = degree + 1``); when both are left out,
///     the degree follows from the number of knots.
///
/// Raises
/// ------
/// TypeError, ValueError
///     For an argument of the wrong dtype or shape (named), NaN or infinity,
///     and every rule of docs/method.md §6 (too few control points, a weight that is not
///     positive, decreasing knots, ...), naming the place.
///
/// Examples
/// --------
/// The rational quarter circle, weights ``1, √2/2, 1``:
///
/// >>> import numpy as np
/// >>> arc = NurbsCurve([[1, 0], [1, 1], [0, 1]], weights=[1, np.sqrt(0.5), 1], degree=2)
/// >>> arc
/// NurbsCurve(dimension=2, degree=2, order=3, control_points=(3, 2), knots=(6,), domain=(0.0, 1.0))
/// >>> points = arc.sample(101)                       # (101, 2), by the sampling engine
/// >>> bool(np.allclose(np.hypot(points[:, 0], points[:, 1]), 1.0, rtol=0, atol=1e-14))
/// True
/// >>> round(arc.arc_length(), 12) == round(np.pi / 2, 12)
/// True
    "NurbsCurve": PyNurbsCurve(Nurbs = NurbsCurve);

/// A normal type-2 fuzzy rational B-spline curve: stage 1 of Algorithm 1.1
/// (docs/method.md §6–§7, paper Def. 5.1 and Fig. 5.1).
///
/// The control points are fuzzy points, one fuzzy number (``FuzzyNumber``)
/// per coordinate. The seven *layer curves* go through one value of every
/// number, with the curve's weights and knots::
///
///     C_L(t) = Σᵢ wᵢ Nᵢ,ₚ(t) Pᵢ,L / Σᵢ wᵢ Nᵢ,ₚ(t),
///     L in upper_left, primary_left, lower_left, crisp, lower_right, primary_right, upper_right
///
/// and since the rational basis is non-negative and sums to 1, they keep the
/// order of the values at every ``t``.
///
/// Parameters
/// ----------
/// crisp : array_like, shape (n, d)
///     The crisp control points, ``d`` = 2 or 3.
/// upper, primary, lower : array_like, shape (n, d, 2)
///     The ``[left, right]`` feet of each number's triangles.
/// lower_height : float or array_like
///     ``h`` of every number: shape ``(n, d)``, or anything that broadcasts
///     to it (one number for all, ``(d,)`` one per coordinate, ``(n, 1)``
///     one per point).
/// weights : array_like, shape (n,), or sequence of FuzzyNumber and float, optional
///     Default: all 1. Fuzzy weights (docs/method.md §16): one
///     ``FuzzyNumber`` per point, a plain number beside them a crisp
///     weight (``FuzzyNumber(w)``); every value of each must be a weight.
///     ``weight_numbers`` gives them back, ``weights`` their crisp values.
/// knots : array_like, shape (n + degree + 1,), optional
///     Default: clamped uniform.
/// degree, order : int, optional
///     Exactly one of them; when both are left out, the degree follows from
///     the number of knots.
///
/// Raises
/// ------
/// TypeError, ValueError
///     For a wrong dtype or shape (naming the argument and the shape
///     expected), NaN or infinity, and every rule of docs/method.md §1 and §6, naming
///     the place: ``points[2].y: the order lower.left <= crisp is broken: 2.1 > 2``,
///     ``weights[1] = -0.5 must be finite and greater than 0``.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> c = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
/// >>> spread = np.array([-0.6, 0.9])          # [left, right] offsets
/// >>> curve = FuzzyCurve(c, c[..., None] + spread, c[..., None] + 0.6 * spread,
/// ...                    c[..., None] + 0.3 * spread, lower_height=0.6, degree=2)
/// >>> curve.upper.shape, curve.lower_height.shape
/// ((4, 2, 2), (4, 2))
/// >>> s = curve.sample(5)
/// >>> s["upper_right"][2] - s["crisp"][2]     # the upper right spread at t = 0.5
/// array([0.9, 0.9])
    "FuzzyCurve": PyFuzzyCurve(Fuzzy = FuzzyCurve);

/// Stages 2–4 of Algorithm 1.1 at one level alpha (docs/method.md §7, paper Figs.
/// 5.2–5.4), from ``FuzzyCurve.solve(alpha, type_reduction=)``.
///
/// 2. alpha-cut control points (``alpha_cut``) and their curves;
/// 3. type-reduced control points ``(left, crisp, right)``
///    (``type_reduced_left``, ``type_reduced_right``) and the curves through
///    the left and the right values;
/// 4. defuzzified control points ``(left + crisp + right)/3``
///    (``defuzzified``), the crisp type-2 solution curve through them, and its
///    distance to the crisp curve (``distance``).
///
/// With another type reduction (docs/method.md §9: ``"centroid"``, ``"nie-tan"``,
/// ``"alpha-planes"``) stage 2 is cut at alpha = 0 and stages 3–4 are that
/// reduction's, exactly as ``run(..., type_reduction=)`` computes them.
///
/// The stages act on the control points, number by number, as Algorithm 1.1
/// does; with one lower height for every number this equals applying them to
/// the curve (docs/method.md §6).
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> c = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
/// >>> s = np.array([-1.0, 1.0])               # symmetric spreads
/// >>> curve = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s, c[..., None] + 0.2 * s,
/// ...                    lower_height=0.5, degree=2)
/// >>> sol = curve.solve(0.3)
/// >>> bool(np.array_equal(sol.defuzzified, sol.crisp))   # symmetric: no shift
/// True
/// >>> sol.distance()["max"]
/// 0.0
    "Solution": PySolution(Solved = Solution);

/// A rational B-spline surface in space or in the plane (docs/method.md §8), the
/// tensor product of two rational B-spline curves::
///
///     S(u, v) = Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v) Pᵢⱼ / Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v)
///
/// over ``(u, v)`` in ``[U[p], U[nu]] × [V[q], V[nv]]``, with a net of
/// ``nu × nv`` control points ``Pᵢⱼ`` (row ``i`` along u, column ``j`` along
/// v), weights ``wᵢⱼ > 0``, degrees ``p`` and ``q`` and a knot vector per
/// direction (default: clamped uniform). Every rule of a curve (docs/method.md §6)
/// holds in each direction: at an interior knot of full multiplicity the
/// value from the right is taken, at the end of a domain the last non-empty
/// span is used.
///
/// Parameters
/// ----------
/// control_points : array_like, shape (nu, nv, 3) or (nu, nv, 2)
/// weights : array_like, shape (nu, nv), optional
///     Default: all 1.
/// knots_u : array_like, shape (nu + p + 1,), optional
/// knots_v : array_like, shape (nv + q + 1,), optional
///     Default: clamped uniform.
/// degree, order : int or (int, int), optional
///     Exactly one of them (``order = degree + 1``), one value for both
///     directions or ``(u, v)``; when both are left out, each direction's
///     degree follows from its number of knots.
///
/// Raises
/// ------
/// TypeError, ValueError
///     For an argument of the wrong dtype or shape (named), NaN or infinity,
///     and every rule of docs/method.md §8 (too few control points in a direction, a
///     weight that is not positive, decreasing knots, ...), naming the place:
///     ``weights[1][0] = 0 must be finite and greater than 0``.
///
/// Examples
/// --------
/// A quarter of the cylinder of radius 1 about the z axis: the rational
/// quarter circle (weights ``1, √2/2, 1``) in u, a straight line in v:
///
/// >>> import numpy as np
/// >>> w = np.sqrt(0.5)
/// >>> net = [[[1, 0, 0], [1, 0, 2]], [[1, 1, 0], [1, 1, 2]], [[0, 1, 0], [0, 1, 2]]]
/// >>> cylinder = NurbsSurface(net, weights=[[1, 1], [w, w], [1, 1]], degree=(2, 1))
/// >>> cylinder
/// NurbsSurface(dimension=3, degree=(2, 1), order=(3, 2), control_points=(3, 2, 3), knots=(6, 4), domain=((0.0, 1.0), (0.0, 1.0)))
/// >>> grid = cylinder.sample(41, 5)                  # (41, 5, 3), by the grid engine
/// >>> bool(np.allclose(np.hypot(grid[..., 0], grid[..., 1]), 1.0, rtol=0, atol=1e-14))
/// True
/// >>> cylinder.eval(0.5, [0.0, 0.5, 1.0])[:, 2]      # u = 0.5 at three heights
/// array([0., 1., 2.])
/// >>> bool(np.allclose(cylinder.normal(0.5, 0.3), [w, w, 0], rtol=0, atol=1e-15))
/// True
    "NurbsSurface": PyNurbsSurface(NurbsNet = NurbsSurface);

/// A normal type-2 fuzzy rational B-spline surface: stage 1 of Algorithm
/// 1.1 on a net of fuzzy control points (docs/method.md §8, the paper's tensor-product
/// extension).
///
/// The control points ``P̃ᵢⱼ`` are fuzzy points, one fuzzy number per
/// coordinate. The seven *layer surfaces* go through one value of every
/// number, with the surface's weights and knots::
///
///     S_L(u, v) = Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v) Pᵢⱼ,L / Σᵢ Σⱼ wᵢⱼ Nᵢ,ₚ(u) Mⱼ,q(v)
///
/// and, the rational basis being non-negative with sum 1, they keep the
/// order of the values at every ``(u, v)``. ``solve`` runs stages 2–4 on the
/// net as ``FuzzyCurve.solve`` does on a curve's control points.
///
/// Parameters
/// ----------
/// crisp : array_like, shape (nu, nv, d)
///     The crisp control net, ``d`` = 3 or 2.
/// upper, primary, lower : array_like, shape (nu, nv, d, 2)
///     The ``[left, right]`` feet of each number's triangles.
/// lower_height : float or array_like
///     ``h`` of every number: shape ``(nu, nv, d)``, or anything that
///     broadcasts to it (one number for all, ``(d,)`` one per coordinate).
/// weights : array_like, shape (nu, nv), optional
///     Default: all 1.
/// knots_u, knots_v : array_like, optional
///     Default: clamped uniform.
/// degree, order : int or (int, int), optional
///     As for ``NurbsSurface``.
///
/// Raises
/// ------
/// TypeError, ValueError
///     For a wrong dtype or shape (naming the argument and the shape
///     expected), NaN or infinity, and every rule of docs/method.md §1 and §8, naming
///     the place: ``points[1][2].z: the order lower.left <= crisp is broken: 0.5 > 0.25``.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> x, y = np.meshgrid([0.0, 1.0, 2.0], [0.0, 1.0, 2.0], indexing="ij")
/// >>> crisp = np.stack([x, y, x * y / 4], axis=-1)   # a 3 × 3 net
/// >>> spread = np.array([-0.6, 0.9])                  # [left, right] offsets
/// >>> s = FuzzySurface(crisp, crisp[..., None] + spread, crisp[..., None] + 0.6 * spread,
/// ...                  crisp[..., None] + 0.3 * spread, lower_height=0.6, degree=(2, 1))
/// >>> s
/// FuzzySurface(dimension=3, degree=(2, 1), order=(3, 2), control_points=(3, 3, 3), domain=((0.0, 1.0), (0.0, 1.0)))
/// >>> layers = s.sample(11, 6)                        # the seven layer surfaces
/// >>> layers["upper_right"].shape, layers["u"].shape
/// ((11, 6, 3), (11,))
/// >>> solution = s.solve(alpha=0.8)                   # above h = 0.6: no lower cut
/// >>> bool(np.allclose(solution.defuzzified - solution.crisp, 0.016, rtol=0, atol=1e-15))
/// True
/// >>> round(solution.distance()["max"], 6)            # 0.016·√3
/// 0.027713
    "FuzzySurface": PyFuzzySurface(FuzzyNet = FuzzySurface);

/// Stages 2–4 of Algorithm 1.1 at one level alpha on the control net of a
/// fuzzy surface (docs/method.md §7, §8), from ``FuzzySurface.solve(alpha,
/// type_reduction=)``: number by number exactly as ``Solution`` for a curve.
///
/// 2. alpha-cut control nets (``alpha_cut``) and their surfaces;
/// 3. type-reduced control nets (``type_reduced_left``,
///    ``type_reduced_right``) and the surfaces through them;
/// 4. the defuzzified net (``defuzzified``), the crisp type-2 solution
///    surface through it, and its distance to the crisp surface
///    (``distance``).
///
/// With another type reduction than the paper's (docs/method.md §9) stage 2 is cut at
/// alpha = 0 and stages 3–4 are that reduction's, exactly as
/// ``run(..., type_reduction=)`` computes them.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> x, y = np.meshgrid([0.0, 1.0, 2.0], [0.0, 1.0], indexing="ij")
/// >>> crisp = np.stack([x, y, x - y], axis=-1)        # a 3 × 2 net
/// >>> s = np.array([-1.0, 1.0])                          # symmetric spreads
/// >>> surface = FuzzySurface(crisp, crisp[..., None] + s, crisp[..., None] + 0.5 * s,
/// ...                        crisp[..., None] + 0.2 * s, lower_height=0.5, degree=1)
/// >>> solution = surface.solve(0.3)
/// >>> bool(np.array_equal(solution.defuzzified, solution.crisp))   # no shift
/// True
/// >>> solution.distance()["max"]
/// 0.0
/// >>> surface.solve(type_reduction="centroid").alpha   # cut at 0, the whole footprint
/// 0.0
    "SurfaceSolution": PySurfaceSolution(SolvedNet = SurfaceSolution);
}
