//! `t2spline.centroid`: the centroid of an interval type-2 set given by
//! samples (`t2spline::reduction::discrete`); the `type_reduction=` keyword
//! read as the core's `TypeReduction`, and the level alpha that `run` and
//! `solve` settle with it (an alpha the reduction does not use is checked,
//! set aside and warned about).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use t2spline::job::{AlphaNote, ALPHA_IGNORED};
use t2spline::reduction::discrete::{SampledCentroid, SampledSet};
use t2spline::{Alpha, TypeReduction};

use crate::arrays::{floats, shape_text, Floats};
use crate::errors::{compute, core_error};
use crate::keyword;

/// `type_reduction=`: one of [`TypeReduction::name`], else a `ValueError`
/// naming the keyword and the known names.
pub(crate) fn type_reduction(name: Option<&str>) -> PyResult<Option<TypeReduction>> {
    name.map(|s| {
        s.parse::<TypeReduction>()
            .map_err(|e| PyValueError::new_err(format!("type_reduction: {e}")))
    })
    .transpose()
}

/// Says with a `UserWarning` that `reduction` does not use the alpha
/// `given` by `alpha=`, as ``t2spline run`` says it on standard error
/// ([`AlphaNote::sentence`]).
///
/// # Errors
/// The error of the warning filter (warnings turned into errors).
pub(crate) fn warn_unused_alpha(
    py: Python<'_>,
    reduction: TypeReduction,
    given: Alpha,
) -> PyResult<()> {
    let note = AlphaNote::Unused {
        reduction,
        alpha: given,
    };
    warn(py, &note.sentence("alpha=", ALPHA_IGNORED))
}

/// A `UserWarning` saying `message`.
///
/// # Errors
/// The warning itself, under ``-W error``.
pub(crate) fn warn(py: Python<'_>, message: &str) -> PyResult<()> {
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    PyErr::warn(py, &category, &std::ffi::CString::new(message)?, 1)
}

/// The level and the type reduction of `solve(alpha, type_reduction)`, as
/// `run` settles them (`Job::settings`): the paper's reduction (the default)
/// needs alpha; the others cut stage 2 at alpha = 0, and an alpha given to
/// them is checked and set aside with a `UserWarning`.
///
/// # Errors
/// `ValueError` for an unknown reduction, an alpha outside `[0, 1]` (or
/// NaN), or no alpha for the paper's reduction; the error of the warning
/// filter.
pub(crate) fn solve_settings(
    py: Python<'_>,
    alpha: Option<f64>,
    type_reduction: Option<&str>,
) -> PyResult<(Alpha, TypeReduction)> {
    let reduction = self::type_reduction(type_reduction)?.unwrap_or_default();
    let given = alpha.map(Alpha::try_new).transpose().map_err(core_error)?;
    match (reduction.uses_alpha(), given) {
        (true, Some(a)) => Ok((a, reduction)),
        (true, None) => Err(PyValueError::new_err(
            "alpha: missing: the paper's type reduction needs the level alpha",
        )),
        (false, given) => {
            if let Some(a) = given {
                warn_unused_alpha(py, reduction, a)?;
            }
            Ok((Alpha::ZERO, reduction))
        }
    }
}

