//! The methods that `NurbsCurve` and `FuzzyCurve` share, written once: the
//! core's `NurbsCurve<D>` and `FuzzyCurve<D>` have the same accessors and the
//! same operations (a fuzzy curve applies them to its seven layers at once),
//! so one body serves both classes.

use pyo3::prelude::*;
use t2spline::Domain;

use crate::arrays::array;
use crate::construct::count;
use crate::errors::core_error;
use crate::keyword;
use crate::sample::check_output;

/// The uniform parameters `tᵢ = a + (b − a)·i/(count − 1)` of a domain;
/// errors name the argument `name`.
pub(crate) fn uniform_params<'py>(
    py: Python<'py>,
    domain: Domain,
    count: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let n = self::count(keyword::int(count, name)?, name, 0)?;
    check_output(n, 1, name)?;
    array(py, domain.uniform(n).map_err(core_error)?, &[n])
}

/// `curve_methods!(Class { methods })`: the `#[pymethods]` block of `Class`
/// (a wrapper of a `ByDim` of curves) with its own `methods` and the shared
/// ones: `dimension`, `degree`, `order`, `weights`, `knots`, `domain`,
/// `uniform_params`, `insert_knot`, `refine_knots`, `elevate_degree`,
/// `split_at`, `segment`.
macro_rules! curve_methods {
    ($class:ident { $($own:tt)* }) => {
        #[pyo3::pymethods]
        impl $class {
            $($own)*

            /// The number of coordinates of a point: 2 or 3.
            #[getter]
            fn dimension(&self) -> usize {
                self.0.dimension()
            }

            /// The degree ``p``.
            #[getter]
            fn degree(&self) -> usize {
                $crate::dim::by_dim!(&self.0, |c| c.degree())
            }

            /// The order ``k = p + 1``.
            #[getter]
            fn order(&self) -> usize {
                $crate::dim::by_dim!(&self.0, |c| c.order())
            }

            /// The weights, shape ``(n,)``.
            #[getter]
            fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                let w = $crate::dim::by_dim!(&self.0, |c| c.weights().to_vec());
                let n = w.len();
                $crate::arrays::array(py, w, &[n])
            }

            /// The knot vector, shape ``(n + order,)`` (the default made explicit).
            #[getter]
            fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                let k = $crate::dim::by_dim!(&self.0, |c| c.knots().as_slice().to_vec());
                let n = k.len();
                $crate::arrays::array(py, k, &[n])
            }

            /// The parameter domain ``(U[p], U[n])``.
            #[getter]
            fn domain(&self) -> (f64, f64) {
                let d = $crate::dim::by_dim!(&self.0, |c| c.domain());
                (d.start, d.end)
            }

            /// ``count`` uniform parameters over the domain (docs/jobs.md)::
            ///
            ///     tᵢ = a + (b − a)·i/(count − 1),   i = 0 … count − 1, the last exactly b
            ///
            /// the parameters of ``sample(count)``.
            fn uniform_params<'py>(
                &self,
                py: Python<'py>,
                count: &Bound<'py, PyAny>,
            ) -> PyResult<Bound<'py, PyAny>> {
                let domain = $crate::dim::by_dim!(&self.0, |c| c.domain());
                $crate::curve_methods::uniform_params(py, domain, count, "count")
            }

            /// The same curve with the knot ``t`` inserted ``times`` times
            /// (Boehm, The NURBS Book A5.1). A fuzzy curve inserts it into
            /// all seven layers at once; their order holds exactly.
            ///
            /// Raises
            /// ------
            /// ValueError
            ///     If ``t`` is outside the domain or would repeat more than
            ///     ``order`` times; for a fuzzy curve, when a coordinate mixes
            ///     lower heights (new control points need one height per
            ///     coordinate).
            ///
            /// Examples
            /// --------
            /// >>> c = NurbsCurve([[0, 0], [1, 2], [3, 2], [4, 0]], degree=2)
            /// >>> d = c.insert_knot(0.3)
            /// >>> d.control_points.shape, bool(abs(d.eval(0.7) - c.eval(0.7)).max() < 1e-14)
            /// ((5, 2), True)
            #[pyo3(signature = (t=None, times=None, *, u=None), text_signature = "($self, t, times=1)")]
            fn insert_knot(
                &self,
                py: Python<'_>,
                t: Option<&Bound<'_, PyAny>>,
                times: Option<&Bound<'_, PyAny>>,
                u: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<Self> {
                let at = match (t, u) {
                    (Some(_), Some(_)) => {
                        return Err(pyo3::exceptions::PyTypeError::new_err(
                            "insert_knot: t and u name the same argument; give t",
                        ))
                    }
                    (None, Some(u)) => {
                        $crate::directed::deprecated(py, "insert_knot(u=…)", "insert_knot(t=…)")?;
                        $crate::keyword::real(u, "t")?
                    }
                    (Some(t), None) => $crate::keyword::real(t, "t")?,
                    (None, None) => {
                        return Err(pyo3::exceptions::PyTypeError::new_err(
                            "insert_knot: missing the argument t",
                        ))
                    }
                };
                let op = $crate::knot_ops::KnotOp::Insert(at, $crate::keyword::times(times)?);
                let [c] = $crate::knot_ops::apply(py, &self.0, (), op)?;
                Ok(Self(c))
            }

            /// The same curve with all of ``knots`` inserted (knot
            /// refinement, The NURBS Book A5.4); a fuzzy curve on all layers.
            fn refine_knots(&self, py: Python<'_>, knots: &Bound<'_, PyAny>) -> PyResult<Self> {
                let new = $crate::arrays::optional_vector(Some(knots), "knots")?
                    .unwrap_or_default();
                let op = $crate::knot_ops::KnotOp::Refine(&new);
                let [c] = $crate::knot_ops::apply(py, &self.0, (), op)?;
                Ok(Self(c))
            }

            /// The same curve of degree ``degree + times`` (The NURBS Book
            /// A5.9; an unclamped curve is first cut to its domain); a fuzzy
            /// curve on all layers.
            #[pyo3(signature = (times=None), text_signature = "($self, times=1)")]
            fn elevate_degree(&self, py: Python<'_>, times: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
                let op = $crate::knot_ops::KnotOp::Elevate($crate::keyword::times(times)?);
                let [c] = $crate::knot_ops::apply(py, &self.0, (), op)?;
                Ok(Self(c))
            }

            /// The two curves left and right of ``t``, strictly inside the
            /// domain, with domains ``(a, t)`` and ``(t, b)``.
            fn split_at(&self, py: Python<'_>, t: &Bound<'_, PyAny>) -> PyResult<(Self, Self)> {
                let op = $crate::knot_ops::KnotOp::Split($crate::keyword::real(t, "t")?);
                let [a, b] = $crate::knot_ops::apply(py, &self.0, (), op)?;
                Ok((Self(a), Self(b)))
            }

            /// The piece of the curve over ``[a, b]``, as a curve of its own.
            fn segment(
                &self,
                py: Python<'_>,
                a: &Bound<'_, PyAny>,
                b: &Bound<'_, PyAny>,
            ) -> PyResult<Self> {
                let (a, b) = ($crate::keyword::real(a, "a")?, $crate::keyword::real(b, "b")?);
                $crate::dim::by_dim!(&self.0, |c| $crate::errors::compute(py, || Ok(c
                    .segment(a, b)?
                    .into())))
            }
        }

        impl $class {
            /// What its descriptions say (`__repr__`, `_repr_html_`).
            fn facts(&self) -> $crate::describe::CurveFacts {
                let (dimension, domain) = (self.0.dimension(), self.domain());
                $crate::dim::by_dim!(&self.0, |c| $crate::describe::CurveFacts {
                    dimension,
                    degree: c.degree(),
                    points: c.weights().len(),
                    domain,
                })
            }
        }
    };
}

pub(crate) use curve_methods;
