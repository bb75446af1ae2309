//! The methods that `FuzzyCurve` and `FuzzySurface` share, written once:
//! reading a job's model, and the fuzzy numbers of the control points as
//! arrays of the net's shape (`(n, d)` for a curve, `(nu, nv, d)` for a
//! surface), with the feet of each number last.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use t2spline::Nt2Point;

use crate::number::PyFuzzyNumber;

/// The fuzzy numbers of `point` as a tuple, one per coordinate.
pub(crate) fn numbers<'py, const D: usize>(
    py: Python<'py>,
    point: &Nt2Point<D>,
) -> PyResult<Bound<'py, PyTuple>> {
    PyTuple::new(py, point.coords().iter().map(|&x| PyFuzzyNumber(x)))
}

/// An index from Python, in `0 .. count`.
///
/// # Errors
/// `ValueError` naming `name` and the range.
pub(crate) fn index(value: i64, count: usize, name: &str) -> PyResult<usize> {
    usize::try_from(value)
        .ok()
        .filter(|&i| i < count)
        .ok_or_else(|| {
            PyValueError::new_err(match count {
                0 => format!("{name}: {value} is outside the empty range"),
                _ => format!("{name}: {value} is outside [0, {}]", count - 1),
            })
        })
}

/// `fuzzy_methods!("kind", "net", Solved => then!(Class, … { methods }))`:
/// the methods of a fuzzy model whose control points form a net of shape
/// `(net)` (`"n"`, `"nu, nv"`) and whose stages 2–4 are a `Solved`, added to
/// `methods`, then handed to `then!` (`curve_methods!` or
/// `surface_methods!`), which writes the `#[pymethods]` block: `from_job`,
/// `to_job`,
/// `crisp`, `upper`, `primary`, `lower`, `lower_height`,
/// `layer_control_points`, `solve`.
macro_rules! fuzzy_methods {
    (
        $kind:literal, $net:literal, $solved:ident =>
        $then:ident!($class:ident $(, $extra:ident)* { $($own:tt)* })
    ) => {
        $then!($class $(, $extra)* {
            $($own)*

            /// Stages 2–4 at level ``alpha`` (docs/method.md §7, §8): alpha-cut, type
            /// reduction and defuzzification of every control point, as a
            /// ``Solution`` (of a curve) or a ``SurfaceSolution`` (of a
            /// surface).
            ///
            /// Parameters
            /// ----------
            /// alpha : float, optional
            ///     The level in ``[0, 1]``; needed by the paper's type reduction
            ///     only. The others read the whole number: stage 2 is cut at
            ///     alpha = 0, and an alpha given anyway is checked and set aside
            ///     with a ``UserWarning``, as ``run`` does.
            /// type_reduction : {"paper", "centroid", "nie-tan", "alpha-planes"}, optional
            ///     The type reduction of stages 3–4 (docs/method.md §9), default
            ///     ``"paper"``.
            ///
            /// Raises
            /// ------
            /// ValueError
            ///     If ``alpha`` is NaN or outside ``[0, 1]``, missing for the
            ///     paper's reduction, or ``type_reduction`` is unknown.
            #[pyo3(signature = (alpha=None, type_reduction=None))]
            fn solve(
                &self,
                py: Python<'_>,
                alpha: Option<&Bound<'_, PyAny>>,
                type_reduction: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<$solved> {
                let alpha = $crate::keyword::opt_real(alpha, "alpha")?;
                let type_reduction = $crate::keyword::opt_text(type_reduction, "type_reduction")?;
                let (a, reduction) =
                    $crate::reduction::solve_settings(py, alpha, type_reduction.as_deref())?;
                $crate::dim::by_dim!(&self.0, |c| $crate::errors::compute(py, || Ok(c
                    .solve_with(a, reduction)
                    .into())))
            }

            #[doc = concat!("The fuzzy ", $kind, " of a job: a dict with the keys of a job file, or the")]
            /// path of one (validated as by ``t2spline run``).
            ///
            /// Raises
            /// ------
            /// JobError
            ///     For a job that breaks the rules; ``ValueError`` for a job
            #[doc = concat!("    of another kind of model than a ", $kind, ".")]
            #[staticmethod]
            fn from_job(job: &Bound<'_, PyAny>) -> PyResult<Self> {
                let (model, source) = $crate::run::job_model(job)?;
                $crate::dim::FromModel::from_model(model).map(Self).ok_or_else(|| {
                    pyo3::exceptions::PyValueError::new_err(format!(
                        concat!("{}: the job is not a ", $kind),
                        source
                    ))
                })
            }

            #[doc = concat!("The job of this fuzzy ", $kind, ": a dict with the keys of a job file")]
            /// (docs/jobs.md) in their canonical form (explicit weights, knots and
            /// type reduction, every number with its own ``lower_height``), that
            /// ``run`` and ``t2spline run`` (after ``json.dump``) run to the same
            /// numbers, and ``from_job`` reads back to an equal object.
            ///
            /// Parameters
            /// ----------
            /// alpha : float, optional
            ///     The level alpha of the job; without it, a run of the paper's type
            ///     reduction needs one (``alpha=``, ``--alpha``).
            /// samples : int or (int, int), optional
            ///     The job's samples (default 101 along a curve, 21 × 21 on a surface).
            /// type_reduction : {"paper", "centroid", "nie-tan", "alpha-planes"}, optional
            ///     The job's type reduction (default ``"paper"``).
            /// description : str, optional
            ///     Free text carried to the result.
            #[pyo3(signature = (alpha=None, *, samples=None, type_reduction=None, description=None))]
            fn to_job<'py>(
                &self,
                py: Python<'py>,
                alpha: Option<&Bound<'py, PyAny>>,
                samples: Option<&Bound<'py, PyAny>>,
                type_reduction: Option<&Bound<'py, PyAny>>,
                description: Option<&Bound<'py, PyAny>>,
            ) -> PyResult<Bound<'py, PyAny>> {
                $crate::job_dict::job_dict(
                    py,
                    $crate::dim::ToModel::to_model(&self.0)?,
                    alpha,
                    samples,
                    type_reduction,
                    description,
                )
            }

            #[doc = concat!("The crisp values, shape ``(", $net, ", d)``.")]
            #[getter]
            fn crisp<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.per_number(py, &[], |x, v| v.push(x.crisp()))
            }

            #[doc = concat!("The upper feet ``[left, right]``, shape ``(", $net, ", d, 2)``.")]
            #[getter]
            fn upper<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.per_number(py, &[2], |x, v| v.extend([x.upper().left(), x.upper().right()]))
            }

            #[doc = concat!("The primary feet ``[left, right]``, shape ``(", $net, ", d, 2)``.")]
            #[getter]
            fn primary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.per_number(py, &[2], |x, v| {
                    v.extend([x.primary().left(), x.primary().right()]);
                })
            }

            #[doc = concat!("The lower feet ``[left, right]``, shape ``(", $net, ", d, 2)``.")]
            #[getter]
            fn lower<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.per_number(py, &[2], |x, v| v.extend([x.lower().left(), x.lower().right()]))
            }

            #[doc = concat!("The lower height of every number, shape ``(", $net, ", d)``.")]
            #[getter]
            fn lower_height<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                self.per_number(py, &[], |x, v| v.push(x.height().get()))
            }

            #[doc = concat!("The values of one layer at every control point, shape ``(", $net, ", d)``.")]
            fn layer_control_points<'py>(
                &self,
                py: Python<'py>,
                layer: &Bound<'py, PyAny>,
            ) -> PyResult<Bound<'py, PyAny>> {
                let l = $crate::construct::layer(layer, "layer")?;
                $crate::dim::by_dim!(&self.0, |c| $crate::net::points_array(
                    py,
                    c.points().iter().map(|p| p.layer(l)).collect(),
                    &$crate::net::Net::net(c),
                ))
            }
        });

        impl $class {
            /// One value per control point and coordinate, `f(number)` each.
            fn per_number<'py>(
                &self,
                py: Python<'py>,
                tail: &[usize],
                f: impl Fn(&t2spline::Nt2Number, &mut Vec<f64>),
            ) -> PyResult<Bound<'py, PyAny>> {
                $crate::dim::by_dim!(&self.0, |c| $crate::net::per_number(
                    py,
                    c.points(),
                    &$crate::net::Net::net(c),
                    tail,
                    &f
                ))
            }
        }
    };
}

pub(crate) use fuzzy_methods;
