//! The fuzzy curve or surface as a set (docs/method.md §10): membership
//! grades of points of any leading shape, alpha-regions as a `Region` with a
//! GeoJSON `__geo_interface__`, station sections as the dicts of `t2spline
//! section`'s JSON, and membership maps on a grid. The methods of
//! `FuzzyCurve` and `FuzzySurface` call the functions here.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use t2spline::set::{Grades, MembershipGrid, Plane, Region, SectionLevel, MAX_GRID_CELLS};
use t2spline::{Alpha, FuzzyCurve, FuzzySurface, Membership};

use crate::arrays::{array, floats, shape_text, Floats};
use crate::construct::{count, PerDirection};
use crate::dim::{by_dim, ByDim, Fuzzy, FuzzyNet};
use crate::errors::{compute, core_error, internal_error, without_gil};
use crate::keyword;

/// Levels of `section(levels=N)` at most, as `t2spline section --levels`.
const MAX_LEVELS: usize = 1001;

/// `"upper"`, `"primary"` or `"lower"`.
fn membership_name(m: Membership) -> &'static str {
    match m {
        Membership::Upper => "upper",
        Membership::Primary => "primary",
        Membership::Lower => "lower",
    }
}

/// A membership function from its name, `"upper"` when not given.
///
/// # Errors
/// `TypeError` for anything but a `str`, `ValueError` for another name,
/// naming the argument `membership`.
pub(crate) fn membership(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Membership> {
    match keyword::opt_text(arg, "membership")?.as_deref() {
        None | Some("upper") => Ok(Membership::Upper),
        Some("primary") => Ok(Membership::Primary),
        Some("lower") => Ok(Membership::Lower),
        Some(other) => Err(PyValueError::new_err(format!(
            "membership: expected 'upper', 'primary' or 'lower', got {other:?}"
        ))),
    }
}

/// A coordinate plane from its name, `"xy"` when not given; a plane curve
/// has only `"xy"`.
///
/// # Errors
/// `TypeError` for anything but a `str`, `ValueError` for another name or a
/// plane the curve does not have, naming the argument `plane`.
fn plane(arg: Option<&Bound<'_, PyAny>>, dimension: usize) -> PyResult<Plane> {
    let name = keyword::opt_text(arg, "plane")?;
    let Some(name) = name else {
        return Ok(Plane::Xy);
    };
    let plane = Plane::ALL
        .into_iter()
        .find(|p| p.name() == name)
        .ok_or_else(|| {
            PyValueError::new_err(format!("plane: expected 'xy', 'xz' or 'yz', got {name:?}"))
        })?;
    if dimension == 2 && plane != Plane::Xy {
        return Err(PyValueError::new_err(format!(
            "plane: a plane curve has only the plane 'xy', got {name:?}"
        )));
    }
    Ok(plane)
}

/// A level in `[0, 1]`, named `name`.
///
/// # Errors
/// `TypeError` for anything but a real number, `ValueError` for NaN or a
/// value outside `[0, 1]`.
fn alpha(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<Alpha> {
    let value = keyword::real(arg, name)?;
    Alpha::try_new(value)
        .map_err(|_| PyValueError::new_err(format!("{name}: {value} is outside [0, 1]")))
}

/// The tolerance of an outline: `None` for the curve's default, else a
/// positive finite number (how fine it may be is the core's rule).
///
/// # Errors
/// `TypeError` for anything but a real number, `ValueError` for NaN,
/// infinity, zero or a negative number.
fn tolerance(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    match keyword::opt_real(arg, "tolerance")? {
        Some(t) if !(t.is_finite() && t > 0.0) => Err(PyValueError::new_err(format!(
            "tolerance: {t} must be a positive finite number"
        ))),
        t => Ok(t),
    }
}

/// A core error, with `tolerance: ` before an error about the tolerance.
fn set_error(e: t2spline::Error) -> PyErr {
    match e {
        t2spline::Error::Tolerance { .. } | t2spline::Error::ToleranceTooCoarse { .. } => {
            PyValueError::new_err(format!("tolerance: {e}"))
        }
        other => core_error(other),
    }
}

/// The points of a membership query: any shape `(..., d)`.
///
/// # Errors
/// The errors of [`floats`] (NaN and infinity named by their index);
/// `ValueError` for another last dimension.
fn query_points(points: &Bound<'_, PyAny>, d: usize) -> PyResult<Floats> {
    let points = floats(points, "points")?;
    match points.shape.last() {
        Some(&k) if k == d => Ok(points),
        _ => Err(PyValueError::new_err(format!(
            "points: expected shape (..., {d}): points of {d} coordinates, the coordinates last, got {}",
            shape_text(&points.shape)
        ))),
    }
}

/// The grades as a dict of three arrays of `shape`.
fn grades_dict<'py>(
    py: Python<'py>,
    grades: &[Grades],
    shape: &[usize],
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for m in t2spline::set::MEMBERSHIPS {
        let values = grades.iter().map(|g| g.get(m)).collect();
        out.set_item(membership_name(m), array(py, values, shape)?)?;
    }
    Ok(out)
}

/// `FuzzyCurve.membership(points)`.
pub(crate) fn curve_membership<'py>(
    py: Python<'py>,
    curve: &ByDim<Fuzzy>,
    points: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let points = query_points(points, curve.dimension())?;
    let grades = by_dim!(curve, |c| {
        let rows = points.rows();
        compute(py, || c.memberships(&rows))
    })?;
    grades_dict(py, &grades, &points.shape[..points.shape.len() - 1])
}

