//! `NurbsCurve`: a rational B-spline curve in the plane or in space (SPEC §6)
//! with the operations of the core: evaluation, derivatives, knot insertion,
//! degree elevation, splitting, arc length, closest point.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::{KnotVector, NurbsCurve};

use crate::arrays::{array, floats, optional_vector, rows_array, transposed, Floats};
use crate::construct::{count, degree};
use crate::dim::{by_dim, ByDim, Nurbs};
use crate::errors::compute;
use crate::sample::{at_params, channels, output_buffer, ParamsArg};

/// A rational B-spline curve (see the stub for the docs).
#[pyclass(frozen, eq, module = "t2spline", name = "NurbsCurve")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PyNurbsCurve(pub(crate) ByDim<Nurbs>);

impl From<NurbsCurve<2>> for PyNurbsCurve {
    fn from(curve: NurbsCurve<2>) -> Self {
        PyNurbsCurve(curve.into())
    }
}

impl From<NurbsCurve<3>> for PyNurbsCurve {
    fn from(curve: NurbsCurve<3>) -> Self {
        PyNurbsCurve(curve.into())
    }
}

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

/// The uniform parameters `tᵢ = a + (b − a)·i/(count − 1)` of a domain.
pub(crate) fn uniform_params<'py>(
    py: Python<'py>,
    domain: t2spline::Domain,
    count: i64,
) -> PyResult<Bound<'py, PyAny>> {
    let n = self::count(count, "count", 0)?;
    // The same bound as any sampling output, before allocating.
    let buffer = output_buffer(n, 1, "count")?;
    drop(buffer);
    array(py, domain.uniform(n), &[n])
}

