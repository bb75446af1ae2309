//! `NurbsCurve`: a rational B-spline curve in the plane or in space (docs/method.md §6)
//! with the operations of the core: evaluation, derivatives, knot insertion,
//! degree elevation, splitting, arc length, closest point.

use pyo3::prelude::*;
use t2spline::{KnotVector, NurbsCurve};

use crate::arrays::{floats, optional_vector, rows_array, Floats};
use crate::capability;
use crate::classes::PyNurbsCurve;
use crate::construct::degree;
use crate::curve_methods::curve_methods;
use crate::dim::by_dim;
use crate::errors::compute;
use crate::keyword;
use crate::py_types::{Obj, ObjResult, Pair, Triple};
use crate::sample::{at_params, ParamsArg};

/// A curve of dimension `D` through the rows of `points`.
fn build<const D: usize>(
    points: &Floats,
    weights: Vec<f64>,
    knots: Option<Vec<f64>>,
    degree: usize,
) -> Result<NurbsCurve<D>, t2spline::Error> {
    let rows = points.rows::<D>();
    match knots {
        Some(k) => {
            let knots = KnotVector::try_new(k, degree, rows.len())?;
            NurbsCurve::try_new(rows, weights, knots)
        }
        None => NurbsCurve::try_clamped(degree, rows, weights),
    }
}