/// `FuzzySurface.membership(points)`.
pub(crate) fn surface_membership<'py>(
    py: Python<'py>,
    surface: &ByDim<FuzzyNet>,
    points: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let points = query_points(points, surface.dimension())?;
    let grades = by_dim!(surface, |s| {
        let rows = points.rows();
        compute(py, || s.memberships(&rows))
    })?;
    grades_dict(py, &grades, &points.shape[..points.shape.len() - 1])
}

/// The region of a fuzzy curve at one level under one membership function,
/// projected on a coordinate plane (docs/method.md §10): the set of places
/// that some curve with its control points inside their cuts passes
/// through, as polygons with holes, from ``FuzzyCurve.region``.
///
/// The outline holds the true region and lies within ``tolerance`` of it.
/// ``__geo_interface__`` is a GeoJSON MultiPolygon (RFC 7946: rings closed,
/// exteriors counter-clockwise, holes clockwise), so ``shapely.geometry.shape``,
/// GeoPandas and other readers of the protocol open it; the coordinates are
/// the model's own.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> c = np.array([[0.0, 0.0], [4.0, 0.0]])        # a segment
/// >>> s = np.array([-1.0, 1.0])                      # ends move ±1 at level 0
/// >>> line = FuzzyCurve(c, c[..., None] + s, c[..., None] + 0.5 * s, c[..., None] + 0 * s,
/// ...                   lower_height=1.0, degree=1)
/// >>> r = line.region(0.0, tolerance=1e-6)           # the rectangle [-1, 5] × [-1, 1]
/// >>> round(r.area, 4), r.membership, r.plane
/// (12.0, 'upper', 'xy')
/// >>> r.contains([4.9, 0.9]), r.contains([5.1, 0.0])
/// (True, False)
/// >>> r.__geo_interface__["type"], len(r.polygons)
/// ('MultiPolygon', 1)
#[pyclass(frozen, eq, module = "t2spline", name = "Region")]
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PyRegion {
    region: Region,
    membership: Membership,
    alpha: f64,
    plane: Plane,
}

/// A polygon as pickled: its exterior ring and its holes, each open.
type Rings = (Vec<[f64; 2]>, Vec<Vec<[f64; 2]>>);

/// A ring as a list of `[x, y]` lists, closed if `closed`.
fn ring_list<'py>(
    py: Python<'py>,
    ring: &[[f64; 2]],
    closed: bool,
) -> PyResult<Bound<'py, PyList>> {
    let end = if closed { ring.first() } else { None };
    PyList::new(py, ring.iter().chain(end).map(|v| vec![v[0], v[1]]))
}

/// A ring as an `(k, 2)` array, open.
fn ring_array<'py>(py: Python<'py>, ring: &[[f64; 2]]) -> PyResult<Bound<'py, PyAny>> {
    array(
        py,
        ring.iter().flatten().copied().collect(),
        &[ring.len(), 2],
    )
}

