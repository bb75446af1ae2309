//! `NurbsSurface`: a rational B-spline surface (docs/method.md §8) with the operations
//! of the core: evaluation broadcast over arrays of `u` and `v`, the grid
//! engine, partial derivatives, the normal, the curvature, the closest point, isocurves,
//! knot insertion and refinement, degree elevation, splitting, the bounding
//! box (the last ones shared with `FuzzySurface`, `surface_methods.rs`).

use pyo3::prelude::*;
use t2spline::{Direction, NurbsSurface};

use crate::arrays::{floats, optional_vector, Floats};
use crate::capability;
use crate::classes::{PyNurbsCurve, PyNurbsSurface};
use crate::closest::ClosestArrays;
use crate::construct::{knot_vector, net_weights, rows, surface_degrees};
use crate::curvature::{spatial, surface_curvature};
use crate::dim::by_dim;
use crate::errors::compute;
use crate::keyword;
use crate::net::{points_array, Net};
use crate::py_types::{DictResult, Obj, ObjResult};
use crate::sample::{at_pairs, GridArg};
use crate::surface_methods::surface_methods;

/// A surface of dimension `D` on the net of `points`.
fn build<const D: usize>(
    points: &Floats,
    net: [usize; 2],
    weights: Vec<f64>,
    [ku, kv]: [Option<Vec<f64>>; 2],
    [p, q]: [usize; 2],
) -> Result<NurbsSurface<D>, t2spline::Error> {
    let knots = [
        knot_vector(Direction::U, ku, p, net[0])?,
        knot_vector(Direction::V, kv, q, net[1])?,
    ];
    NurbsSurface::try_new(rows(points.rows::<D>(), net), rows(weights, net), knots)
}

