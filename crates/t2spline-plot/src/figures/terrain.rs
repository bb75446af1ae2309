//! The terrain figures of a surface job (x and y crisp, the graph of a
//! height): `envelope-width`, `shoreline` and `terrain-measures`, asked of
//! [`crate::terrain_view`]; a surface that is not a terrain gets the
//! core's reason instead.

use t2spline::job::Job;
use t2spline::{Alpha, FuzzySurface};

use super::surface::{shoreline_figure, width_figure};
use super::terrain_measures::terrain_measures_figure;
use crate::chart::scene::Figure;
use crate::chart::ticks::nice_ticks;
use crate::error::Error;
use crate::terrain_view::{self, Terrain, WIDTH_MAP_CELLS};

/// The file stems of the terrain figures, in the order
/// [`terrain_figures`] returns them (after a surface's stages).
pub const TERRAIN_FIGURE_NAMES: [&str; 3] = ["envelope-width", "shoreline", "terrain-measures"];

/// Contour lines of the crisp surface under the shoreline, about.
const CONTOUR_MAP_LINES: usize = 8;

/// The terrain figures of a job, or why it has none.
#[derive(Debug)]
pub enum TerrainFigures {
    /// The figures, in the order of [`TERRAIN_FIGURE_NAMES`].
    Drawn(Vec<Figure>),
    /// Why they are left out (a curve, a fuzzy plan, a fold).
    LeftOut(String),
}

/// Why `job` has no terrain figures; `None` for a terrain. Cheap: the
/// core's check of the plan and one volume of the crisp surface.
///
/// # Errors
/// As `terrain_view::terrain` (the core refusing a computation).
pub fn terrain_left_out(job: &Job) -> Result<Option<String>, Error> {
    Ok(match terrain_view::terrain(&job.model)? {
        Terrain::Yes(_) => None,
        Terrain::No(reason) => Some(reason),
    })
}

/// The crisp surface's contour lines at nice heights across its range (the
/// map under the shoreline): per height, polylines.
///
/// # Errors
/// As [`terrain_view::contour_map`].
pub fn contour_map(s: &FuzzySurface<3>) -> Result<Vec<terrain_view::ContourLevel>, Error> {
    let [lo, hi] = terrain_view::height_range(s);
    let heights = if lo < hi {
        nice_ticks(lo, hi, CONTOUR_MAP_LINES).0
    } else {
        Vec::new()
    };
    terrain_view::contour_map(s, &heights)
}

/// The terrain figures of `job` at `alpha`: the envelope's width on
/// [`WIDTH_MAP_CELLS`] along the longer side of the plan, the shoreline on
/// the grid of `t2spline contour`, and the fuzzy measures (computed side by
/// side on rayon's pool); or why the job has none.
///
/// # Errors
/// [`Error::Core`] if the core refuses a computation (never for a terrain).
pub fn terrain_figures(job: &Job, alpha: Alpha) -> Result<TerrainFigures, Error> {
    let s = match terrain_view::terrain(&job.model)? {
        Terrain::Yes(s) => s,
        Terrain::No(reason) => return Ok(TerrainFigures::LeftOut(reason)),
    };
    let heights = job.model.heights();
    let ((width, shoreline), measures) = rayon::join(
        || {
            rayon::join(
                || -> Result<Figure, Error> {
                    let maps = terrain_view::width_maps(s, &[alpha], WIDTH_MAP_CELLS)?;
                    let map = maps
                        .first()
                        .ok_or(Error::Core(t2spline::Error::MissingAlpha))?;
                    Ok(width_figure(map, &heights, false))
                },
                || -> Result<Figure, Error> {
                    let (contour, map) = rayon::join(
                        || terrain_view::datum_contour(s, &[alpha], None),
                        || contour_map(s),
                    );
                    Ok(shoreline_figure(&contour?, 0, &map?))
                },
            )
        },
        || terrain_view::terrain_measures(s, &heights).map(|m| terrain_measures_figure(&m)),
    );
    Ok(TerrainFigures::Drawn(vec![width?, shoreline?, measures?]))
}
