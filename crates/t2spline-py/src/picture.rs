//! Pictures in notebooks: the `_repr_html_` of the classes, an inline SVG
//! of each figure drawn by the figure code of `t2spline plot`
//! (`t2spline_plot::notebook_figures` and friends) under a short table of
//! the numbers that matter. Jupyter shows it; `repr()` stays one line.
//!
//! A crisp curve or surface is drawn as the fuzzy one whose every number is
//! crisp (every spread 0), so that one figure builder serves both.

use std::fmt::Write as _;
use std::sync::atomic::{AtomicU64, Ordering};

use pyo3::prelude::*;
use t2spline::job::{Job, Model};
use t2spline::set::{Plane, Region};
use t2spline::{
    Alpha, Direction, FuzzyCurve, FuzzySurface, Membership, Nt2Number, Nt2Point, NurbsCurve,
    NurbsSurface, TypeReduction,
};
use t2spline_plot::{
    notebook_figures, number_notebook_figure, region_notebook_figure, render_svg_prefixed, Figure,
    Stages,
};

use crate::errors::{core_error, internal_error};

/// Pictures drawn so far in this process: each picture's element ids begin
/// with its own number, so that pictures on one page keep their clip paths.
static DRAWN: AtomicU64 = AtomicU64::new(0);

/// `&`, `<`, `>` and `"` as entities.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The HTML of a picture: a table of `rows` (name, value) and each figure
/// as inline SVG.
pub(crate) fn page(figures: &[Figure], rows: &[(&str, String)]) -> String {
    let mut s = String::from("<div class=\"t2spline-picture\">\n");
    if !rows.is_empty() {
        s.push_str("<table>\n");
        for (name, value) in rows {
            let _ = writeln!(
                s,
                "<tr><th style=\"text-align:left\">{}</th><td style=\"text-align:left\">{}</td></tr>",
                escape(name),
                escape(value)
            );
        }
        s.push_str("</table>\n");
    }
    for fig in figures {
        let n = DRAWN.fetch_add(1, Ordering::Relaxed);
        s.push_str("<div>");
        s.push_str(&render_svg_prefixed(fig, &format!("t2s{n}-")));
        s.push_str("</div>\n");
    }
    s.push_str("</div>\n");
    s
}

fn plot_error(e: t2spline_plot::Error) -> PyErr {
    internal_error(&format!("drawing the picture: {e}"))
}

/// The stage figures of `model` at `alpha` with `method`.
pub(crate) fn stage_figures(
    model: Model,
    alpha: Alpha,
    method: TypeReduction,
    stages: Stages,
) -> PyResult<Vec<Figure>> {
    let mut job = Job::new(model);
    job.alpha = Some(alpha);
    job.type_reduction = method;
    notebook_figures(&job, alpha, stages).map_err(plot_error)
}

/// A crisp number (every foot at `v`, height 1).
fn crisp_number(v: f64) -> Result<Nt2Number, t2spline::Error> {
    Nt2Number::try_new(v, [v, v], [v, v], [v, v], 1.0)
}

/// A crisp point of `D` coordinates.
fn crisp_point<const D: usize>(p: &[f64; D]) -> Result<Nt2Point<D>, t2spline::Error> {
    let mut coords = [crisp_number(0.0)?; D];
    for (c, &v) in coords.iter_mut().zip(p) {
        *c = crisp_number(v)?;
    }
    Ok(Nt2Point::new(coords))
}

/// Crisp points of `D` coordinates, one per row of `points`.
fn crisp_points<const D: usize>(points: &[[f64; D]]) -> PyResult<Vec<Nt2Point<D>>> {
    points
        .iter()
        .map(crisp_point)
        .collect::<Result<Vec<_>, _>>()
        .map_err(core_error)
}

/// The fuzzy curve whose every number is crisp: the curve itself.
pub(crate) fn crisp_fuzzy_curve<const D: usize>(c: &NurbsCurve<D>) -> PyResult<FuzzyCurve<D>> {
    let points = crisp_points(c.control_points())?;
    FuzzyCurve::try_new(
        c.degree(),
        points,
        c.weights().to_vec(),
        Some(c.knots().as_slice().to_vec()),
    )
    .map_err(core_error)
}

/// The fuzzy surface whose every number is crisp: the surface itself.
pub(crate) fn crisp_fuzzy_surface<const D: usize>(
    s: &NurbsSurface<D>,
) -> PyResult<FuzzySurface<D>> {
    let [_, nv] = s.shape();
    let points = crisp_points(s.control_points())?;
    let rows: Vec<Vec<Nt2Point<D>>> = points.chunks(nv.max(1)).map(<[_]>::to_vec).collect();
    let weights: Vec<Vec<f64>> = s.weights().chunks(nv.max(1)).map(<[_]>::to_vec).collect();
    FuzzySurface::try_new(
        s.degree(),
        rows,
        weights,
        [
            Some(s.knots(Direction::U).as_slice().to_vec()),
            Some(s.knots(Direction::V).as_slice().to_vec()),
        ],
    )
    .map_err(core_error)
}

