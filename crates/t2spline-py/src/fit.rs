//! `t2spline.fit`: fuzzy data points given as arrays → a `FuzzyCurve` and a
//! summary of the fit, by the core's `FuzzyData::fit` (the fit of
//! `t2spline fit`).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use t2spline::fit::{Deviation, FitOptions, FitSummary, FuzzyData, FuzzyFitMode, Parametrization};
use t2spline::{Layer, Layers};

use crate::classes::PyFuzzyCurve;
use crate::construct::{degree, FuzzyArrays};
use crate::dim::{ByDim, FromModel};
use crate::errors::compute;
use crate::keyword;

/// Fits a fuzzy curve to fuzzy data points (``t2spline fit``): interpolation
/// (The NURBS Book §9.2.1) or least squares with the end points interpolated
/// (§9.4.1), one parametrization and one knot vector for all seven layers.
///
/// With ``mode="valid"`` (the default) the crisp values are fitted and the
/// spreads as nested non-negative increments (non-negative least squares,
/// from the lower spreads outwards), so the control points are always valid
/// fuzzy numbers; with ``"independent"`` each layer is fitted on its own, and
/// a fit whose control points break the order of docs/method.md §1 is an error.
///
/// Parameters
/// ----------
/// crisp, upper, primary, lower, lower_height
///     The data points, as for ``FuzzyCurve``: ``(m, d)``, ``(m, d, 2)`` and a
///     height per number or for all.
/// degree : int
///     The degree ``p >= 1``.
/// control_points : int, optional
///     Least squares with this many control points (``p + 1`` … ``m``);
///     default: interpolation, one per data point.
/// parametrization : {'chord', 'centripetal', 'uniform'}
///     How the data get their parameters (The NURBS Book Eqs. 9.3–9.6).
/// mode : {'valid', 'independent'}
///
/// Returns
/// -------
/// (FuzzyCurve, dict)
///     The curve and a summary: ``data_points``, ``control_points``, ``mode``,
///     ``condition`` (estimated condition number of the system),
///     ``deviations`` and ``spread_deviations`` (per layer, the largest
///     distance from the data at the data parameters: ``max``, ``point``,
///     ``axis``), ``independent_violations`` (where fitting each layer on its
///     own breaks the order), ``mixed_heights`` (axis → the smallest height,
///     given to the control points where the data mix heights).
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> t = np.linspace(0, 1, 8)
/// >>> crisp = np.stack([4 * t, np.sin(3 * t)], axis=1)
/// >>> s = np.array([-0.2, 0.3])
/// >>> curve, summary = fit(crisp, crisp[..., None] + s, crisp[..., None] + 0.5 * s,
/// ...                      crisp[..., None] + 0.2 * s, lower_height=0.5, degree=3)
/// >>> curve.crisp.shape, summary["mode"]
/// ((8, 2), 'valid')
/// >>> bool(summary["deviations"]["crisp"]["max"] < 1e-12)   # interpolation
/// True
#[pyfunction]
#[pyo3(
    signature = (crisp, upper, primary, lower, lower_height, *, degree, control_points=None, parametrization=None, mode=None),
    text_signature = "(crisp, upper, primary, lower, lower_height, *, degree, control_points=None, parametrization='chord', mode='valid')"
)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn fit<'py>(
    py: Python<'py>,
    crisp: &Bound<'py, PyAny>,
    upper: &Bound<'py, PyAny>,
    primary: &Bound<'py, PyAny>,
    lower: &Bound<'py, PyAny>,
    lower_height: &Bound<'py, PyAny>,
    degree: &Bound<'py, PyAny>,
    control_points: Option<&Bound<'py, PyAny>>,
    parametrization: Option<&Bound<'py, PyAny>>,
    mode: Option<&Bound<'py, PyAny>>,
) -> PyResult<(PyFuzzyCurve, Bound<'py, PyDict>)> {
    let degree = keyword::int(degree, "degree")?;
    let control_points = keyword::opt_int(control_points, "control_points")?;
    let parametrization = keyword::opt_text(parametrization, "parametrization")?;
    let mode = keyword::opt_text(mode, "mode")?;
    let data = FuzzyArrays::read([crisp, upper, primary, lower, lower_height], 1)?;
    let options = FitOptions {
        degree: self::degree(Some(degree), None, None, data.n)?,
        parametrization: parametrization
            .as_deref()
            .unwrap_or("chord")
            .parse::<Parametrization>()
            .map_err(|e| PyValueError::new_err(format!("parametrization: {e}")))?,
        control_points: control_points
            .map(|m| crate::construct::count(m, "control_points", 1))
            .transpose()?,
    };
    let mode: FuzzyFitMode = mode
        .as_deref()
        .unwrap_or("valid")
        .parse()
        .map_err(|e| PyValueError::new_err(format!("mode: {e}")))?;
    let outcome = compute(py, move || {
        let points = match data.points()? {
            ByDim::Planar(p) => FuzzyData::Planar(p),
            ByDim::Spatial(p) => FuzzyData::Spatial(p),
        };
        points.fit(&options, mode)
    })?;
    let curve = match outcome.model {
        Ok(model) => FromModel::from_model(model)
            .map(PyFuzzyCurve)
            .ok_or_else(|| {
                crate::errors::internal_error("a fit gave a model that is not a curve")
            })?,
        Err(violations) => {
            let mut lines = vec![format!(
                "fitting every layer on its own breaks the order of the seven values at {} place(s) of the control points:",
                violations.len()
            )];
            lines.extend(violations.iter().map(ToString::to_string));
            lines.push(
                "mode='valid' (the default) fits the spreads so that the control points are valid fuzzy numbers"
                    .to_owned(),
            );
            return Err(PyValueError::new_err(lines.join("\n")));
        }
    };
    Ok((curve, summary(py, &outcome.summary)?))
}

/// The summary as a dict (the keys of the stub's `FitSummary`).
fn summary<'py>(py: Python<'py>, s: &FitSummary) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("data_points", s.data_points)?;
    out.set_item("control_points", s.control_points)?;
    out.set_item("mode", s.mode.name())?;
    out.set_item("condition", s.condition)?;
    out.set_item("deviations", deviations(py, &s.deviations)?)?;
    out.set_item("spread_deviations", deviations(py, &s.spread_deviations)?)?;
    out.set_item(
        "independent_violations",
        PyList::new(py, s.independent_violations.iter().map(ToString::to_string))?,
    )?;
    let heights = PyDict::new(py);
    for (axis, h) in &s.mixed_heights {
        heights.set_item(axis.name(), h.get())?;
    }
    out.set_item("mixed_heights", heights)?;
    Ok(out)
}

/// Per layer: `{"max": …, "point": i, "axis": "x"}`.
fn deviations<'py>(py: Python<'py>, d: &Layers<Deviation>) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for l in Layer::ALL {
        let entry = PyDict::new(py);
        entry.set_item("max", d[l].max)?;
        entry.set_item("point", d[l].point)?;
        entry.set_item("axis", d[l].axis.name())?;
        out.set_item(l.name(), entry)?;
    }
    Ok(out)
}
