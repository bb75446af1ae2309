//! The figures of the method: one builder per figure, each reading numbers
//! from [`crate::data`] and returning a [`Figure`] in data coordinates.
//!
//! | file stem | shows | paper |
//! |---|---|---|
//! | `number` | membership functions of one number, its cut and type reduction | Figs. 3.1, 4.1–4.4 |
//! | `stage1-fuzzy` | fuzzy control points and the seven layer curves | Fig. 5.1 |
//! | `stage2-alpha-cut` | alpha-cut control points and curves | Fig. 5.2 |
//! | `stage3-type-reduced` | type-reduced control points and curves, with weights | Fig. 5.3 |
//! | `stage4-defuzzified` | crisp and defuzzified curves, largest distance, magnified | Fig. 5.4 |
//! | `alpha-sweep` | distance along t between solution and crisp curve, several α | — |
//! | `distance-alpha` | `error.max` and `error.rms` against α, both sides of each h | — |
//! | `reductions` | the solution curve of every type reduction and its distance to the crisp curve | docs/method.md §9 |
//! | `measures` | the fuzzy arc length and (plane curves) area as fuzzy numbers, the crisp curve's values marked | docs/method.md §11 |
//! | `membership` | plane curves: `mu_upper` and `mu_lower` in the plane as maps, region outlines as contours | docs/method.md §10 |
//! | `section` | plane curves: the fuzzy value of y at a station `x = x0` | docs/method.md §10 |
//! | `envelope-width` | terrains: greatest − least height over the plan at α, per function | docs/method.md §12 |
//! | `shoreline` | terrains: the fuzzy contour at z = 0 per function over the crisp contour map | docs/method.md §13 |
//! | `terrain-measures` | terrains: volumes about z = 0, plan area below, surface area as fuzzy numbers | docs/method.md §14 |
//!
//! Stages 2–4 follow the run's type reduction (docs/method.md §9); `alpha-sweep` and
//! `distance-alpha` show the paper's, the one that uses α.
//!
//! Curve figures live in [`curve`]; the layout, legend, colour bar and SVG/PNG
//! output they use are independent of what is drawn.

mod aspect;
pub mod curve;
mod measures;
mod notebook;
mod number;
mod number_reductions;
pub mod style;
pub mod surface;
mod terrain;
mod terrain_measures;

use t2spline::job::Job;
use t2spline::Alpha;

pub use aspect::Aspect;
pub use curve::reductions_figure;
pub use measures::measures_figure;
pub use notebook::{
    measures_notebook_figure, notebook_figures, number_notebook_figure, region_notebook_figure,
    section_notebook_figure, Stages, NOTEBOOK_MAX_REGION_POINTS, NOTEBOOK_MAX_SAMPLES,
    NOTEBOOK_SURFACE_GRID,
};
pub use number::{number_figure, NumberChoice};
pub use style::{palette, reduction_label};
pub use terrain::{
    contour_map, terrain_figures, terrain_left_out, TerrainFigures, TERRAIN_FIGURE_NAMES,
};
pub use terrain_measures::terrain_measures_figure;

use crate::chart::scene::Figure;
use crate::error::Error;
use crate::{data, set_view};
use curve::{CurveScene, Zoom};
use surface::{SurfaceScene, View};

/// The file stems of all figures, in the order [`all_figures`] returns them
/// for a plane curve (a space curve has all but the last two).
pub const FIGURE_NAMES: [&str; 11] = [
    "number",
    "stage1-fuzzy",
    "stage2-alpha-cut",
    "stage3-type-reduced",
    "stage4-defuzzified",
    "alpha-sweep",
    "distance-alpha",
    "reductions",
    "measures",
    "membership",
    "section",
];

/// The most control points of a curve whose `measures` figure is drawn:
/// beyond, the largest length and the area are branch-and-bound brackets at
/// every level, seconds to minutes of work (`t2spline measure` gives them).
pub const MEASURES_MAX_POINTS: usize = 20;

/// What the figures show beyond the job and alpha.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FigureOptions {
    /// The number of the `number` figure.
    pub number: NumberChoice,
    /// The scaling of curve panels (and of the 3-D box of surfaces).
    pub aspect: Aspect,
    /// The direction the 3-D views of surfaces look from.
    pub view: View,
    /// The station `x = x0` of the `section` figure (plane curves); `None`:
    /// x of the crisp curve at the middle of its domain.
    pub station: Option<f64>,
}

