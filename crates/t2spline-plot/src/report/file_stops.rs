//! Which stops a report has and which of them carry the downloads: as fine
//! a grid of alpha as the report's budget allows ([`choose_stops`]), and what
//! the page says where the result files are thinned or left out.

use rayon::prelude::*;
use serde_json::{json, Value};
use t2spline::job::{Job, Samples};
use t2spline::{Alpha, TypeReduction};

use super::budget::{file_samples, DATA_BUDGET};
use super::downloads::files_of;
use super::frames::static_svg;
use super::stop_figures::stop_figures;
use super::stops::{self, finest_within, Stops};
use super::terrain_frames::slider_figures;
use super::{pack, reductions};
use crate::data;
use crate::error::Error;
use crate::figures::FigureOptions;

/// Samples as the page writes them: `1001`, or `101 × 101` for a grid.
fn samples_text(samples: Samples) -> String {
    match samples {
        Samples::Along(n) => n.to_string(),
        Samples::Grid([u, v]) => format!("{u} × {v}"),
    }
}

/// Samples as `--samples` takes them: `1001`, or `101,101`.
fn samples_option(samples: Samples) -> String {
    match samples {
        Samples::Along(n) => n.to_string(),
        Samples::Grid([u, v]) => format!("{u},{v}"),
    }
}

/// What the page says, under the slider, of result files sampled more
/// coarsely than the job ([`file_samples`]); `None` when they are the job's.
pub(super) fn thinned_note(job: &Job) -> Option<String> {
    let files = file_samples(job.samples);
    (files != job.samples).then(|| {
        format!(
            "The job samples {}; to keep the report small its result files (JSON, CSV) are sampled at {}, the most a report carries: they are the bytes of <code>t2spline run JOB --samples {} --alpha A</code>. <code>t2spline run JOB</code> gives the full result at the job's samples. The figures are drawn from a sampling of their own.",
            samples_text(job.samples),
            samples_text(files),
            samples_option(files),
        )
    })
}

/// The stops, and those that carry the downloads: as fine a grid as the
/// packed size of two sample stops allows within [`DATA_BUDGET`], less the
/// frames of the reductions other than the paper's, with the downloads at
/// every frame while that grid is 0.05 or finer, and always for a curve. A
/// larger surface job (sampled finely, its files are most of a stop: 2 MB at
/// 101 × 101) carries the downloads on a coarser grid, at the start only or
/// not at all ([`FileStops`]), so that its figures still get fine stops. The
/// samples (α = 0.3 and 0.9, the paper's reduction) do not depend on the
/// start, so a job gets the same grid whatever alpha its report starts at.
pub(super) fn choose_stops(
    job: &Job,
    start: Alpha,
    options: &FigureOptions,
) -> Result<(Stops, FileStops), Error> {
    let heights = job.model.heights();
    // The packed sizes of each sample stop's files and figures, the two
    // stops in parallel.
    let sizes: Vec<Result<(usize, usize, usize), Error>> = [0.3, 0.9]
        .par_iter()
        .map(|&a| {
            let alpha = Alpha::try_new(a)?;
            let run = data::run_with(job, alpha, TypeReduction::Paper, file_samples(job.samples))?;
            let files: Vec<String> = files_of(&run)?.into_iter().map(|(_, t)| t).collect();
            // Drawn as the report stores them: lines and regions simplified
            // to the report's tolerance.
            let figures: Vec<String> =
                stop_figures(job, alpha, TypeReduction::Paper, &heights, options)?
                    .0
                    .iter()
                    .map(static_svg)
                    .collect();
            // A terrain's width map and shoreline follow the slider too,
            // in the paper's frames only, each drawn anew at every stop.
            let terrain: Vec<String> = match slider_figures(job, &[a])? {
                Some((widths, shorelines)) => {
                    widths.iter().chain(&shorelines).map(static_svg).collect()
                }
                None => Vec::new(),
            };
            Ok((
                pack::packed_len(&json!(files)),
                pack::packed_len(&json!(figures)),
                if terrain.is_empty() {
                    0
                } else {
                    pack::packed_len(&json!(terrain))
                },
            ))
        })
        .collect();
    let (mut total, mut whole, mut figures_cost, mut terrain_cost) = (0, 0, 0, 0);
    for size in sizes {
        let (f, g, t) = size?;
        terrain_cost += t;
        // Measured on jobs of 4 to 200 points: a stop's packed downloads take
        // a third of a whole result's files packed alone (half its numbers
        // change, and the CSV files repeat the result's), and its figure
        // parts a bit under half of its whole figures.
        total += f / 3 + g * 9 / 20;
        whole += f;
        figures_cost += g;
    }
    let terrain_cost = terrain_cost / 2;
    let per_stop = (total / 2).max(1);
    let others = reductions::count();
    let budget = DATA_BUDGET.saturating_sub(others.saturating_mul(per_stop));
    let per_stop = per_stop + terrain_cost;
    let all = finest_within(job, start, per_stop, budget);
    if all.per_unit >= FILES_EVERYWHERE || !job.model.is_surface() {
        return Ok((all, FileStops::Every));
    }
    // A surface's figures change more from stop to stop than a curve's: its
    // stored parts take about three quarters of its whole figures (measured
    // on the terrain example and 40 × 40 nets), not 9/20. The frames of the
    // other reductions carry figures only.
    let (whole, figures_cost) = ((whole / 2).max(1), (figures_cost * 3 / 8).max(1));
    let files_cost = (whole / 3).max(1);
    let budget = DATA_BUDGET.saturating_sub(others.saturating_mul(figures_cost));
    let figures_cost = figures_cost + terrain_cost;
    if whole > budget / 2 {
        // A result this large takes most of a stop's time to compute (every
        // stop needs its exact distance), so the figures get half the budget.
        let stops = finest_within(job, start, figures_cost, budget / 2);
        return Ok((stops, FileStops::None(whole)));
    }
    // The start's files whole; the figures' grid within what is left.
    let stops = finest_within(job, start, figures_cost, budget - whole);
    let figures_bytes = stops.alphas.len() * figures_cost + whole;
    let files = stops::STEPS
        .iter()
        .filter(|&&n| stops.per_unit % n == 0)
        .map(|&n| Stops::new(job, start, n))
        .find(|s| figures_bytes + s.alphas.len() * files_cost <= budget)
        .map_or(FileStops::Start(start.get()), FileStops::Grid);
    Ok((stops, files))
}

