//! `t2spline.fit`: fuzzy data points given as arrays → a `FuzzyCurve` and a
//! summary of the fit, by the core's `FuzzyData::fit` (the fit of
//! `t2spline fit`).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use t2spline::fit::{Deviation, FitOptions, FitSummary, FuzzyData, FuzzyFitMode, Parametrization};
use t2spline::{Layer, Layers};

use crate::construct::{degree, FuzzyArrays};
use crate::dim::ByDim;
use crate::errors::compute;
use crate::fuzzy_curve::PyFuzzyCurve;

/// Fits a fuzzy curve to fuzzy data points (see the stub for the docs).
#[pyfunction]
#[pyo3(signature = (crisp, upper, primary, lower, lower_height, *, degree, control_points=None, parametrization="chord", mode="valid"))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn fit<'py>(
    py: Python<'py>,
    crisp: &Bound<'py, PyAny>,
    upper: &Bound<'py, PyAny>,
    primary: &Bound<'py, PyAny>,
    lower: &Bound<'py, PyAny>,
    lower_height: &Bound<'py, PyAny>,
    degree: i64,
    control_points: Option<i64>,
    parametrization: &str,
    mode: &str,
) -> PyResult<(PyFuzzyCurve, Bound<'py, PyDict>)> {
    let data = FuzzyArrays::read(crisp, upper, primary, lower, lower_height)?;
    let options = FitOptions {
        degree: self::degree(Some(degree), None, None, data.n)?,
        parametrization: parametrization
            .parse::<Parametrization>()
            .map_err(|e| PyValueError::new_err(format!("parametrization: {e}")))?,
        control_points: control_points
            .map(|m| crate::construct::count(m, "control_points", 1))
            .transpose()?,
    };
    let mode: FuzzyFitMode = mode
        .parse()
        .map_err(|e| PyValueError::new_err(format!("mode: {e}")))?;
    let outcome = compute(py, move || {
        let points = match data.d {
            2 => FuzzyData::Planar(data.points()?),
            _ => FuzzyData::Spatial(data.points()?),
        };
        points.fit(&options, mode)
    })?;
    let curve = match outcome.model {
        Ok(model) => ByDim::from_model(model).map(PyFuzzyCurve).ok_or_else(|| {
            crate::errors::internal_error("a fit gave a model that is not a curve")
        })?,
        Err(violations) => {
            let mut lines = vec![format!(
                "fitting every layer on its own breaks the order of SPEC §1 at {} place(s) of the control points:",
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