/// Why a curve's figures of the set view (`membership`, `section`,
/// `measures`, and the regions shaded in stages 1–2) are left out, if they
/// are: a curve with fuzzy weights has no set view yet (docs/method.md §16).
/// A surface has none of these figures; with fuzzy weights its terrain
/// figures are left out ([`terrain_left_out`] says why).
#[must_use]
pub fn set_figures_left_out(job: &Job) -> Option<&'static str> {
    (!job.model.is_surface() && job.model.has_fuzzy_weights()).then_some(
        "regions, membership maps and measures of a curve with fuzzy weights are not available yet (`t2spline membership` and `t2spline section` take them)",
    )
}

/// Every figure of the job at `alpha`, in the order of [`FIGURE_NAMES`]; a
/// space curve has all but `membership` and `section` (figures of the
/// plane), a surface job all but those and `alpha-sweep`, `reductions` and `measures`
/// (nor a curve of more than [`MEASURES_MAX_POINTS`] control points, nor a
/// curve with fuzzy weights: [`set_figures_left_out`]), and
/// after them, for a terrain, the figures of [`TERRAIN_FIGURE_NAMES`] (a
/// surface that is not one has none: [`terrain_left_out`] says why). Stages 2–4 follow
/// the job's type reduction, as `t2spline run` does (a reduction other than
/// the paper's cuts stage 2 at 0); `alpha` is the paper's level in the
/// `number`, `distance-alpha` and `reductions` figures.
///
/// # Errors
/// [`Error::NoSuchPoint`] or [`Error::NoSuchAxis`] if `options.number` names
/// a point or coordinate the job lacks.
pub fn all_figures(job: &Job, alpha: Alpha, options: &FigureOptions) -> Result<Vec<Figure>, Error> {
    let number = number_figure(job, alpha, job.type_reduction, options.number)?;
    let result = data::compute(job, alpha)?;
    let heights = job.model.heights();
    if job.model.is_surface() {
        let scene = SurfaceScene::new(&result, &heights, options.view, options.aspect);
        let mut figures = vec![
            number,
            surface::stage1_figure(&scene),
            surface::stage2_figure(&scene),
            surface::stage3_figure(&scene),
            surface::stage4_figure(job, &scene)?,
            curve::distance_figure(job, alpha.get())?,
        ];
        if let TerrainFigures::Drawn(terrain) = terrain_figures(job, alpha)? {
            figures.extend(terrain);
        }
        return Ok(figures);
    }
    let scene = CurveScene::new(&result, &heights, options.aspect);
    let axes = scene.axes();
    // The figures of the plane (plane curves) beside the others, on
    // rayon's pool: they ask the core for maps, regions and sections.
    let (figures, plane) = rayon::join(
        || -> Result<Vec<Figure>, Error> {
            let (zero, at) = rayon::join(
                || set_view::regions(&job.model, Alpha::ZERO, &axes),
                || set_view::regions(&job.model, Alpha::try_new(result.alpha)?, &axes),
            );
            Ok(vec![
                number,
                curve::stage1_figure(&scene, &zero?),
                curve::stage2_figure(&scene, &at?),
                curve::stage3_figure(&scene),
                curve::stage4_figure(job, &scene, Zoom::WhereApart)?,
                curve::sweep_figure(job)?,
                curve::distance_figure(job, alpha.get())?,
                reductions_figure(job, alpha, options.aspect)?,
            ]
            .into_iter()
            .chain(
                (job.model.control_point_count() <= MEASURES_MAX_POINTS
                    && !job.model.has_fuzzy_weights())
                .then(|| measures_figure(job))
                .transpose()?,
            )
            .collect())
        },
        || -> Result<Vec<Figure>, Error> {
            if !matches!(job.model, t2spline::job::Model::Planar(_))
                || job.model.has_fuzzy_weights()
            {
                return Ok(Vec::new());
            }
            let (map, section) = rayon::join(
                || curve::membership_figure(job, &scene),
                || curve::section_figure(job, &scene, options.station),
            );
            Ok(vec![map?, section?])
        },
    );
    let mut figures = figures?;
    figures.extend(plane?);
    Ok(figures)
}