/// Grids of stops this fine or finer carry the downloads at every stop.
const FILES_EVERYWHERE: u32 = 20;

/// The frames that carry the downloads.
#[derive(Debug)]
pub(super) enum FileStops {
    /// Every frame.
    Every,
    /// The paper's frames at the stops of a coarser grid (with every h and
    /// the start).
    Grid(Stops),
    /// The paper's frame at the starting alpha.
    Start(f64),
    /// None: one stop's files would take this many bytes, more than half
    /// the report's budget.
    None(usize),
}

impl FileStops {
    /// Whether the frame at `alpha` with `method` carries the downloads.
    pub(super) fn carries(&self, alpha: f64, method: TypeReduction) -> bool {
        let paper = method == TypeReduction::Paper;
        match self {
            FileStops::Every => true,
            FileStops::Grid(s) => paper && s.alphas.contains(&alpha),
            FileStops::Start(a) => paper && *a == alpha,
            FileStops::None(_) => false,
        }
    }

    /// Per frame of `shown`, the index of its downloads, or `null`.
    pub(super) fn index_json(&self, shown: &[(Alpha, TypeReduction)]) -> Value {
        let mut next = 0;
        shown
            .iter()
            .map(|&(a, method)| {
                if self.carries(a.get(), method) {
                    next += 1;
                    json!(next - 1)
                } else {
                    Value::Null
                }
            })
            .collect()
    }

    /// What the page says at a frame of `job` without downloads (before the
    /// `run` command that writes them), or `null` if every frame has them.
    pub(super) fn note(&self, job: &Job) -> Value {
        let where_ = match self {
            FileStops::Every => return Value::Null,
            FileStops::Grid(s) => format!(
                "at α = 0, {}, …, 1, at every h and at the starting α",
                s.step_text()
            ),
            FileStops::Start(_) => "at the starting α only".to_owned(),
            FileStops::None(bytes) => {
                let files = file_samples(job.samples);
                let at = if files == job.samples {
                    "at the job's samples".to_owned()
                } else {
                    format!("even at {} samples", samples_text(files))
                };
                return json!(format!(
                    "The result files are left out of this report: {at} they would take {:.1} MB at every α",
                    *bytes as f64 / 1e6
                ));
            }
        };
        json!(format!(
            "To keep the report small, the result files are in it {where_}"
        ))
    }
}