/// A one-dimensional argument of `centroid`.
fn samples(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<Floats> {
    let a = floats(arg, name)?;
    if a.shape.len() != 1 {
        return Err(PyValueError::new_err(format!(
            "{name}: expected a one-dimensional array of samples, got shape {}",
            shape_text(&a.shape)
        )));
    }
    Ok(a)
}

/// The centroid ``[c_l, c_r]`` of an interval type-2 fuzzy set given by
/// samples: its lower and upper membership functions ``lmf`` and ``umf`` at
/// points ``x`` (docs/method.md §9). The centroid is the range of the centroids of
/// every type-1 set between ``lmf`` and ``umf``::
///
///     c_l = min over switch points k of  Σ_{i≤k} xᵢ·umfᵢ + Σ_{i>k} xᵢ·lmfᵢ
///                                        ─────────────────────────────────
///                                          Σ_{i≤k} umfᵢ  + Σ_{i>k} lmfᵢ
///
/// and ``c_r`` the maximum with ``lmf`` and ``umf`` exchanged.
///
/// Parameters
/// ----------
/// x : array_like, shape (n,)
///     The sample points, not decreasing.
/// lmf, umf : array_like, shape (n,)
///     The lower and upper membership at each point, ``0 <= lmf <= umf``,
///     some ``umf > 0``.
/// method : {"km", "ekm", "eiasc", "nie-tan"}
///     Karnik–Mendel (2001), enhanced Karnik–Mendel (Wu and Mendel 2009) or
///     the enhanced iterative algorithm with stop condition (Wu and Nie
///     2011): the same exact discrete centroid, found with different numbers
///     of iterations. ``"nie-tan"`` (Nie and Tan 2008) is the centroid of
///     ``(lmf + umf)/2``, one value: ``left``, ``right`` and ``defuzzified``
///     are all that value.
///
/// Returns
/// -------
/// dict
///     ``left`` (``c_l``), ``right`` (``c_r``), ``defuzzified``
///     (``(c_l + c_r)/2``) and ``iterations``, the switch points tried for
///     each end as ``(left, right)`` (``(0, 0)`` for ``"nie-tan"``).
///
/// Raises
/// ------
/// ValueError
///     For arrays of different lengths, a decreasing ``x``, ``lmf < 0``,
///     ``lmf > umf`` or no ``umf > 0``, naming the index; for an unknown
///     method.
///
/// Examples
/// --------
/// >>> c = centroid([1.0, 2.0, 3.0], [0.2, 0.5, 0.2], [0.6, 1.0, 0.6], method="ekm")
/// >>> round(c["left"] * 13, 12), round(c["right"] * 13, 12)
/// (22.0, 30.0)
/// >>> c["defuzzified"]
/// 2.0
/// >>> centroid([0.0, 1.0], [0.0, 0.5], [1.0, 1.0], method="nie-tan")["left"]
/// 0.6
#[pyfunction]
#[pyo3(signature = (x, lmf, umf, method=None), text_signature = "(x, lmf, umf, method='km')")]
pub(crate) fn centroid<'py>(
    py: Python<'py>,
    x: &Bound<'py, PyAny>,
    lmf: &Bound<'py, PyAny>,
    umf: &Bound<'py, PyAny>,
    method: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let method = keyword::opt_text(method, "method")?;
    // `None`: Nie–Tan, one value and no iterations.
    let algorithm: Option<fn(&SampledSet<'_>) -> SampledCentroid> =
        match method.as_deref().unwrap_or("km") {
            "km" => Some(|s| s.km()),
            "ekm" => Some(|s| s.ekm()),
            "eiasc" => Some(|s| s.eiasc()),
            "nie-tan" => None,
            other => {
                return Err(PyValueError::new_err(format!(
                    "method: unknown method `{other}` (known: km, ekm, eiasc, nie-tan)"
                )))
            }
        };
    let (x, lmf, umf) = (samples(x, "x")?, samples(lmf, "lmf")?, samples(umf, "umf")?);
    let (left, right, defuzzified, iterations) = compute(py, move || {
        let set = SampledSet::try_new(&x.data, &lmf.data, &umf.data)?;
        Ok(match algorithm {
            Some(algorithm) => {
                let c = algorithm(&set);
                let i = c.iterations();
                (c.left(), c.right(), c.defuzzified(), (i.left, i.right))
            }
            None => {
                let v = set.nie_tan();
                (v, v, v, (0, 0))
            }
        })
    })?;
    let d = PyDict::new(py);
    d.set_item("left", left)?;
    d.set_item("right", right)?;
    d.set_item("defuzzified", defuzzified)?;
    d.set_item("iterations", iterations)?;
    Ok(d)
}
