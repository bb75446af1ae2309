//! The terrain figures that follow the slider (`envelope-width` and
//! `shoreline`, a frame per stop, computed for all stops at once: one
//! envelope and one contour of the core over every stop's level) and the
//! one that does not (`terrain-measures`). A surface that is not a terrain
//! gets the core's reason, which the page shows in their place.

use t2spline::job::Job;
use t2spline::Alpha;

use crate::chart::scene::Figure;
use crate::error::Error;
use crate::figures::surface::{shoreline_figure, width_figure};
use crate::figures::{contour_map, terrain_measures_figure};
use crate::terrain_view::{self, Terrain, REPORT_CONTOUR_CELLS, REPORT_WIDTH_MAP_CELLS};

/// The width maps and the shorelines at every stop.
pub(super) type SliderFigures = (Vec<Figure>, Vec<Figure>);

/// The terrain figures of a report.
#[derive(Debug)]
pub(super) enum TerrainFrames {
    /// Per stop the width map and the shoreline; the fuzzy measures once.
    Drawn {
        /// `envelope-width` at every stop.
        widths: Vec<Figure>,
        /// `shoreline` at every stop.
        shorelines: Vec<Figure>,
        /// `terrain-measures`.
        measures: Box<Figure>,
    },
    /// Not a terrain (or a curve): the core's reason.
    LeftOut(String),
}

/// The width maps and shorelines of `job`'s terrain at `alphas` (all in one
/// envelope and one contour of the core, on the report's coarser grids
/// [`REPORT_WIDTH_MAP_CELLS`] and [`REPORT_CONTOUR_CELLS`]); `None` for a
/// job that is not a terrain.
///
/// # Errors
/// [`Error::Core`] if the core refuses (never for a terrain).
pub(super) fn slider_figures(job: &Job, alphas: &[f64]) -> Result<Option<SliderFigures>, Error> {
    let Terrain::Yes(s) = terrain_view::terrain(&job.model)? else {
        return Ok(None);
    };
    let heights = job.model.heights();
    let levels: Vec<Alpha> = alphas
        .iter()
        .map(|&a| Alpha::try_new(a))
        .collect::<Result<_, _>>()?;
    let (maps, (contour, map)) = rayon::join(
        || terrain_view::width_maps(s, &levels, REPORT_WIDTH_MAP_CELLS),
        || {
            rayon::join(
                || terrain_view::datum_contour(s, &levels, Some(REPORT_CONTOUR_CELLS)),
                || contour_map(s),
            )
        },
    );
    let (maps, contour, map) = (maps?, contour?, map?);
    let widths = maps
        .iter()
        .map(|m| width_figure(m, &heights, true))
        .collect();
    let shorelines = (0..contour.levels.len())
        .map(|k| shoreline_figure(&contour, k, &map))
        .collect();
    Ok(Some((widths, shorelines)))
}

impl TerrainFrames {
    /// The terrain figures of `job` at the slider's `alphas`.
    ///
    /// # Errors
    /// [`Error::Core`] if the core refuses (never for a terrain).
    pub(super) fn compute(job: &Job, alphas: &[f64]) -> Result<TerrainFrames, Error> {
        let s = match terrain_view::terrain(&job.model)? {
            Terrain::Yes(s) => s,
            Terrain::No(reason) => return Ok(TerrainFrames::LeftOut(reason)),
        };
        let heights = job.model.heights();
        let (slider, measures) = rayon::join(
            || slider_figures(job, alphas),
            || terrain_view::terrain_measures(s, &heights),
        );
        let Some((widths, shorelines)) = slider? else {
            return Ok(TerrainFrames::LeftOut(String::new()));
        };
        Ok(TerrainFrames::Drawn {
            widths,
            shorelines,
            measures: Box::new(terrain_measures_figure(&measures?)),
        })
    }
}