curve_methods!(PyNurbsCurve {

    /// Pickling and copying: the constructor with ``(control_points, weights, knots)``
    /// (the degree following from the knots), an equal object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        crate::pickle::by_constructor(slf, &["control_points", "weights", "knots"])
    }
    #[new]
    #[pyo3(signature = (control_points, weights=None, knots=None, *, degree=None, order=None))]
    fn new(
        py: Python<'_>,
        control_points: &Obj<'_>,
        weights: Option<&Obj<'_>>,
        knots: Option<&Obj<'_>>,
        degree: Option<&Obj<'_>>,
        order: Option<&Obj<'_>>,
    ) -> PyResult<Self> {
        let (degree, order) = (
            keyword::opt_int(degree, "degree")?,
            keyword::opt_int(order, "order")?,
        );
        let points = floats(control_points, "control_points")?;
        let (n, d) = points.points_shape("control_points")?;
        let weights = optional_vector(weights, "weights")?.unwrap_or_else(|| vec![1.0; n]);
        let knots = optional_vector(knots, "knots")?;
        let degree = self::degree(degree, order, knots.as_ref().map(Vec::len), n)?;
        compute(py, move || {
            Ok(match d {
                2 => build::<2>(&points, weights, knots, degree)?.into(),
                _ => build::<3>(&points, weights, knots, degree)?.into(),
            })
        })
    }

    /// The control points, shape ``(n, dimension)``.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |c| rows_array(py, c.control_points().to_vec()))
    }

    /// The point ``C(t)`` at every value of ``t``, by the straightforward
    /// evaluator (the rational basis at ``t``); ``sample`` is the fast
    /// engine for many parameters.
    ///
    /// Parameters
    /// ----------
    /// t : float or array_like
    ///     Parameters in the domain, any shape.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``t.shape + (dimension,)``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a parameter outside the domain (``parameter t = 2 is outside
    ///     the domain [0, 1]``), NaN or infinity.
    fn eval<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |c| capability::curve_points(py, c, t, self.dimension()))
    }

    /// ``curve(t)`` is ``curve.eval(t)`` (as splipy's curves are called).
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> line = NurbsCurve(np.array([[0.0, 0.0], [2.0, 4.0]]), degree=1)
    /// >>> line(0.25).tolist(), line([0.0, 1.0]).shape
    /// ([0.5, 1.0], (2, 2))
    fn __call__<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        self.eval(py, t)
    }

    /// The curve at many parameters by the sampling engine (one power form of
    /// the rational basis per knot span, multi-threaded for large jobs); agrees
    /// with ``eval`` to rounding.
    ///
    /// Parameters
    /// ----------
    /// params : int or array_like
    ///     A count of uniform parameters (``uniform_params(count)``), or a 1-D
    ///     array of parameters in any order (sorted ones are fastest).
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``(len(params), dimension)``; each coordinate is contiguous
    ///     (the engine's structure of arrays, seen through a transpose).
    fn sample<'py>(&self, py: Python<'py>, params: &Obj<'py>) -> ObjResult<'py> {
        let params = ParamsArg::extract(params, "params")?;
        // One row per coordinate: the (d, n) buffer seen as (n, d).
        let d = self.dimension();
        by_dim!(&self.0, |c| params.sample(py, [&[], &[d]], |t, out| c.sampler().sample_into(t, out)))
    }

    /// The derivatives ``C⁽ʲ⁾(t)``, ``j = 0 … order``, at every value of ``t``
    /// (The NURBS Book A3.2 and A4.2); one-sided at knots, as ``eval``.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``t.shape + (order + 1, dimension)``; ``[..., 0, :]`` is the
    ///     point itself.
    ///
    /// Examples
    /// --------
    /// >>> line = NurbsCurve([[0, 0], [3, 4]], degree=1)
    /// >>> line.derivatives(0.5, order=2).tolist()
    /// [[1.5, 2.0], [3.0, 4.0], [0.0, 0.0]]
    #[pyo3(signature = (t, order=None), text_signature = "($self, t, order=1)")]
    fn derivatives<'py>(
        &self, py: Python<'py>, t: &Obj<'py>, order: Option<&Obj<'py>>,
    ) -> ObjResult<'py> {
        by_dim!(&self.0, |c| capability::curve_derivatives(py, c, t, order, self.dimension()))
    }

    /// The unit tangent ``C'(t)/|C'(t)|`` at every value of ``t``; shape
    /// ``t.shape + (dimension,)``.
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     Where the curve has zero speed.
    fn tangent<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        let d = self.dimension();
        by_dim!(&self.0, |c| at_params(py, t, &[d], |v, out| {
            out.extend(c.tangent(v)?);
            Ok(())
        }))
    }

    /// The curvature ``|C' × C''| / |C'|³`` at every value of ``t``: a float for
    /// a number, else an array of the shape of ``t``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np
    /// >>> arc = NurbsCurve([[1, 0], [1, 1], [0, 1]], weights=[1, np.sqrt(0.5), 1], degree=2)
    /// >>> bool(np.allclose(arc.curvature([0.0, 0.3, 1.0]), 1.0))   # the unit circle
    /// True
    fn curvature<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        by_dim!(&self.0, |c| capability::curve_curvature(py, c, t))
    }

    /// The rational basis ``Rᵢ(t) = wᵢNᵢ,ₚ(t) / Σⱼ wⱼNⱼ,ₚ(t)`` of every control
    /// point at every value of ``t``: non-negative, summing to 1; shape
    /// ``t.shape + (n,)``.
    fn rational_basis<'py>(&self, py: Python<'py>, t: &Obj<'py>) -> ObjResult<'py> {
        let n = by_dim!(&self.0, |c| c.control_points().len());
        by_dim!(&self.0, |c| at_params(py, t, &[n], |v, out| {
            out.extend(c.rational_basis(v)?);
            Ok(())
        }))
    }

    /// The same curve with a clamped knot vector (end knots repeated
    /// ``order`` times), so that it starts and ends at control points.
    fn clamped(&self, py: Python<'_>) -> PyResult<Self> {
        by_dim!(&self.0, |c| compute(py, || Ok(c.clamped().into())))
    }

    /// The length of the curve between ``a`` and ``b`` (default: the whole
    /// domain), by adaptive Gauss–Kronrod 7/15 quadrature of ``|C'(t)|`` per
    /// knot span (tolerance 1e-10 relative).
    #[pyo3(signature = (a=None, b=None))]
    fn arc_length(
        &self, py: Python<'_>, a: Option<&Obj<'_>>, b: Option<&Obj<'_>>,
    ) -> PyResult<f64> {
        let (a, b) = (keyword::opt_real(a, "a")?, keyword::opt_real(b, "b")?);
        by_dim!(&self.0, |c| compute(py, || match (a, b) {
            (None, None) => Ok(c.arc_length()),
            _ => {
                let d = c.domain();
                c.arc_length_between(a.unwrap_or(d.start), b.unwrap_or(d.end))
            }
        }))
    }

    /// The parameter at which the arc length from the start of the domain is
    /// ``length`` (Newton's method safeguarded by bisection).
    fn param_at_length(&self, py: Python<'_>, length: &Obj<'_>) -> PyResult<f64> {
        let length = keyword::real(length, "length")?;
        by_dim!(&self.0, |c| compute(py, || c.param_at_length(length)))
    }

    /// The point of the curve closest to ``point`` (The NURBS Book §6.1:
    /// sampling per span, Newton's method, golden-section search as a
    /// fallback).
    ///
    /// Parameters
    /// ----------
    /// point : array_like, shape (dimension,) or (m, dimension)
    ///
    /// Returns
    /// -------
    /// (t, point, distance)
    ///     For one point: a float, an array ``(dimension,)`` and a float; for
    ///     ``m`` points: arrays ``(m,)``, ``(m, dimension)`` and ``(m,)``.
    fn closest_point<'py>(&self, py: Python<'py>, point: &Obj<'py>) -> PyResult<Triple<'py>> {
        let [t, p, d] = by_dim!(&self.0, |c| capability::closest(py, c, point))?;
        Ok((t, p, d))
    }

    /// The tight axis-aligned box of the curve ``(min, max)``, each of shape
    /// ``(dimension,)`` (from the roots of each coordinate's derivative).
    fn bounding_box<'py>(&self, py: Python<'py>) -> PyResult<Pair<'py>> {
        by_dim!(&self.0, |c| capability::bounding_box(py, c))
    }

    /// The picture in a notebook: the curve and its control polygon, drawn
    /// by the figure code of ``t2spline plot`` (stage 1 of the fuzzy curve
    /// whose every number is crisp), as inline SVG under a short table.
    fn _repr_html_(&self) -> PyResult<String> {
        use crate::dim::ToModel as _;
        let fuzzy: crate::dim::ByDim<crate::dim::Fuzzy> =
            by_dim!(&self.0, |c| crate::picture::crisp_fuzzy_curve(c)?.into());
        crate::picture::crisp_page(fuzzy.to_model()?, "NURBS curve", &self.facts().rows())
    }

    fn __repr__(&self) -> String {
        let knots = by_dim!(&self.0, |c| c.knots().as_slice().len());
        self.facts().repr("NurbsCurve", Some(knots))
    }
});
