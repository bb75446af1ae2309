//! `FuzzySurface`: stage 1 of Algorithm 1.1 on a net of fuzzy control
//! points (docs/method.md §8); its seven layer surfaces on a grid by the grid engine,
//! the curvature of each layer, its operations on all layers at once
//! (`surface_methods.rs`), the fuzzy numbers of its net
//! (`fuzzy_methods.rs`), and `solve` for stages 2–4.

use pyo3::prelude::*;
use pyo3::types::PyTuple;
use t2spline::FuzzySurface;

use crate::arrays::optional_vector;
use crate::capability;
use crate::classes::{PyFuzzyCurve, PyFuzzySurface, PyNurbsSurface, PySurfaceSolution};
use crate::closest::ClosestArrays;
use crate::construct::{layer, net_weights, rows, surface_degrees, FuzzyArrays};
use crate::curvature::surface_curvature;
use crate::dim::by_dim;
use crate::errors::compute;
use crate::fuzzy_methods::{fuzzy_methods, index, numbers};
use crate::keyword;
use crate::py_types::{DictResult, Obj, ObjResult};
use crate::sample::{layer_dict, GridArg};
use crate::surface_methods::surface_methods;

fuzzy_methods!("surface", "nu, nv", PySurfaceSolution => surface_methods!(PyFuzzySurface, PyFuzzyCurve {

    /// Pickling and copying: the constructor with ``(crisp, upper, primary, lower, lower_height, weights, knots_u, knots_v)``
    /// (the degree following from the knots), an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        crate::pickle::by_constructor(slf, &["crisp", "upper", "primary", "lower", "lower_height", "weights", "knots_u", "knots_v"])
    }
    #[new]
    #[pyo3(signature = (crisp, upper=None, primary=None, lower=None, lower_height=None, weights=None, knots_u=None, knots_v=None, *, degree=None, order=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        crisp: &Obj<'_>,
        upper: Option<&Obj<'_>>,
        primary: Option<&Obj<'_>>,
        lower: Option<&Obj<'_>>,
        lower_height: Option<&Obj<'_>>,
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
        let data = FuzzyArrays::read(crisp, [upper, primary, lower, lower_height], 2)?;
        let net = [data.net[0], data.net[1]];
        let weights = rows(net_weights(weights, net)?, net);
        let knots = [
            optional_vector(knots_u, "knots_u")?,
            optional_vector(knots_v, "knots_v")?,
        ];
        let lengths = knots.each_ref().map(|k| k.as_ref().map(Vec::len));
        let degree = surface_degrees(degree, order, lengths, net)?;
        compute(py, move || {
            Ok(by_dim!(data.points()?, |p| FuzzySurface::try_new(
                degree,
                rows(p, net),
                weights,
                knots
            )?
            .into()))
        })
    }

    /// The fuzzy control point ``P̃ᵢⱼ`` (row ``i`` along u, column ``j``
    /// along v): one ``FuzzyNumber`` per coordinate.
    fn point<'py>(
        &self, py: Python<'py>, i: &Obj<'py>, j: &Obj<'py>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let [nu, nv] = by_dim!(&self.0, |s| s.shape());
        let (i, j) = (
            index(keyword::int(i, "i")?, nu, "i")?,
            index(keyword::int(j, "j")?, nv, "j")?,
        );
        by_dim!(&self.0, |s| numbers(py, &s.points()[i * nv + j]))
    }

    /// The layer surface through one value of every control point, as a
    /// ``NurbsSurface`` (``"crisp"``: the crisp surface).
    fn layer_surface(&self, layer: &Obj<'_>) -> PyResult<PyNurbsSurface> {
        let l = self::layer(layer, "layer")?;
        Ok(by_dim!(&self.0, |s| s.layer_surface(l).into()))
    }

    /// The crisp rational B-spline surface through the crisp values.
    fn crisp_surface(&self) -> PyNurbsSurface {
        by_dim!(&self.0, |s| s.crisp_surface().into())
    }

    /// The point of every layer surface closest to ``point`` (see
    /// ``NurbsSurface.closest_point``), layers in the order of docs/method.md §1
    /// (``upper_left`` … ``upper_right``, ``crisp`` at index 3).
    ///
    /// Parameters
    /// ----------
    /// point : array_like, shape (dimension,) or (m, dimension)
    ///
    /// Returns
    /// -------
    /// (u, v, point, distance)
    ///     For one point: arrays ``(7,)``, ``(7,)``, ``(7, dimension)`` and
    ///     ``(7,)``; for ``m`` points: ``(m, 7)``, ``(m, 7)``,
    ///     ``(m, 7, dimension)`` and ``(m, 7)``.
    fn closest_points<'py>(&self, py: Python<'py>, point: &Obj<'py>) -> PyResult<ClosestArrays<'py>> {
        let [u, v, p, d] = by_dim!(&self.0, |s| capability::closest(py, s, point))?;
        Ok((u, v, p, d))
    }

    /// The curvature of every layer surface at every pair of ``u`` and ``v``
    /// (see ``NurbsSurface.curvature``), layers in the order of docs/method.md §1
    /// (``upper_left`` … ``upper_right``, ``crisp`` at index 3); each layer
    /// with its own normal. Unlike the points, the layers' curvatures are not
    /// ordered.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"gaussian"`` and ``"mean"``: shape ``broadcast(u, v).shape +
    ///     (7,)``; ``"principal"``: that ``+ (2,)``; ``"directions"``: that
    ///     ``+ (2, 3)``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a parameter outside its domain; where the normal of a layer
    ///     is undefined (the message names the layer); for a surface in the
    ///     plane.
    fn curvatures<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> DictResult<'py> {
        surface_curvature(py, &self.0, "curvatures", [u, v])
    }

    /// The derivatives of every layer surface at every pair of ``u`` and
    /// ``v`` (see ``NurbsSurface.derivatives``).
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``broadcast(u, v).shape + (7, order + 1, order + 1,
    ///     dimension)``, layers in the order of docs/method.md §1:
    ///     ``[..., i, k, l, :]`` is ``∂ᵏ⁺ˡS/∂uᵏ∂vˡ`` of layer ``i``; NaN where
    ///     ``k + l > order``.
    #[pyo3(signature = (u, v, order=None), text_signature = "($self, u, v, order=1)")]
    fn derivatives<'py>(
        &self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>, order: Option<&Obj<'py>>,
    ) -> ObjResult<'py> {
        by_dim!(&self.0, |s| capability::surface_derivatives(py, s, [u, v], order, self.dimension()))
    }

    /// The seven layer surfaces at every pair of ``u`` and ``v`` (broadcast
    /// as numpy does) by the straightforward evaluator (one rational basis
    /// for all layers); the reference that ``sample`` is tested against.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``broadcast(u, v).shape + (7, d)``, layers in the order of docs/method.md §1
    ///     (``upper_left`` … ``upper_right``, ``crisp`` at index 3).
    fn eval_layers<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |s| capability::surface_points(py, s, [u, v], self.dimension()))
    }

    /// ``surface(u, v)`` is ``surface.eval_layers(u, v)``: the seven layer
    /// surfaces, shape ``broadcast(u, v).shape + (7, d)``.
    fn __call__<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> ObjResult<'py> {
        self.eval_layers(py, u, v)
    }

    /// The seven layer surfaces on the grid ``u × v`` by the grid engine (one
    /// basis evaluation per grid row and column for all layers), the docs/method.md §1
    /// order of the layers kept exactly at every grid point.
    ///
    /// Parameters
    /// ----------
    /// u, v : int or array_like
    ///     Each a count of uniform parameters over its domain, or a 1-D array
    ///     of parameters in any order.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"u"`` and ``"v"``: the parameters, shapes ``(su,)`` and
    ///     ``(sv,)``; for each layer name (``"upper_left"`` …
    ///     ``"upper_right"``) the grid, shape ``(su, sv, d)``, views of one
    ///     ``(7, d, su, sv)`` array.
    fn sample<'py>(&self, py: Python<'py>, u: &Obj<'py>, v: &Obj<'py>) -> DictResult<'py> {
        let grid = GridArg::extract(u, v)?;
        // (layer, u, v, coordinate), seen through the engine's (layer,
        // coordinate, u, v).
        let d = self.dimension();
        let layers = by_dim!(&self.0, |s| grid.sample(py, [&[7], &[d]], |[u, v], out| s
            .sample_layers_into_slices(u, v, out)))?;
        let [u, v] = grid.arrays(py, self.domains())?;
        layer_dict(py, [("u", u), ("v", v)], &layers)
    }

    /// The membership grades of points in the fuzzy surface as a set
    /// (docs/method.md §10): for each membership function, the largest level
    /// at which some surface with its control points inside their cuts
    /// passes through the point; 0 where none does.
    ///
    /// Parameters
    /// ----------
    /// points : array_like, shape (..., d)
    ///     Any leading shape (a single point ``(d,)`` too), the coordinates
    ///     last.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"upper"``, ``"primary"``, ``"lower"``: arrays of the leading
    ///     shape ``(...)``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For another last dimension than ``d``, and NaN or infinity, naming
    ///     the index.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> x, y = np.meshgrid([0.0, 2.0], [0.0, 2.0], indexing="ij")
    /// >>> crisp = np.stack([x, y, 0 * x], axis=-1)        # the flat square
    /// >>> s = np.array([-1.0, 1.0])
    /// >>> flat = FuzzySurface(crisp, crisp[..., None] + s, crisp[..., None] + 0.5 * s,
    /// ...                     crisp[..., None] + 0.25 * s, lower_height=0.5, degree=1)
    /// >>> g = flat.membership([1.0, 1.0, 0.5])           # one point: arrays of shape ()
    /// >>> round(float(g["upper"]), 9), round(float(g["lower"]), 9)
    /// (0.5, 0.0)
    fn membership<'py>(&self, py: Python<'py>, points: &Obj<'py>) -> DictResult<'py> {
        crate::set::surface_membership(py, &self.0, points)
    }

    /// The fuzzy height at the location ``(x0, y0)`` of a surface in space
    /// (docs/method.md §10): at each level and for each membership function,
    /// the intervals of z where the vertical line meets the surface's
    /// region, ends accurate to about 1e-9 of the region's height; as
    /// ``t2spline section --at X0,Y0`` writes them.
    ///
    /// Parameters
    /// ----------
    /// x0, y0 : float
    /// levels : int or array_like, optional
    ///     A count of levels equally spaced from 0 to 1 (2 to 1001, default
    ///     11), or the levels themselves.
    ///
    /// Returns
    /// -------
    /// list of dict
    ///     As ``FuzzyCurve.section``, with intervals of z.
    #[pyo3(signature = (x0, y0, levels=None), text_signature = "($self, x0, y0, levels=11)")]
    fn section<'py>(
        &self, py: Python<'py>, x0: &Obj<'py>, y0: &Obj<'py>, levels: Option<&Obj<'py>>,
    ) -> PyResult<Bound<'py, pyo3::types::PyList>> {
        crate::set::surface_section(py, &self.0, x0, y0, levels)
    }

    /// The volumes between the surface and the plane ``z = datum`` (where
    /// it lies below and above), the plan area where it lies below, and the
    /// surface area, each as intervals over the nets whose heights lie in
    /// their cuts, per membership function and level (docs/method.md §14):
    /// the dict ``t2spline measure`` writes for a surface job. x and y must
    /// be crisp and the surface the graph of a height over its plan.
    ///
    /// Parameters
    /// ----------
    /// levels : int or array_like, optional
    ///     A count of levels equally spaced from 0 to 1 (2 to 51, default
    ///     11), or the levels themselves.
    /// datum : float, optional
    ///     The height of the plane (default 0).
    /// area : bool, optional
    ///     Whether to measure the surface area (default True).
    /// against : FuzzySurface, optional
    ///     A second surface of the same plan map (the same degrees, knots,
    ///     weights and crisp x and y; e.g. the last survey): adds ``"cut"``
    ///     and ``"fill"``, the volumes where this surface lies above and
    ///     below it, as ``t2spline measure --against`` writes them. A plan
    ///     that differs raises ``ValueError`` naming the difference.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"levels"``, ``"datum"``, ``"tolerance"``, ``"plan_area"``, and
    ///     per quantity (``"volume_below"``, ``"volume_above"``,
    ///     ``"plan_area_below"``, ``"area"``, and with ``against``
    ///     ``"cut"``, ``"fill"``) a list of levels per function.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> x, y = np.meshgrid([0.0, 2.0], [0.0, 2.0], indexing="ij")
    /// >>> crisp = np.stack([x, y, 1 + 0 * x], axis=-1)
    /// >>> s = np.array([0.0, 0.0, 1.0])[:, None] * np.array([-0.5, 0.5])
    /// >>> flat = FuzzySurface(crisp, crisp[..., None] + s, crisp[..., None] + 0.5 * s,
    /// ...                     crisp[..., None] + 0 * s, lower_height=1.0, degree=1)
    /// >>> m = flat.measure(levels=3)
    /// >>> [(round(l["min"], 9), round(l["max"], 9)) for l in m["volume_above"]["upper"]]
    /// [(2.0, 6.0), (3.0, 5.0), (4.0, 4.0)]
    #[pyo3(
        signature = (levels=None, datum=0.0, area=true, *, against=None),
        text_signature = "($self, levels=11, datum=0.0, area=True, *, against=None)"
    )]
    fn measure<'py>(
        &self,
        py: Python<'py>,
        levels: Option<&Obj<'py>>,
        datum: f64,
        area: bool,
        against: Option<PyRef<'py, PyFuzzySurface>>,
    ) -> ObjResult<'py> {
        let against = against.as_ref().map(|a| &a.0);
        crate::measure::surface_measure(py, &self.0, levels, datum, area, against)
    }

    /// The distance between the crisp surface and the defuzzified surface
    /// of the paper's type reduction at each level of ``alphas``, sampled on
    /// a uniform grid (docs/method.md §7), as ``FuzzyCurve.distance_sweep``:
    /// the grid's trapezoidal rule gives ``rms``.
    ///
    /// Parameters
    /// ----------
    /// alphas : float or array_like
    ///     The levels, each in [0, 1].
    /// samples : int or (int, int), optional
    ///     Uniform parameters along u and v (each at least 2, default 101).
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``"alpha"``, ``"max"``, ``"rms"``: ``(L,)``; ``"distance"``:
    ///     ``(L, su, sv)``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> x, y = np.meshgrid([0.0, 2.0], [0.0, 2.0], indexing="ij")
    /// >>> crisp = np.stack([x, y, 0 * x], axis=-1)
    /// >>> s = np.array([0.0, 0.0, 1.0])[:, None] * np.array([-1.0, 2.0])
    /// >>> flat = FuzzySurface(crisp, crisp[..., None] + s, crisp[..., None] + 0 * s,
    /// ...                     crisp[..., None] + 0 * s, lower_height=1.0, degree=1)
    /// >>> d = flat.distance_sweep(0.0, samples=(3, 4))
    /// >>> d["distance"].shape, round(float(d["rms"][0]), 12)
    /// ((1, 3, 4), 0.111111111111)
    #[pyo3(signature = (alphas, samples=None), text_signature = "($self, alphas, samples=101)")]
    fn distance_sweep<'py>(
        &self, py: Python<'py>, alphas: &Obj<'py>, samples: Option<&Obj<'py>>,
    ) -> DictResult<'py> {
        crate::distance_sweep::distance_sweep(py, &self.0, alphas, samples)
    }

    /// The picture in a notebook: stage 1 (the shaded crisp surface, the
    /// upper envelopes, the fuzzy net), drawn by the figure code of
    /// ``t2spline plot``, as inline SVG under a short table; a large surface
    /// is drawn on a thinned grid and the figure says so. ``None`` (no
    /// picture) for a surface in the plane.
    fn _repr_html_(&self) -> PyResult<Option<String>> {
        use crate::dim::ToModel as _;
        let Ok(model) = self.0.to_model() else {
            return Ok(None);
        };
        crate::picture::first_stage_page(model, &self.facts().rows()).map(Some)
    }

    fn __repr__(&self) -> String {
        self.facts().repr("FuzzySurface", None)
    }
}));