#[pymethods]
impl PyRegion {
    /// Pickling and copying: ``Region._restore`` of the polygons, tolerance,
    /// membership, alpha and plane (nothing is computed again), an equal
    /// object.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<crate::pickle::Reduced<'py>> {
        let py = slf.py();
        let region = slf.get();
        let polygons = region
            .region
            .polygons()
            .iter()
            .map(|g| (g.exterior.clone(), g.holes.clone()))
            .collect::<Vec<_>>();
        let args = (
            polygons,
            region.region.tolerance(),
            region.membership(),
            region.alpha,
            region.plane(),
        )
            .into_pyobject(py)?;
        Ok((slf.get_type().getattr("_restore")?, args))
    }

    /// A region from what `__reduce__` gives (not part of the API), checked
    /// as a region is made: what a pickle restores is not trusted.
    ///
    /// Raises
    /// ------
    /// TypeError, ValueError
    ///     For parts of another form, a membership or plane unknown, an
    ///     alpha outside [0, 1], a tolerance that is not a finite positive
    ///     number, or a ring that is too short, not finite, wound the wrong
    ///     way or crosses itself (naming the polygon and the ring).
    #[classmethod]
    fn _restore(
        _cls: &Bound<'_, pyo3::types::PyType>,
        polygons: Vec<Rings>,
        tolerance: f64,
        membership: &Bound<'_, PyAny>,
        alpha: f64,
        plane: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let polygons = polygons
            .into_iter()
            .map(|(exterior, holes)| t2spline::set::Polygon { exterior, holes })
            .collect();
        let alpha = t2spline::Alpha::try_new(alpha).map_err(crate::errors::core_error)?;
        Ok(PyRegion {
            region: Region::try_from_parts(polygons, tolerance)
                .map_err(crate::errors::core_error)?,
            membership: self::membership(Some(membership))?,
            alpha: alpha.get(),
            plane: self::plane(Some(plane), 3)?,
        })
    }

    /// The total area of the polygons.
    #[getter]
    fn area(&self) -> f64 {
        self.region.area()
    }

    /// The tolerance of the outline: every point of the true region lies in
    /// the polygons, every point of the polygons within this distance of it.
    #[getter]
    fn tolerance(&self) -> f64 {
        self.region.tolerance()
    }

    /// The membership function: ``"upper"``, ``"primary"`` or ``"lower"``.
    #[getter]
    fn membership(&self) -> &'static str {
        membership_name(self.membership)
    }

    /// The level.
    #[getter]
    fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The coordinate plane: ``"xy"`` (always so for a plane curve), ``"xz"``
    /// or ``"yz"``.
    #[getter]
    fn plane(&self) -> &'static str {
        self.plane.name()
    }

    /// The polygons, which do not overlap: a list of ``(exterior, holes)``,
    /// ``exterior`` an array ``(k, 2)`` counter-clockwise and ``holes`` a list
    /// of such arrays, clockwise; rings open (the first vertex is not
    /// repeated).
    #[getter]
    fn polygons<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let items = self
            .region
            .polygons()
            .iter()
            .map(|g| {
                let holes = g
                    .holes
                    .iter()
                    .map(|h| ring_array(py, h))
                    .collect::<PyResult<Vec<_>>>()?;
                Ok((ring_array(py, &g.exterior)?, PyList::new(py, holes)?))
            })
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, items)
    }

    /// The region as a GeoJSON MultiPolygon geometry (RFC 7946): a dict
    /// ``{"type": "MultiPolygon", "coordinates": [...]}``, each polygon its
    /// closed exterior ring (counter-clockwise) followed by its closed holes
    /// (clockwise), each position a list ``[x, y]``.
    #[getter]
    fn __geo_interface__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let polygons = self
            .region
            .polygons()
            .iter()
            .map(|g| {
                let rings = std::iter::once(&g.exterior)
                    .chain(&g.holes)
                    .map(|r| ring_list(py, r, true))
                    .collect::<PyResult<Vec<_>>>()?;
                PyList::new(py, rings)
            })
            .collect::<PyResult<Vec<_>>>()?;
        let out = PyDict::new(py);
        out.set_item("type", "MultiPolygon")?;
        out.set_item("coordinates", PyList::new(py, polygons)?)?;
        Ok(out)
    }

    /// Whether the point ``(a, b)`` of the plane lies in the polygons
    /// (points on the outline may go either way).
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     For a point that is not two finite numbers.
    fn contains(&self, point: &Bound<'_, PyAny>) -> PyResult<bool> {
        let p = floats(point, "point")?;
        match p.data[..] {
            [a, b] if p.shape == [2] => Ok(self.region.contains([a, b])),
            _ => Err(PyValueError::new_err(format!(
                "point: expected shape (2,), got {}",
                shape_text(&p.shape)
            ))),
        }
    }

    /// The picture in a notebook: the region's polygons in its plane,
    /// filled as stage 1 of ``t2spline plot`` fills them, as inline SVG
    /// under a table of its plane, polygons, area and tolerance.
    fn _repr_html_(&self) -> PyResult<String> {
        crate::picture::region_page(&self.region, self.membership, self.alpha, self.plane)
    }

    fn __repr__(&self) -> String {
        format!(
            "Region(membership='{}', alpha={:?}, plane='{}', polygons={}, area={:?}, tolerance={:?})",
            membership_name(self.membership),
            self.alpha,
            self.plane.name(),
            self.region.polygons().len(),
            self.region.area(),
            self.region.tolerance()
        )
    }
}