/// The picture of stage 1 of a fuzzy model (level 0, the paper's type
/// reduction) as a page under the table of `rows`.
///
/// # Errors
/// Those of [`stage_figures`].
pub(crate) fn first_stage_page(model: Model, rows: &[(&str, String)]) -> PyResult<String> {
    let figures = stage_figures(model, Alpha::ZERO, TypeReduction::Paper, Stages::First)?;
    Ok(page(&figures, rows))
}

/// The picture of a crisp curve or surface: stage 1 of the crisp fuzzy
/// model, retitled.
pub(crate) fn crisp_page(model: Model, title: &str, rows: &[(&str, String)]) -> PyResult<String> {
    let mut figures = stage_figures(model, Alpha::ZERO, TypeReduction::Paper, Stages::First)?;
    for f in &mut figures {
        f.title = title.to_owned();
    }
    Ok(page(&figures, rows))
}

/// The picture of a fuzzy number: the `number` figure cut at `alpha = h/2`
/// (all three functions cut) with the paper's type reduction.
pub(crate) fn number_page(x: &Nt2Number) -> PyResult<String> {
    let alpha = Alpha::try_new(0.5 * x.height().get()).map_err(core_error)?;
    let fig = number_notebook_figure(x, alpha, "Fuzzy number");
    let pair = |i: t2spline::Interval| format!("[{:?}, {:?}]", i.left(), i.right());
    Ok(page(
        &[fig],
        &[
            ("crisp", format!("{:?}", x.crisp())),
            ("upper", pair(x.upper())),
            ("primary", pair(x.primary())),
            ("lower", pair(x.lower())),
            ("lower height h", format!("{:?}", x.height().get())),
            ("cut shown at", format!("α = h/2 = {:?}", alpha.get())),
        ],
    ))
}

/// The picture of a region of the set view.
pub(crate) fn region_page(
    region: &Region,
    membership: Membership,
    alpha: f64,
    plane: Plane,
) -> PyResult<String> {
    let alpha = Alpha::try_new(alpha).map_err(core_error)?;
    let [i, j] = plane.axes();
    const NAMES: [&str; 3] = ["x", "y", "z"];
    let fig = region_notebook_figure(region, membership, alpha, [NAMES[i], NAMES[j]]);
    Ok(page(
        &[fig],
        &[
            ("plane", plane.name().to_owned()),
            ("polygons", region.polygons().len().to_string()),
            ("area", format!("{:?}", region.area())),
            ("tolerance", format!("{:?}", region.tolerance())),
        ],
    ))
}

/// A picture kept beside a result that is a plain dict or list (`measure`,
/// `section`), drawn when a notebook shows the result: the result is an
/// instance of a dict or list subclass of `t2spline._pictures` that holds
/// it. Not exported: only its `_repr_html_` is used.
#[pyclass(frozen, module = "t2spline._t2spline", name = "_Picture")]
#[derive(Debug)]
pub(crate) struct PyPicture {
    figures: Vec<Figure>,
    rows: Vec<(&'static str, String)>,
}

#[pymethods]
impl PyPicture {
    fn _repr_html_(&self) -> String {
        page(&self.figures, &self.rows)
    }
}

/// `value` as the dict or list subclass of `t2spline._pictures` that shows
/// `figures` (under a table of `rows`) in a notebook; equal to `value` and
/// pickled as it.
pub(crate) fn pictured<'py>(
    value: Bound<'py, PyAny>,
    figures: Vec<Figure>,
    rows: Vec<(&'static str, String)>,
) -> PyResult<Bound<'py, PyAny>> {
    let py = value.py();
    let picture = Bound::new(py, PyPicture { figures, rows })?;
    py.import("t2spline._pictures")?
        .getattr("pictured")?
        .call1((value, picture))
}

/// The colours of the figures by series (``"upper"``, ``"primary"``,
/// ``"lower"``, ``"crisp"``, ``"polygon"``, ``"type_reduced_left"``,
/// ``"type_reduced_right"``, ``"solution"``, ``"distance"``), each
/// ``"#rrggbb"``: the table that ``t2spline.plot`` draws with, so that its
/// figures look as ``t2spline plot`` draws them.
#[pyfunction]
pub(crate) fn _palette() -> Vec<(&'static str, String)> {
    t2spline_plot::palette()
        .into_iter()
        .map(|(name, colour)| (name, colour.to_string()))
        .collect()
}
