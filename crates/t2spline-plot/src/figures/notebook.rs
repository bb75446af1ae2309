//! The figures of one object at a time, for pictures in notebooks (the
//! Python package's `_repr_html_`): the same builders as `t2spline plot`,
//! with the sampling capped so that a picture stays small and quick, and a
//! note on the figure whenever something was thinned.
//!
//! | object | figures |
//! |---|---|
//! | a fuzzy curve or surface | stage 1 |
//! | a solution (curve or surface) | stages 1–4 |
//! | a number | the `number` figure |
//! | a region of the set view | the region's polygons, filled as in stage 1 |
//! | the measures of a curve | the `measures` figure of those measures |
//! | the section of a plane curve | the `section` figure at its station |

use t2spline::job::{Job, Samples};
use t2spline::measure::Measures;
use t2spline::set::Region;
use t2spline::{Alpha, FuzzyCurve, Membership, Nt2Number, TypeReduction};

use super::aspect::Aspect;
use super::curve::{self, region_mark, CurveScene, Zoom};
use super::measures::measures_figure_of;
use super::number::lone_number_figure;
use super::style::{lower_band, upper_band};
use super::surface::{self, SurfaceScene, View};
use crate::chart::scene::{Figure, LegendEntry, Panel};
use crate::chart::ticks::short;
use crate::data;
use crate::error::Error;
use crate::measure_view::quantities;
use crate::set_view::{self, Regions};

/// The most samples per curve in a notebook's picture (16 per knot span up to
/// 256 spans); `t2spline plot` draws up to 65 537.
pub const NOTEBOOK_MAX_SAMPLES: usize = 4097;

/// The most grid points per direction of a surface in a notebook's picture,
/// as in the report.
pub const NOTEBOOK_SURFACE_GRID: usize = data::REPORT_SURFACE_GRID;

/// Curves of more control points than this are drawn without the regions of
/// the set view (their outlines are the slow part of a picture).
pub const NOTEBOOK_MAX_REGION_POINTS: usize = 200;

/// Which stages a notebook's picture of a job shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stages {
    /// Stage 1 alone: a fuzzy curve or surface.
    First,
    /// Stages 1–4: a solution.
    All,
}

/// The stage figures of `job` at `alpha` with the job's type reduction, as
/// `t2spline plot` draws them (stage 4 of a curve with its magnified part),
/// with at most [`NOTEBOOK_MAX_SAMPLES`] samples per curve or
/// [`NOTEBOOK_SURFACE_GRID`] grid points per direction of a surface, and no
/// regions for a curve of more than [`NOTEBOOK_MAX_REGION_POINTS`] control
/// points; each figure's notes say what was thinned.
///
/// # Errors
/// [`Error::Core`] if the run fails (it does not for a validated job).
///
/// # Examples
/// ```
/// use t2spline_plot::{notebook_figures, Stages};
/// let job = t2spline_io::read_job("../../examples/paper-alg-1-1.json".as_ref())?;
/// let alpha = job.alpha.expect("the example gives alpha");
/// let figures = notebook_figures(&job, alpha, Stages::All)?;
/// assert_eq!(figures.len(), 4);
/// assert!(t2spline_plot::render_svg(&figures[0]).contains("Stage 1"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn notebook_figures(job: &Job, alpha: Alpha, stages: Stages) -> Result<Vec<Figure>, Error> {
    let heights = job.model.heights();
    if let Some(grid) = data::surface_grid(&job.model) {
        let capped = grid.map(|n| n.min(NOTEBOOK_SURFACE_GRID));
        let result = data::run_with(job, alpha, job.type_reduction, Samples::Grid(capped))?;
        let scene = SurfaceScene::new(&result, &heights, View::default(), Aspect::Equal);
        let mut figures = vec![surface::stage1_figure(&scene)];
        if stages == Stages::All {
            figures.push(surface::stage2_figure(&scene));
            figures.push(surface::stage3_figure(&scene));
            figures.push(surface::stage4_figure(job, &scene)?);
        }
        if capped != grid {
            let note = format!(
                "Thinned for the notebook: a grid of {} × {} points per surface (t2spline plot draws {} × {}).",
                capped[0], capped[1], grid[0], grid[1]
            );
            figures.iter_mut().for_each(|f| f.notes.push(note.clone()));
        }
        return Ok(figures);
    }
    let full = data::figure_samples(&job.model);
    let samples = full.min(NOTEBOOK_MAX_SAMPLES);
    let result = data::run_with(job, alpha, job.type_reduction, Samples::Along(samples))?;
    let scene = CurveScene::new(&result, &heights, Aspect::Equal);
    let axes = scene.axes();
    let with_regions = job.model.control_point_count() <= NOTEBOOK_MAX_REGION_POINTS;
    let regions_at = |level: Alpha| -> Result<Regions, Error> {
        if with_regions {
            set_view::regions(&job.model, level, &axes)
        } else {
            Ok(Regions::default())
        }
    };
    let mut figures = vec![curve::stage1_figure(&scene, &regions_at(Alpha::ZERO)?)];
    if stages == Stages::All {
        let at = regions_at(Alpha::try_new(result.alpha)?)?;
        figures.push(curve::stage2_figure(&scene, &at));
        figures.push(curve::stage3_figure(&scene));
        figures.push(curve::stage4_figure(job, &scene, Zoom::WhereApart)?);
    }
    let mut notes = Vec::new();
    if samples < full {
        notes.push(format!(
            "Thinned for the notebook: {samples} samples per curve (t2spline plot draws {full})."
        ));
    }
    if !with_regions {
        notes.push(format!(
            "Regions of the set view left out for more than {NOTEBOOK_MAX_REGION_POINTS} control points (t2spline plot draws them)."
        ));
    }
    for f in &mut figures {
        f.notes.extend(notes.iter().cloned());
    }
    Ok(figures)
}