/// `FuzzyCurve.region(alpha, membership=, tolerance=, plane=)`.
pub(crate) fn curve_region(
    py: Python<'_>,
    curve: &ByDim<Fuzzy>,
    level: &Bound<'_, PyAny>,
    membership_arg: Option<&Bound<'_, PyAny>>,
    tolerance_arg: Option<&Bound<'_, PyAny>>,
    plane_arg: Option<&Bound<'_, PyAny>>,
) -> PyResult<Option<PyRegion>> {
    let a = alpha(level, "alpha")?;
    let m = membership(membership_arg)?;
    let t = tolerance(tolerance_arg)?;
    let p = plane(plane_arg, curve.dimension())?;
    let region = by_dim!(curve, |c| without_gil(py, || c.region_in(p, m, a, t))?
        .map_err(set_error))?;
    Ok(region.map(|region| PyRegion {
        region,
        membership: m,
        alpha: a.get(),
        plane: p,
    }))
}

/// The levels of a section: `N` equally spaced from 0 to 1 (`2 ..= 1001`,
/// as `t2spline section --levels`), or the levels themselves.
///
/// # Errors
/// `ValueError` naming `levels` for a count out of range, a level outside
/// `[0, 1]` (named by its index) or no level.
fn levels(arg: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<Alpha>> {
    let Some(arg) = arg.filter(|a| !a.is_none()) else {
        return Ok(spaced(11));
    };
    if let Ok(n) = arg.extract::<i64>() {
        let n = count(n, "levels", 2)?;
        if n > MAX_LEVELS {
            return Err(PyValueError::new_err(format!(
                "levels: {n} is more than the limit of {MAX_LEVELS}"
            )));
        }
        return Ok(spaced(n));
    }
    let given = floats(arg, "levels")?;
    if given.shape.len() != 1 || given.data.is_empty() {
        return Err(PyValueError::new_err(format!(
            "levels: expected a count of at least 2 or a non-empty 1-D array of levels, got shape {}",
            shape_text(&given.shape)
        )));
    }
    keyword::alphas(&given.data, "levels")
}

/// `n ≥ 2` levels from 0 to 1.
fn spaced(n: usize) -> Vec<Alpha> {
    (0..n)
        .filter_map(|k| Alpha::try_new(k as f64 / (n - 1) as f64).ok())
        .collect()
}

/// The sections as a list of dicts `{"alpha", "upper", "primary",
/// "lower"}`, each function's intervals a list of `[lo, hi]` lists or `None`.
fn sections_list<'py>(py: Python<'py>, sections: &[SectionLevel]) -> PyResult<Bound<'py, PyList>> {
    let items = sections
        .iter()
        .map(|s| {
            let d = PyDict::new(py);
            d.set_item("alpha", s.alpha)?;
            for m in t2spline::set::MEMBERSHIPS {
                let intervals = s
                    .get(m)
                    .map(|list| list.iter().map(|iv| vec![iv[0], iv[1]]).collect::<Vec<_>>());
                d.set_item(membership_name(m), intervals)?;
            }
            Ok(d)
        })
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, items)
}

/// The curve of a plane curve's query, `what` naming the method.
fn planar<'a>(curve: &'a ByDim<Fuzzy>, what: &str) -> PyResult<&'a FuzzyCurve<2>> {
    curve.planar_or(|| {
        format!("{what}: taken of plane curves; for a space curve, take its region's projections (region(alpha, plane='xy'|'xz'|'yz'))")
    })
}

