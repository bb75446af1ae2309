//! `t2spline.fit`: fuzzy data points given as arrays → a `FuzzyCurve` (a
//! net of them → a `FuzzySurface`) and a summary of the fit, by the core's
//! `FuzzyData::fit` and `FuzzyData::fit_net` (the fits of `t2spline fit`);
//! `t2spline.fit_job`: a data file (or its dict) → the job `t2spline fit`
//! writes, by the I/O crate's `parse_data` and `FitData::job_json`.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use t2spline::fit::{
    Deviation, FitOptions, FitSummary, FuzzyData, FuzzyFitMode, OrderViolation, Parametrization,
    SurfaceFitOptions,
};
use t2spline::{Alpha, Layer, Layers};
use t2spline_io::{parse_data, parse_job, to_json_pretty};

use crate::classes::{PyFuzzyCurve, PyFuzzySurface};
use crate::construct::{degree, rows as rows_of, FuzzyArrays};
use crate::dim::{ByDim, FromModel, Fuzzy, FuzzyNet};
use crate::errors::{compute, core_error, io_error, without_gil};
use crate::json::loads;
use crate::keyword;

/// Fits a fuzzy curve to fuzzy data points, or a fuzzy surface to a net of
/// them (``t2spline fit``): interpolation (The NURBS Book §9.2.1, §9.2.5) or
/// least squares with the end points (of a net: its boundary curves' ends)
/// interpolated (§9.4.1, §9.4.3), one parametrization and one knot vector per
/// direction for all seven layers.
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
///     height per number or for all; or a net of them, as for
///     ``FuzzySurface``: ``(rows, cols, 3)`` and ``(rows, cols, 3, 2)``, point
///     ``[i, j]`` on row ``i`` (along u) and column ``j`` (along v).
/// degree : int or (int, int)
///     The degree ``p >= 1``; for a net, one for both directions or a pair
///     ``(p, q)`` along u and v.
/// control_points : int or (int, int), optional
///     Least squares with this many control points (``p + 1`` … ``m``); for a
///     net, one count for both directions or a pair ``(nu, nv)``, each from
///     the degree + 1 to the rows (columns) of the net; default:
///     interpolation, one per data point.
/// parametrization : {'chord', 'centripetal', 'uniform'}
///     How the data get their parameters (The NURBS Book Eqs. 9.3–9.6; for
///     a net, averaged over its rows and columns, Algorithm A9.3).
/// mode : {'valid', 'independent'}
/// closed : bool
///     Fit a closed curve around the points taken as a loop (``t2spline fit
///     --closed``): the closing chord in the parametrization, periodic knots,
///     the first ``p`` control points repeated at the end; a last point equal
///     to the first counts once. Curves only.
///
/// Returns
/// -------
/// (FuzzyCurve, dict) or (FuzzySurface, dict)
///     The curve (surface) and a summary: ``data_points``,
///     ``control_points`` (of a net: all of them), ``mode``, ``condition``
///     (estimated condition number of the system; of a net, the larger of u
///     and v), ``deviations`` and ``spread_deviations`` (per layer, the
///     largest distance from the data at the data parameters: ``max``,
///     ``point`` (the index in row-major order for a net), ``axis``),
///     ``independent_violations`` (where fitting each layer on its own
///     breaks the order), ``mixed_heights`` (axis → the smallest height,
///     given to the control points where the data mix heights), ``net``
///     (``{"data": [rows, cols], "control": [nu, nv]}`` for a net, ``None``
///     for a curve).
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> t = np.linspace(0, 1, 8)
/// >>> crisp = np.stack([4 * t, np.sin(3 * t)], axis=1)
/// >>> s = np.array([-0.2, 0.3])
/// >>> curve, summary = fit(crisp, crisp[..., None] + s, crisp[..., None] + 0.5 * s,
/// ...                      crisp[..., None] + 0.2 * s, lower_height=0.5, degree=3)
/// >>> curve.crisp.shape, summary["mode"], summary["net"]
/// ((8, 2), 'valid', None)
/// >>> bool(summary["deviations"]["crisp"]["max"] < 1e-12)   # interpolation
/// True
///
/// A net of 5 × 4 data points, least squares with 4 × 3 control points:
///
/// >>> u, v = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 1, 4), indexing="ij")
/// >>> net = np.stack([u, v, u * v], axis=-1)                        # (5, 4, 3)
/// >>> surface, summary = fit(net, net[..., None] + s, net[..., None] + 0.5 * s,
/// ...                        net[..., None] + 0.2 * s, 0.5, degree=(2, 1), control_points=(4, 3))
/// >>> surface.crisp.shape, summary["net"]
/// ((4, 3, 3), {'data': [5, 4], 'control': [4, 3]})
#[pyfunction]
#[pyo3(
    signature = (crisp, upper=None, primary=None, lower=None, lower_height=None, *, degree, control_points=None, parametrization=None, mode=None, closed=None),
    text_signature = "(crisp, upper=None, primary=None, lower=None, lower_height=None, *, degree, control_points=None, parametrization='chord', mode='valid', closed=False)"
)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn fit<'py>(
    py: Python<'py>,
    crisp: &Bound<'py, PyAny>,
    upper: Option<&Bound<'py, PyAny>>,
    primary: Option<&Bound<'py, PyAny>>,
    lower: Option<&Bound<'py, PyAny>>,
    lower_height: Option<&Bound<'py, PyAny>>,
    degree: &Bound<'py, PyAny>,
    control_points: Option<&Bound<'py, PyAny>>,
    parametrization: Option<&Bound<'py, PyAny>>,
    mode: Option<&Bound<'py, PyAny>>,
    closed: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Py<PyAny>, Bound<'py, PyDict>)> {
    let degree = keyword::per_direction(degree, "degree")?;
    let closed = keyword::opt_bool(closed, "closed")?.unwrap_or(false);
    let control_points = keyword::opt_per_direction(control_points, "control_points")?;
    let parametrization = self::parametrization(parametrization)?;
    let mode = self::mode(mode)?;
    // A net's crisp values are (rows, cols, d): three dimensions.
    let rank = match py
        .import("numpy")?
        .call_method1("ndim", (crisp,))?
        .extract::<usize>()?
    {
        3 => 2,
        _ => 1,
    };
    let data = FuzzyArrays::read(crisp, [upper, primary, lower, lower_height], rank)?;
    if rank == 2 {
        if closed {
            return Err(PyValueError::new_err(CLOSED_NET));
        }
        let [rows, cols] = [data.net[0], data.net[1]];
        if data.d != 3 {
            return Err(PyValueError::new_err(format!(
                "crisp: a net of data points needs x, y and z, shape (rows, cols, 3), got {}",
                crate::arrays::shape_text(&[rows, cols, data.d])
            )));
        }
        let names = match degree {
            keyword::PerDirection::One(_) => ["degree"; 2].map(str::to_owned),
            keyword::PerDirection::Two(..) => ["degree[0]", "degree[1]"].map(str::to_owned),
        };
        let degree =
            crate::construct::surface_degrees(Some(degree), None, [None; 2], [rows, cols])?;
        for (k, (n, lines)) in [(rows, "rows"), (cols, "columns")].into_iter().enumerate() {
            let p = degree[k];
            if p == 0 || p >= n {
                return Err(PyValueError::new_err(format!(
                    "{}: {p} along {} is outside [1, {}]: a fit needs degree 1 or more, and a net of {n} {lines} carries at most degree {}",
                    names[k],
                    ["u", "v"][k],
                    n.saturating_sub(1),
                    n.saturating_sub(1),
                )));
            }
        }
        let counts = control_points.map(|c| {
            let names = match c {
                keyword::PerDirection::One(_) => ["control_points"; 2].map(str::to_owned),
                keyword::PerDirection::Two(..) => {
                    ["control_points[0]", "control_points[1]"].map(str::to_owned)
                }
            };
            let [m, n] = c.pair();
            Ok::<_, PyErr>([
                count_within(m, &names[0], degree[0] + 1, rows, "rows")?,
                count_within(n, &names[1], degree[1] + 1, cols, "columns")?,
            ])
        });
        let options = SurfaceFitOptions::new(degree, counts.transpose()?)
            .map_err(core_error)?
            .with_parametrization(parametrization);
        let outcome = compute(py, move || {
            let ByDim::Spatial(points) = data.points()? else {
                return Err(t2spline::Error::Length {
                    what: "coordinates",
                    expected: 3,
                    found: 2,
                });
            };
            FuzzyData::Net(rows_of(points, [rows, cols])).fit_net(&options, mode)
        })?;
        let model = outcome.model.map_err(|v| order_error(&v))?;
        let surface: ByDim<FuzzyNet> = FromModel::from_model(model).ok_or_else(|| {
            crate::errors::internal_error("a fit of a net gave a model that is not a surface")
        })?;
        let surface = Py::new(py, PyFuzzySurface(surface))?.into_any();
        return Ok((surface, summary(py, &outcome.summary)?));
    }
    let degree = match degree {
        keyword::PerDirection::One(p) => p,
        keyword::PerDirection::Two(..) => {
            return Err(PyValueError::new_err(
                "degree: a pair (p, q) is for a net of data points, crisp of shape (rows, cols, 3); the points of a curve take one degree",
            ))
        }
    };
    let control_points = match control_points {
        None => None,
        Some(keyword::PerDirection::One(m)) => Some(m),
        Some(keyword::PerDirection::Two(..)) => {
            return Err(PyValueError::new_err(
                "control_points: a pair (nu, nv) is for a net of data points, crisp of shape (rows, cols, 3); the points of a curve take one count",
            ))
        }
    };
    let options = FitOptions::new(
        self::degree(Some(degree), None, None, data.n)?,
        control_points
            .map(|m| crate::construct::count(m, "control_points", 1))
            .transpose()?,
    )
    .map_err(core_error)?
    .with_parametrization(parametrization);
    let options = if closed { options.closed() } else { options };
    let outcome = compute(py, move || {
        let points = match data.points()? {
            ByDim::Planar(p) => FuzzyData::Planar(p),
            ByDim::Spatial(p) => FuzzyData::Spatial(p),
        };
        points.fit(&options, mode)
    })?;
    let model = outcome.model.map_err(|v| order_error(&v))?;
    let curve: ByDim<Fuzzy> = FromModel::from_model(model)
        .ok_or_else(|| crate::errors::internal_error("a fit gave a model that is not a curve"))?;
    let curve = Py::new(py, PyFuzzyCurve(curve))?.into_any();
    Ok((curve, summary(py, &outcome.summary)?))
}