#[pymethods]
impl PyNurbsCurve {
    #[new]
    #[pyo3(signature = (control_points, weights=None, knots=None, *, degree=None, order=None))]
    fn new(
        py: Python<'_>,
        control_points: &Bound<'_, PyAny>,
        weights: Option<&Bound<'_, PyAny>>,
        knots: Option<&Bound<'_, PyAny>>,
        degree: Option<i64>,
        order: Option<i64>,
    ) -> PyResult<Self> {
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

    #[getter]
    fn dimension(&self) -> usize {
        self.0.dimension()
    }

    #[getter]
    fn degree(&self) -> usize {
        by_dim!(&self.0, |c| c.degree())
    }

    #[getter]
    fn order(&self) -> usize {
        by_dim!(&self.0, |c| c.order())
    }

    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| rows_array(py, c.control_points().to_vec()))
    }

    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let w = by_dim!(&self.0, |c| c.weights().to_vec());
        let n = w.len();
        array(py, w, &[n])
    }

    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let k = by_dim!(&self.0, |c| c.knots().as_slice().to_vec());
        let n = k.len();
        array(py, k, &[n])
    }

    #[getter]
    fn domain(&self) -> (f64, f64) {
        let d = by_dim!(&self.0, |c| c.domain());
        (d.start, d.end)
    }

    fn uniform_params<'py>(&self, py: Python<'py>, count: i64) -> PyResult<Bound<'py, PyAny>> {
        uniform_params(py, by_dim!(&self.0, |c| c.domain()), count)
    }

    fn eval<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let d = self.dimension();
        by_dim!(&self.0, |c| at_params(py, t, &[d], |v, out| {
            out.extend(c.eval(v)?);
            Ok(())
        }))
    }

    fn sample<'py>(
        &self,
        py: Python<'py>,
        params: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let params = ParamsArg::extract(params, "params")?;
        let (n, d) = (params.len(), self.dimension());
        let mut buffer = output_buffer(n, d, "params")?;
        by_dim!(&self.0, |c| compute(py, || {
            c.sampler()
                .sample_into(params.params(), &mut channels(&mut buffer, d, n))
        }))?;
        // One row per coordinate: the (d, n) buffer seen as (n, d).
        transposed(&array(py, buffer, &[d, n])?, &[1, 0])
    }

    #[pyo3(signature = (t, order=1))]
    fn derivatives<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        order: i64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let order = count(order, "order", 0)?;
        let d = self.dimension();
        // The order is checked by the core before anything is computed.
        let rows = order.min(t2spline::nurbs::MAX_DERIVATIVE_ORDER) + 1;
        by_dim!(&self.0, |c| at_params(py, t, &[rows, d], |v, out| {
            out.extend(c.derivatives(v, order)?.into_iter().flatten());
            Ok(())
        }))
    }

    fn tangent<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let d = self.dimension();
        by_dim!(&self.0, |c| at_params(py, t, &[d], |v, out| {
            out.extend(c.tangent(v)?);
            Ok(())
        }))
    }

    fn curvature<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        by_dim!(&self.0, |c| at_params(py, t, &[], |v, out| {
            out.push(c.curvature(v)?);
            Ok(())
        }))
    }

    fn rational_basis<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let n = by_dim!(&self.0, |c| c.control_points().len());
        by_dim!(&self.0, |c| at_params(py, t, &[n], |v, out| {
            out.extend(c.rational_basis(v)?);
            Ok(())
        }))
    }

    #[pyo3(signature = (u, times=1))]
    fn insert_knot(&self, py: Python<'_>, u: f64, times: i64) -> PyResult<Self> {
        let times = count(times, "times", 1)?;
        by_dim!(&self.0, |c| compute(py, || Ok(c.insert_knot(u, times)?.into())))
    }

    fn refine_knots(&self, py: Python<'_>, knots: &Bound<'_, PyAny>) -> PyResult<Self> {
        let new = optional_vector(Some(knots), "knots")?.unwrap_or_default();
        by_dim!(&self.0, |c| compute(py, || Ok(c.refine_knots(&new)?.into())))
    }

    #[pyo3(signature = (times=1))]
    fn elevate_degree(&self, py: Python<'_>, times: i64) -> PyResult<Self> {
        let times = count(times, "times", 1)?;
        by_dim!(&self.0, |c| compute(py, || Ok(c.elevate_degree(times)?.into())))
    }

    fn split_at(&self, py: Python<'_>, t: f64) -> PyResult<(Self, Self)> {
        by_dim!(&self.0, |c| compute(py, || {
            let [a, b] = c.split_at(t)?;
            Ok((a.into(), b.into()))
        }))
    }

    fn segment(&self, py: Python<'_>, a: f64, b: f64) -> PyResult<Self> {
        by_dim!(&self.0, |c| compute(py, || Ok(c.segment(a, b)?.into())))
    }

    fn clamped(&self, py: Python<'_>) -> PyResult<Self> {
        by_dim!(&self.0, |c| compute(py, || Ok(c.clamped().into())))
    }

    #[pyo3(signature = (a=None, b=None))]
    fn arc_length(&self, py: Python<'_>, a: Option<f64>, b: Option<f64>) -> PyResult<f64> {
        by_dim!(&self.0, |c| compute(py, || match (a, b) {
            (None, None) => Ok(c.arc_length()),
            _ => {
                let d = c.domain();
                c.arc_length_between(a.unwrap_or(d.start), b.unwrap_or(d.end))
            }
        }))
    }

    fn param_at_length(&self, py: Python<'_>, length: f64) -> PyResult<f64> {
        by_dim!(&self.0, |c| compute(py, || c.param_at_length(length)))
    }

    fn closest_point<'py>(
        &self,
        py: Python<'py>,
        point: &Bound<'py, PyAny>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let d = self.dimension();
        let target = floats(point, "point")?;
        let many = match target.shape[..] {
            [k] if k == d => false,
            [_, k] if k == d => true,
            _ => {
                return Err(PyValueError::new_err(format!(
                    "point: expected shape ({d},) or (m, {d}), got {}",
                    crate::arrays::shape_text(&target.shape)
                )))
            }
        };
        let (t, points, distances) = by_dim!(&self.0, |c| compute(py, || {
            let found: Vec<_> = target
                .rows()
                .into_iter()
                .map(|p| c.closest_point(p))
                .collect();
            Ok((
                found.iter().map(|f| f.t).collect::<Vec<_>>(),
                found.iter().flat_map(|f| f.point).collect::<Vec<_>>(),
                found.iter().map(|f| f.distance).collect::<Vec<_>>(),
            ))
        }))?;
        if many {
            let m = t.len();
            Ok((array(py, t, &[m])?, array(py, points, &[m, d])?, array(py, distances, &[m])?))
        } else {
            Ok((
                t[0].into_pyobject(py)?.into_any(),
                array(py, points, &[d])?,
                distances[0].into_pyobject(py)?.into_any(),
            ))
        }
    }

    fn bounding_box<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let d = self.dimension();
        let (lo, hi) = by_dim!(&self.0, |c| compute(py, || {
            let b = c.bounding_box();
            Ok((b.min.to_vec(), b.max.to_vec()))
        }))?;
        Ok((array(py, lo, &[d])?, array(py, hi, &[d])?))
    }

    fn __repr__(&self) -> String {
        let (a, b) = self.domain();
        by_dim!(&self.0, |c| format!(
            "NurbsCurve(dimension={}, degree={}, order={}, control_points=({}, {}), knots=({},), domain=({a:?}, {b:?}))",
            self.dimension(),
            c.degree(),
            c.order(),
            c.control_points().len(),
            self.dimension(),
            c.knots().as_slice().len(),
        ))
    }
}