/// `FuzzyCurve.section(x0, levels=, tolerance=)`.
pub(crate) fn curve_section<'py>(
    py: Python<'py>,
    curve: &ByDim<Fuzzy>,
    x0: &Bound<'py, PyAny>,
    levels_arg: Option<&Bound<'py, PyAny>>,
    tolerance_arg: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    let c = planar(curve, "section")?;
    let x0 = finite(x0, "x0")?;
    let levels = levels(levels_arg)?;
    let t = tolerance(tolerance_arg)?;
    let sections = without_gil(py, || c.sections(x0, &levels, t))?.map_err(set_error)?;
    let list = sections_list(py, &sections)?;
    // The picture: the `section` figure of `t2spline plot` at this station.
    let job = t2spline::job::Job::new(t2spline::job::Model::Planar(c.clone()));
    let figure = t2spline_plot::section_notebook_figure(&job, x0)
        .map_err(|e| internal_error(&format!("drawing the section: {e}")))?;
    crate::picture::pictured(
        list.into_any(),
        vec![figure],
        vec![
            ("station", format!("x = {x0:?}")),
            ("levels", sections.len().to_string()),
        ],
    )
}

/// `FuzzySurface.section(x0, y0, levels=)`.
pub(crate) fn surface_section<'py>(
    py: Python<'py>,
    surface: &ByDim<FuzzyNet>,
    x0: &Bound<'py, PyAny>,
    y0: &Bound<'py, PyAny>,
    levels_arg: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyList>> {
    let s: &FuzzySurface<3> = match surface {
        ByDim::Spatial(s) => s,
        ByDim::Planar(_) => {
            return Err(PyValueError::new_err(
                "section: taken of surfaces in space (the fuzzy height z at (x0, y0)); this surface is in the plane",
            ))
        }
    };
    let (x0, y0) = (finite(x0, "x0")?, finite(y0, "y0")?);
    let levels = levels(levels_arg)?;
    let sections = compute(py, || s.sections([x0, y0], &levels))?;
    sections_list(py, &sections)
}

/// A real argument that must be finite.
///
/// # Errors
/// `TypeError` for anything but a real number, `ValueError` for NaN or
/// infinity, naming `name`.
fn finite(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    let v = keyword::real(arg, name)?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(PyValueError::new_err(format!(
            "{name} = {v} is not a finite number (NaN and infinity are refused)"
        )))
    }
}

/// A range `(lo, hi)` of finite numbers with `lo < hi`, named `name`.
fn range(arg: &Bound<'_, PyAny>, name: &str) -> PyResult<[f64; 2]> {
    let (lo, hi) = keyword::real_pair(arg, name)?;
    for (k, v) in [lo, hi].into_iter().enumerate() {
        if !v.is_finite() {
            return Err(PyValueError::new_err(format!(
                "{name}[{k}] = {v} is not a finite number (NaN and infinity are refused)"
            )));
        }
    }
    if lo < hi && (hi - lo).is_finite() {
        Ok([lo, hi])
    } else {
        Err(PyValueError::new_err(format!(
            "{name}: ({lo}, {hi}) is not a range: the first must be less than the second"
        )))
    }
}

/// `FuzzyCurve.membership_grid(x_range, y_range, shape)`.
pub(crate) fn curve_membership_grid<'py>(
    py: Python<'py>,
    curve: &ByDim<Fuzzy>,
    x_range: &Bound<'py, PyAny>,
    y_range: &Bound<'py, PyAny>,
    shape: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let c = planar(curve, "membership_grid")?;
    let xs = range(x_range, "x_range")?;
    let ys = range(y_range, "y_range")?;
    let (columns, rows) = match keyword::per_direction(shape, "shape")? {
        PerDirection::One(n) => (count(n, "shape", 1)?, count(n, "shape", 1)?),
        PerDirection::Two(a, b) => (count(a, "shape[0]", 1)?, count(b, "shape[1]", 1)?),
    };
    if columns.checked_mul(rows).is_none_or(|n| n > MAX_GRID_CELLS) {
        return Err(PyValueError::new_err(format!(
            "shape: a grid of {columns} × {rows} cells is more than the limit of {MAX_GRID_CELLS}"
        )));
    }
    let MembershipGrid {
        xs,
        ys,
        upper,
        primary,
        lower,
    } = compute(py, || c.membership_grid(xs, ys, [columns, rows]))?;
    let out = PyDict::new(py);
    let (nx, ny) = (xs.len(), ys.len());
    out.set_item("xs", array(py, xs, &[nx])?)?;
    out.set_item("ys", array(py, ys, &[ny])?)?;
    out.set_item("upper", array(py, upper, &[ny, nx])?)?;
    out.set_item("primary", array(py, primary, &[ny, nx])?)?;
    out.set_item("lower", array(py, lower, &[ny, nx])?)?;
    Ok(out)
}