/// The refusal of `closed=True` for a net of data points.
const CLOSED_NET: &str =
    "closed: a net of data points is fitted as an open surface; closed=True is for a loop of points of a curve";

/// A count of control points in one direction of a net, within
/// `[min, max]` (the degree + 1, the rows or columns of the net).
fn count_within(m: i64, name: &str, min: usize, max: usize, lines: &str) -> PyResult<usize> {
    usize::try_from(m)
        .ok()
        .filter(|m| (min..=max).contains(m))
        .ok_or_else(|| {
            PyValueError::new_err(format!(
                "{name}: {m} is outside [{min}, {max}]: at least degree + 1, at most the {max} {lines} of the net"
            ))
        })
}

/// `parametrization=`, default chord length.
fn parametrization(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Parametrization> {
    keyword::opt_text(arg, "parametrization")?
        .as_deref()
        .unwrap_or("chord")
        .parse::<Parametrization>()
        .map_err(|e| PyValueError::new_err(format!("parametrization: {e}")))
}

/// `mode=`, default valid.
fn mode(arg: Option<&Bound<'_, PyAny>>) -> PyResult<FuzzyFitMode> {
    keyword::opt_text(arg, "mode")?
        .as_deref()
        .unwrap_or("valid")
        .parse()
        .map_err(|e| PyValueError::new_err(format!("mode: {e}")))
}

/// The `ValueError` of an independent fit whose control points break the
/// order of the seven values.
fn order_error(violations: &[OrderViolation]) -> PyErr {
    let mut lines = vec![format!(
        "fitting every layer on its own breaks the order of the seven values at {} place(s) of the control points:",
        violations.len()
    )];
    lines.extend(violations.iter().map(ToString::to_string));
    lines.push(
        "mode='valid' (the default) fits the spreads so that the control points are valid fuzzy numbers"
            .to_owned(),
    );
    PyValueError::new_err(lines.join("\n"))
}

/// The job of a fit of a data file (a dict with its keys, as ``fuzzify``
/// gives, or its path), as ``t2spline fit DATA.json`` writes it: the same
/// validation of the data, the same fit and the same job, so
/// ``json.loads`` of the command's output equals the dict returned.
///
/// Parameters
/// ----------
/// data : dict or str or os.PathLike
///     The data of a fit: the keys of a data file (docs/fitting.md: a job's
///     keys without ``weights`` and ``knots``), the points of a curve or the
///     rows of a net. A dict is read as ``json.dumps(data, indent=2)`` and
///     named ``<dict>`` in messages.
/// control_points : int or (int, int), optional
///     Least squares with this many control points (``--control-points``);
///     a pair ``(nu, nv)`` for a net, one count for both directions.
/// parametrization : {'chord', 'centripetal', 'uniform'}
/// mode : {'valid', 'independent'}
///     As ``--fuzzy-fit``.
/// alpha : float, optional
///     Replaces the data's alpha (``--alpha``).
///
/// Returns
/// -------
/// dict
///     The job: the keys of a job file, weights 1 and explicit knots, with
///     the data's description, alpha, type reduction, lower height,
///     samples and choice of degree or order; ``run`` runs it.
///
/// Raises
/// ------
/// JobError
///     For data that break the rules of data files, and for a fit that
///     fails (too few points, repeated points, an ill-conditioned system),
///     named as the command names them.
/// ValueError
///     For an argument out of its range, named.
///
/// Examples
/// --------
/// >>> data = fuzzify("examples/beach-readings.csv", tolerance=0.02, alpha=0.5)
/// >>> job = fit_job(data, control_points=8)
/// >>> len(job["points"]), len(job["knots"]), job["alpha"]
/// (8, 12, 0.5)
#[pyfunction]
#[pyo3(
    signature = (data, *, control_points=None, parametrization=None, mode=None, alpha=None, closed=None),
    text_signature = "(data, *, control_points=None, parametrization='chord', mode='valid', alpha=None, closed=False)"
)]
pub(crate) fn fit_job<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyAny>,
    control_points: Option<&Bound<'py, PyAny>>,
    parametrization: Option<&Bound<'py, PyAny>>,
    mode: Option<&Bound<'py, PyAny>>,
    alpha: Option<&Bound<'py, PyAny>>,
    closed: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let counts = keyword::opt_per_direction(control_points, "control_points")?;
    let closed = keyword::opt_bool(closed, "closed")?.unwrap_or(false);
    let parametrization = self::parametrization(parametrization)?;
    let mode = self::mode(mode)?;
    let alpha = keyword::opt_real(alpha, "alpha")?
        .map(|a| Alpha::try_new(a).map_err(|e| PyValueError::new_err(format!("alpha: {e}"))))
        .transpose()?;
    let is_data = data.is_instance_of::<PyDict>()
        || data.is_instance_of::<pyo3::types::PyString>()
        || data.hasattr("__fspath__")?;
    if !is_data {
        return Err(PyTypeError::new_err(format!(
            "data: expected a dict with the keys of a data file (as fuzzify gives), or the path of a data file (str or os.PathLike), got {}",
            data.get_type().name()?
        )));
    }
    let (text, source) = crate::run::job_text(data)?;
    let mut data = without_gil(py, || parse_data(&text, &source))?.map_err(|e| io_error(py, e))?;
    if alpha.is_some() {
        data.alpha = alpha;
    }
    let (options, surface) = match &data.points {
        FuzzyData::Net(_) if closed => return Err(PyValueError::new_err(CLOSED_NET)),
        FuzzyData::Net(rows) => {
            let shape = [rows.len(), rows.first().map_or(0, Vec::len)];
            let degree = [data.degree, data.degree_v.unwrap_or(data.degree)];
            let counts = counts
                .map(|c| {
                    let two = matches!(c, keyword::PerDirection::Two(..));
                    let [m, n] = c.pair();
                    let name = |k: usize| {
                        if two {
                            format!("control_points[{k}]")
                        } else {
                            "control_points".to_owned()
                        }
                    };
                    Ok::<_, PyErr>([
                        count_within(m, &name(0), degree[0] + 1, shape[0], "rows")?,
                        count_within(n, &name(1), degree[1] + 1, shape[1], "columns")?,
                    ])
                })
                .transpose()?;
            let surface = SurfaceFitOptions::new(degree, counts)
                .map_err(core_error)?
                .with_parametrization(parametrization);
            let options = FitOptions::new(data.degree, counts.map(|[m, _]| m))
                .map_err(core_error)?
                .with_parametrization(parametrization);
            (options, Some(surface))
        }
        _ => {
            let m = match counts {
                None => None,
                Some(keyword::PerDirection::One(m)) => Some(count_within(
                    m,
                    "control_points",
                    data.degree + 1,
                    data.len(),
                    "data points",
                )?),
                Some(keyword::PerDirection::Two(..)) => {
                    return Err(PyValueError::new_err(
                        "control_points: a pair (nu, nv) is for a net of data points (a surface); these are the data of a curve: give one count",
                    ))
                }
            };
            let options = FitOptions::new(data.degree, m)
                .map_err(core_error)?
                .with_parametrization(parametrization);
            let options = if closed { options.closed() } else { options };
            (options, None)
        }
    };
    let text = without_gil(py, move || -> Result<String, t2spline_io::Error> {
        let outcome = match &surface {
            Some(o) => data.points.fit_net(o, mode),
            None => data.points.fit(&options, mode),
        }
        .map_err(|e| data.fit_error(&e))?;
        let job = match outcome.model {
            Ok(model) => data.job_json(&model, closed),
            Err(violations) => {
                return Err(data.order_error(
                    &violations,
                    "no job written: these control points are not valid fuzzy numbers; mode='valid' (the default) fits the spreads so that they are",
                ))
            }
        };
        let text = to_json_pretty(&job);
        // The last guard, as the command's: the job is a valid job file.
        parse_job(&text, "<fit_job>")?;
        Ok(text)
    })?
    .map_err(|e| io_error(py, e))?;
    loads(py, &text)
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
    match s.net {
        Some(net) => {
            let counts = PyDict::new(py);
            counts.set_item("data", net.data.to_vec())?;
            counts.set_item("control", net.control.to_vec())?;
            out.set_item("net", counts)?;
        }
        None => out.set_item("net", py.None())?,
    }
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