surface_methods!(PyNurbsSurface, PyNurbsCurve {

    /// Pickling and copying: the constructor with ``(control_points, weights, knots_u, knots_v)``
    /// (the degree following from the knots), an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        crate::pickle::by_constructor(slf, &["control_points", "weights", "knots_u", "knots_v"])
    }
    #[new]
    #[pyo3(signature = (control_points, weights=None, knots_u=None, knots_v=None, *, degree=None, order=None))]
    fn new(
        py: Python<'_>,
        control_points: &Obj<'_>,
        weights: Option<&Obj<'_>>,
        knots_u: Option<&Obj<'_>>,
        knots_v: Option<&Obj<'_>>,
        degree: Option<&Obj<'_>>,
        order: Option<&Obj<'_>>,
    ) -> PyResult<Self> {
        let (degree, order) = (
            keyword::opt_per_direction(degree, "degree")?,
            keyword::opt_per_direction(order, "order")?,
        );
        let points = floats(control_points, "control_points")?;
        let (net, d) = points.net_shape("control_points", 2)?;
        let net = [net[0], net[1]];
        let weights = net_weights(weights, net)?;
        let knots = [
            optional_vector(knots_u, "knots_u")?,
            optional_vector(knots_v, "knots_v")?,
        ];
        let lengths = knots.each_ref().map(|k| k.as_ref().map(Vec::len));
        let degree = surface_degrees(degree, order, lengths, net)?;
        compute(py, move || {
            Ok(match d {
                2 => build::<2>(&points, net, weights, knots, degree)?.into(),
                _ => build::<3>(&points, net, weights, knots, degree)?.into(),
            })
        })
    }

    /// The control net, shape ``(nu, nv, dimension)``.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |s| points_array(py, s.control_points().to_vec(), &s.net()))
    }

    /// The point ``S(u, v)`` at every pair of ``u`` and ``v``, by the
    /// straightforward evaluator (the rational basis at ``(u, v)``);
    /// ``sample`` is the fast engine for grids.
    ///
    /// Parameters
    /// ----------
    /// u, v : float or array_like
    ///     Parameters in the domain; arrays broadcast together as numpy's do
    ///     (``u[:, None]`` and ``v[None, :]`` give a grid).
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``broadcast(u, v).shape + (dimension,)``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a parameter outside its domain (``parameter v = 2 is outside
    ///     the domain [0, 1]``), NaN or infinity, shapes that do not
    ///     broadcast.
    fn eval<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |s| capability::surface_points(py, s, [u, v], self.dimension()))
    }

    /// ``surface(u, v)`` is ``surface.eval(u, v)`` (as splipy's surfaces are
    /// called).
    fn __call__<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        self.eval(py, u, v)
    }

    /// The surface on the grid ``u × v`` by the grid engine (the basis in u
    /// once per grid row, in v once per grid column, multi-threaded by rows
    /// for large grids); agrees with ``eval`` to rounding.
    ///
    /// Parameters
    /// ----------
    /// u, v : int or array_like
    ///     Each a count of uniform parameters over its domain
    ///     (``uniform_params``) or a 1-D array of parameters in any order.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``(len(u), len(v), dimension)``: the point ``[a, b]`` is
    ///     ``S(u[a], v[b])``, as ``run``'s ``surfaces`` grids.
    fn sample<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        let grid = GridArg::extract(u, v)?;
        let d = self.dimension();
        by_dim!(&self.0, |s| grid.sample(py, [&[], &[d]], |[u, v], out| s
            .grid_sampler()
            .sample_into(u, v, out)))
    }

    /// The partial derivatives ``∂ᵏ⁺ˡS/∂uᵏ∂vˡ`` for ``k + l <= order`` at
    /// every pair of ``u`` and ``v`` (The NURBS Book A3.6 and A4.4);
    /// one-sided at knots, as ``eval``.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``broadcast(u, v).shape + (order + 1, order + 1,
    ///     dimension)``: ``[..., k, l, :]`` is ``∂ᵏ⁺ˡS/∂uᵏ∂vˡ``,
    ///     ``[..., 0, 0, :]`` the point itself; NaN where ``k + l > order``
    ///     (not computed).
    ///
    /// Examples
    /// --------
    /// >>> s = NurbsSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], degree=1)
    /// >>> d = s.derivatives(0.25, 0.5, order=2)        # S(u, v) = (u, v, u·v)
    /// >>> d[1, 0].tolist(), d[0, 1].tolist(), d[1, 1].tolist()   # S_u, S_v, S_uv
    /// ([1.0, 0.0, 0.5], [0.0, 1.0, 0.25], [0.0, 0.0, 1.0])
    #[pyo3(signature = (u, v, order=None), text_signature = "($self, u, v, order=1)")]
    fn derivatives<'py>(
        &self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>, order: Option<&Obj<'py>>,
    ) -> ObjResult<'py> {
        by_dim!(&self.0, |s| capability::surface_derivatives(py, s, [u, v], order, self.dimension()))
    }

    /// The unit normal ``S_u × S_v / |S_u × S_v|`` at every pair of ``u`` and
    /// ``v``, one-sided at knots as ``derivatives``; shape
    /// ``broadcast(u, v).shape + (3,)``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     Where ``S_u`` and ``S_v`` are parallel or zero; for a surface in
    ///     the plane.
    fn normal<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        let s = spatial(&self.0, "normal")?;
        at_pairs(py, u, v, &[3], |u, v, out| {
            out.extend(s.normal(u, v)?);
            Ok(())
        })
    }

    /// The curvature at every pair of ``u`` and ``v``: Gaussian curvature
    /// ``K``, mean curvature ``H``, the principal curvatures ``k1 >= k2``
    /// and their unit directions in space, from the first and second
    /// fundamental forms (do Carmo §3-3); one-sided at knots as
    /// ``derivatives``.
    ///
    /// Signs follow ``normal``: a normal curvature is positive where the
    /// surface bends toward the normal ``S_u × S_v / |S_u × S_v|``. At an
    /// umbilic (``k1 = k2`` within rounding: a sphere, a plane) the
    /// directions are ``S_u/|S_u|`` and ``normal × S_u/|S_u|``.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"gaussian"`` and ``"mean"``: shape ``broadcast(u, v).shape``
    ///     (0-d arrays for two numbers); ``"principal"``: that ``+ (2,)``,
    ///     ``[k1, k2]``; ``"directions"``: that ``+ (2, 3)``, ``[e1, e2]``
    ///     with ``(e1, e2, normal)`` right-handed and orthonormal.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a parameter outside its domain; where the normal is
    ///     undefined (as ``normal``); for a surface in the plane.
    ///
    /// Examples
    /// --------
    /// >>> w = 0.5 ** 0.5                     # a quarter cylinder of radius 2 about z
    /// >>> s = NurbsSurface([[[2, 0, 0], [2, 0, 1]], [[2, 2, 0], [2, 2, 1]], [[0, 2, 0], [0, 2, 1]]],
    /// ...                  weights=[[1, 1], [w, w], [1, 1]], degree=(2, 1))
    /// >>> c = s.curvature([0.2, 0.7], 0.5)
    /// >>> (c["principal"].round(12) + 0.0).tolist()  # none along the axis, -1/2 around it
    /// [[0.0, -0.5], [0.0, -0.5]]
    /// >>> (c["directions"][0, 0].round(12) + 0.0).tolist()
    /// [0.0, 0.0, 1.0]
    fn curvature<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> DictResult<'py> {
        surface_curvature(py, &self.0, "curvature", [u, v])
    }

    /// The rational basis ``Rᵢⱼ(u, v) = wᵢⱼNᵢ,ₚ(u)Mⱼ,q(v) / Σₖₗ
    /// wₖₗNₖ,ₚ(u)Mₗ,q(v)`` of every control point at every pair of ``u`` and
    /// ``v``: non-negative, summing to 1; shape ``broadcast(u, v).shape +
    /// (nu, nv)``.
    fn rational_basis<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        let net = by_dim!(&self.0, |s| s.net());
        by_dim!(&self.0, |s| at_pairs(py, u, v, &net, |u, v, out| {
            out.extend(s.rational_basis(u, v)?.into_iter().flatten());
            Ok(())
        }))
    }

    /// The point of the surface closest to ``point``: a global minimum over
    /// the domain (each knot-span patch pruned by the box of its control
    /// points, else scanned, refined by Nelder–Mead inside the patch and
    /// polished by Newton's method on the normal equations, The NURBS Book
    /// §6.1); borders and corners included.
    ///
    /// Parameters
    /// ----------
    /// point : array_like, shape (dimension,) or (m, dimension)
    ///
    /// Returns
    /// -------
    /// (u, v, point, distance)
    ///     For one point: two floats, an array ``(dimension,)`` and a float;
    ///     for ``m`` points: arrays ``(m,)``, ``(m,)``, ``(m, dimension)``
    ///     and ``(m,)``.
    ///
    /// Examples
    /// --------
    /// >>> s = NurbsSurface([[[0, 0, 0], [0, 2, 0]], [[3, 0, 0], [3, 2, 0]]], degree=1)
    /// >>> u, v, p, d = s.closest_point([1.2, 0.5, 4.0])     # S(u, v) = (3u, 2v, 0)
    /// >>> round(u, 12), round(v, 12), round(d, 12)
    /// (0.4, 0.25, 4.0)
    fn closest_point<'py>(&self, py: Python<'py>, point: &Obj<'py>) -> PyResult<ClosestArrays<'py>> {
        let [u, v, p, d] = by_dim!(&self.0, |s| capability::closest(py, s, point))?;
        Ok((u, v, p, d))
    }

    /// The picture in a notebook: the shaded surface and its control net,
    /// drawn by the figure code of ``t2spline plot`` (stage 1 of the fuzzy
    /// surface whose every number is crisp), as inline SVG under a short
    /// table; ``None`` (no picture) for a surface in the plane.
    fn _repr_html_(&self) -> PyResult<Option<String>> {
        use crate::dim::ToModel as _;
        let fuzzy: crate::dim::ByDim<crate::dim::FuzzyNet> =
            by_dim!(&self.0, |s| crate::picture::crisp_fuzzy_surface(s)?.into());
        let Ok(model) = fuzzy.to_model() else {
            return Ok(None);
        };
        crate::picture::crisp_page(model, "NURBS surface", &self.facts().rows()).map(Some)
    }

    fn __repr__(&self) -> String {
        let knots = by_dim!(&self.0, |s| Direction::BOTH.map(|k| s.knots(k).as_slice().len()));
        self.facts().repr("NurbsSurface", Some(knots))
    }
});