/// The `number` figure of one number on its own at `alpha` (the paper's type
/// reduction beside the others of docs/method.md §9), titled `title`.
///
/// # Examples
/// ```
/// use t2spline::{Alpha, Nt2Number};
/// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
/// let fig = t2spline_plot::number_notebook_figure(&x, Alpha::try_new(0.5)?, "Fuzzy number");
/// assert!(t2spline_plot::render_svg(&fig).contains("defuzzified"));
/// # Ok::<(), t2spline::Error>(())
/// ```
#[must_use]
pub fn number_notebook_figure(x: &Nt2Number, alpha: Alpha, title: &str) -> Figure {
    lone_number_figure(x, alpha, TypeReduction::Paper, title.to_owned(), "value")
}

/// A region of the set view in its plane, filled as stage 1 fills it (the
/// upper function's light, the lower's darker); `axes` names the plane's two
/// coordinates (the lower function's fill also for the lower region, a
/// primary region filled as an upper one).
///
/// # Examples
/// ```
/// use t2spline::{Alpha, Membership};
/// let job = t2spline_io::read_job("../../examples/paper-alg-1-1.json".as_ref())?;
/// let t2spline::job::Model::Planar(curve) = &job.model else { unreachable!() };
/// let alpha = Alpha::try_new(0.2)?;
/// let region = curve.region(Membership::Upper, alpha, None)?.ok_or("no region")?;
/// let fig = t2spline_plot::region_notebook_figure(&region, Membership::Upper, alpha, ["x", "y"]);
/// assert!(t2spline_plot::render_svg(&fig).contains("<path"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[must_use]
pub fn region_notebook_figure(
    region: &Region,
    membership: Membership,
    alpha: Alpha,
    axes: [&str; 2],
) -> Figure {
    let (name, fill) = match membership {
        Membership::Upper => ("upper", upper_band()),
        Membership::Primary => ("primary", upper_band()),
        Membership::Lower => ("lower", lower_band()),
    };
    let mut panel = Panel::curves(axes[0], axes[1]);
    panel.push("region", region_mark(region, fill.clone()));
    let label = format!("{name} region at α = {}", short(alpha.get(), 4));
    Figure::new(
        "region",
        format!(
            "Region of the fuzzy curve: {name} function, α = {}",
            short(alpha.get(), 4)
        ),
        format!(
            "{} polygon(s), area {}",
            region.polygons().len(),
            short(region.area(), 6)
        ),
        vec![panel],
        vec![LegendEntry::area(&label, fill)],
    )
}

/// The `measures` figure of `measures`, taken of `curve` at the levels they
/// hold (the area panel when they hold level 1, where its crisp value is
/// read).
#[must_use]
pub fn measures_notebook_figure<const D: usize>(
    curve: &FuzzyCurve<D>,
    measures: &Measures,
) -> Figure {
    let n = measures.levels.len();
    measures_figure_of(
        &quantities(curve, measures.clone()),
        &format!(
            "Each function is traced by its cuts at the {n} levels measured, joined by straight lines; docs/method.md §11."
        ),
    )
}

/// The `section` figure of the plane curve job `job` at the station
/// `x = x0`, cut at level 0 and the job's heights, as `t2spline plot
/// --station X0` draws it at alpha 0.
///
/// # Errors
/// [`Error::Planar`] for a job that is not a plane curve; [`Error::Core`]
/// if `x0` is not finite.
pub fn section_notebook_figure(job: &Job, x0: f64) -> Result<Figure, Error> {
    let samples = data::figure_samples(&job.model).min(NOTEBOOK_MAX_SAMPLES);
    let result = data::run_with(
        job,
        Alpha::ZERO,
        TypeReduction::Paper,
        Samples::Along(samples),
    )?;
    let heights = job.model.heights();
    let scene = CurveScene::new(&result, &heights, Aspect::Equal);
    curve::section_figure(job, &scene, Some(x0))
}
