//! `FuzzyCurve.measure`: the quantities of docs/method.md §11 (arc length,
//! area, derivative, tangent angle, curvature as intervals over the control
//! points inside their cuts) as the dict `t2spline measure` writes, every
//! list of numbers a numpy array, which shows the `measures` figure in a
//! notebook; `FuzzySurface.measure`: the volumes, plan area and surface
//! area of §14, and with `against` the cut and fill between two surfaces
//! (of one plan map, or over the overlap of their plans), as the command
//! writes them for a surface.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use t2spline::measure::{
    uniform_levels, MeasureOptions, SurfaceMeasureOptions, DEFAULT_MEASURE_LEVELS,
};
use t2spline::Alpha;

use crate::arrays::{floats, shape_text};
use crate::dim::{by_dim, ByDim, Fuzzy, FuzzyNet};
use crate::errors::{compute, internal_error};
use crate::keyword;
use crate::value::to_value;

/// `levels`: a count (default [`DEFAULT_MEASURE_LEVELS`]) or the levels
/// themselves; their number is checked by the options
/// ([`MeasureOptions::new`]).
fn levels(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<Alpha>> {
    let Some(arg) = arg.filter(|a| !a.is_none()) else {
        return uniform_levels(DEFAULT_MEASURE_LEVELS).map_err(crate::errors::core_error);
    };
    if let Ok(n) = arg.extract::<i64>() {
        let n = keyword::count(n, "levels", 0)?;
        return uniform_levels(n).map_err(crate::errors::core_error);
    }
    let given = floats(arg, "levels")?;
    if given.shape.len() != 1 {
        return Err(PyValueError::new_err(format!(
            "levels: expected a count or a 1-D array of levels, got shape {}",
            shape_text(&given.shape)
        )));
    }
    keyword::alphas(&given.data, "levels")
}

/// `at`: `None`, one parameter or a 1-D array of them.
fn params(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<f64>> {
    let Some(arg) = arg.filter(|a| !a.is_none()) else {
        return Ok(Vec::new());
    };
    let given = floats(arg, "at")?;
    if given.shape.len() > 1 {
        return Err(PyValueError::new_err(format!(
            "at: expected a parameter or a 1-D array of parameters, got shape {}",
            shape_text(&given.shape)
        )));
    }
    Ok(given.data)
}

/// `FuzzyCurve.measure(levels=11, at=None, order=1, *, closed=None)`.
pub(crate) fn curve_measure<'py>(
    py: Python<'py>,
    curve: &ByDim<Fuzzy>,
    levels_arg: Option<&Bound<'py, PyAny>>,
    at_arg: Option<&Bound<'py, PyAny>>,
    order_arg: Option<&Bound<'py, PyAny>>,
    closed_arg: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let order = match order_arg.filter(|a| !a.is_none()) {
        Some(order) => keyword::count(keyword::int(order, "order")?, "order", 0)?,
        None => 1,
    };
    let options = MeasureOptions::new(levels(levels_arg)?, params(at_arg)?, order)
        .map_err(crate::errors::core_error)?
        .closed(keyword::opt_bool(closed_arg, "closed")?);
    let (measures, figure) = by_dim!(curve, |c| {
        let m = compute(py, || c.measure(&options))?;
        // The picture: the `measures` figure of `t2spline plot` of these
        // measures (nothing is measured again).
        let figure = t2spline_plot::measures_notebook_figure(c, &m);
        (m, figure)
    });
    // A function with no cut at a level, or no parameters, is an empty list.
    let value = to_value(&measures)
        .map_err(|e| internal_error(&e.to_string()))?
        .empty_as_lists()
        .into_py(py)?;
    crate::picture::pictured(
        value,
        vec![figure],
        vec![("levels", measures.levels.len().to_string())],
    )
}

/// A surface in space, else a `ValueError` naming `what`.
fn spatial<'a>(
    surface: &'a ByDim<FuzzyNet>,
    what: &str,
) -> PyResult<&'a t2spline::FuzzySurface<3>> {
    surface.spatial_or(|| {
        format!("{what}: taken of surfaces in space (heights z over a plan); this surface is in the plane")
    })
}

/// `FuzzySurface.measure(levels=11, datum=0.0, area=True, *, against=None)`.
pub(crate) fn surface_measure<'py>(
    py: Python<'py>,
    surface: &ByDim<FuzzyNet>,
    levels_arg: Option<&Bound<'py, PyAny>>,
    datum: f64,
    area: bool,
    against: Option<&ByDim<FuzzyNet>>,
) -> PyResult<Bound<'py, PyAny>> {
    let s = spatial(surface, "measure")?;
    let against = against.map(|a| spatial(a, "against")).transpose()?;
    let options = SurfaceMeasureOptions::new(levels(levels_arg)?, datum)
        .map_err(crate::errors::core_error)?
        .with_area(area);
    let measures = compute(py, || match against {
        Some(other) => s.measure_against(other, &options),
        None => s.measure(&options),
    })?;
    to_value(&measures)
        .map_err(|e| internal_error(&e.to_string()))?
        .empty_as_lists()
        .into_py(py)
}
