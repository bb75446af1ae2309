//! The HTML report: one self-contained file (no network, no external scripts,
//! styles or fonts) with every figure, an alpha slider and number field that
//! update the figures, tables and distance, downloads of each figure (SVG,
//! PNG) and of the result at the shown alpha (JSON, CSV, the bytes of
//! `t2spline run`), and the job itself.
//!
//! The slider stops on a grid of alpha ([`Stops`]: 0.01 apart for small jobs,
//! coarser as the job grows, to keep the file within [`DATA_BUDGET`]), at
//! every lower height h and at the starting alpha. A selector switches the
//! type reduction of stages 3–4 (docs/method.md §9): the paper's has a frame per
//! slider stop, each other reduction one frame after them (it does not use
//! alpha). For every frame the numbers shown, the changing parts of the
//! figures and the downloads are computed here, in Rust, by the same library
//! calls as `t2spline run --alpha A --type-reduction NAME`, and embedded
//! compressed ([`pack`]); the page's script only unpacks and swaps them in.
//! Numbers are written as `run` writes them, so they agree to the last
//! digit.
//!
//! The report's memory and size do not grow with the job's `samples`: the
//! figures are drawn from a sampling of their own, and the result files are
//! those of the job's samples up to [`MAX_FILE_SAMPLES`] per curve
//! ([`MAX_FILE_GRID`] per direction of a surface); beyond, they are
//! `t2spline run --samples 1001`'s (`101,101`), and the page says so and
//! that `t2spline run` gives the full result.

mod budget;
mod computed;
mod data_block;
mod downloads;
mod file_stops;
mod frames;
mod pack;
mod page;
mod reductions;
mod sections;
mod stop_figures;
mod stops;
pub mod tables;
mod terrain_frames;

pub use budget::{DATA_BUDGET, MAX_FILE_GRID, MAX_FILE_SAMPLES};
pub use stops::Stops;

use t2spline::job::Job;
use t2spline::Alpha;

use crate::error::Error;
use crate::figures::FigureOptions;
use computed::Computed;
use data_block::DataBlock;
use sections::Still;
use terrain_frames::TerrainFrames;

/// Renders the report of `job` (whose file text is `job_text`) with the
/// slider at `start`; `options` chooses the number shown and the aspect of
/// curve panels.
///
/// Five steps, a module each: the stops (`file_stops`), every frame computed
/// (`computed`), a terrain's width maps and shorelines at every stop and
/// its fuzzy measures (`terrain_frames`), the data block the page swaps in
/// (`data_block`), and the page's sections around the figures that do not
/// change (`sections`).
///
/// # Errors
/// [`Error::NoSuchPoint`] or [`Error::NoSuchAxis`] if `options.number` names
/// a point or coordinate the job lacks; otherwise only if the library cannot
/// evaluate a curve where the result says the distance is largest (never for
/// a validated job).
pub fn render(
    job: &Job,
    job_text: &str,
    start: Alpha,
    options: &FigureOptions,
) -> Result<String, Error> {
    let (stops, with_files) = file_stops::choose_stops(job, start, options)?;
    let frames = Computed::all(job, start, &stops, &with_files, options)?;
    let terrain = TerrainFrames::compute(job, &stops.alphas)?;
    let block = DataBlock::build(job, start, &stops, &with_files, &frames, &terrain)?;
    let still = Still::draw(job, &frames.figure_run, start, options, &terrain)?;
    sections::page(
        job, job_text, start, options, &stops, &frames, &still, &block,
    )
}

#[cfg(test)]
mod tests;
