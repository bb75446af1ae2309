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

mod downloads;
mod frames;
mod pack;
mod page;
mod reductions;
mod stops;
pub mod tables;

use downloads::files_of;
#[cfg(test)]
use downloads::unpack;
use stops::finest_within;
pub use stops::Stops;

use rayon::prelude::*;
use serde_json::{json, Value};
use t2spline::job::{Job, RunOutput, Samples};
use t2spline::{Alpha, Axis, Layer, TypeReduction};

use crate::chart::layout;
use crate::chart::scene::Figure;
use crate::chart::svg;
use crate::error::Error;
use crate::figures::curve::{
    distance_figure, membership_figure, reductions_figure, section_figure, stage1_figure,
    stage2_figure, stage3_figure, stage4_figure, sweep_figure, CurveScene, Zoom,
};
use crate::figures::surface::{self, SurfaceScene};
use crate::figures::{measures_figure, number_figure, FigureOptions, MEASURES_MAX_POINTS};
use crate::{data, set_view};
use frames::{frames, Frames, Strings};
use page::{Page, Section};
use tables::{number_text, rounded};

/// The most bytes the packed per-stop data may take; the grid of stops is
/// coarsened to stay within it.
pub const DATA_BUDGET: usize = 3_500_000;

/// The most samples per curve of the result files a report carries. A job
/// sampled more finely gets, at every stop that carries files, the files of
/// `t2spline run --samples 1001` instead, and the page says so: a page needs
/// no more, and the memory and size of a report then no longer grow with
/// the job's `samples` (at 30 000 samples the files of every stop took
/// 2.9 GB, at 100 000 the report ran out of memory).
pub const MAX_FILE_SAMPLES: usize = 1001;

/// The most samples per direction of a surface's result files in a report
/// (101 × 101 at most), as [`MAX_FILE_SAMPLES`] for a curve.
pub const MAX_FILE_GRID: usize = 101;

/// The samples of the result files a report of a job sampled at `samples`
/// carries: the job's, at most [`MAX_FILE_SAMPLES`] along a curve and
/// [`MAX_FILE_GRID`] in each direction of a surface.
#[must_use]
pub(crate) fn file_samples(samples: Samples) -> Samples {
    match samples {
        Samples::Along(n) => Samples::Along(n.min(MAX_FILE_SAMPLES)),
        Samples::Grid(grid) => Samples::Grid(grid.map(|n| n.min(MAX_FILE_GRID))),
    }
}

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
fn thinned_note(job: &Job) -> Option<String> {
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

/// Renders the report of `job` (whose file text is `job_text`) with the
/// slider at `start`; `options` chooses the number shown and the aspect of
/// curve panels.
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
    let heights = job.model.heights();
    let (stops, with_files) = choose_stops(job, start, options)?;
    // Frames 0..stops: the paper's reduction at every stop; then one frame
    // per other reduction, which does not use alpha.
    let others = reductions::frames(stops.alphas.len());
    let initial = reductions::initial_frame(&others, job.type_reduction).unwrap_or(stops.initial);
    let mut shown: Vec<(Alpha, TypeReduction)> = stops
        .alphas
        .iter()
        // Stops lie in [0, 1].
        .map(|&a| Ok((Alpha::try_new(a)?, TypeReduction::Paper)))
        .collect::<Result<_, t2spline::Error>>()?;
    shown.extend(others.iter().map(|f| (start, f.method)));
    // Every frame on its own, in parallel; then gathered in order.
    let computed: Vec<Result<Frame, Error>> = shown
        .par_iter()
        .enumerate()
        .map(|(k, &(alpha, method))| {
            Frame::compute(
                job,
                alpha,
                method,
                &heights,
                options,
                &with_files,
                k == initial,
            )
        })
        .collect();
    let mut frame_data = Vec::with_capacity(shown.len());
    let mut kinds: [Vec<Figure>; 4] = Default::default();
    let mut files: Vec<(String, Vec<String>)> = Vec::new();
    // The start's figure run also draws the figures that do not change.
    let mut start_figure_run = None;
    for frame in computed {
        let frame = frame?;
        start_figure_run = start_figure_run.or(frame.figure_run);
        for (list, f) in kinds.iter_mut().zip(frame.figures) {
            list.push(f);
        }
        for (k, (name, text)) in frame.files.into_iter().enumerate() {
            match files.get_mut(k) {
                Some((_, texts)) => texts.push(text),
                None => files.push((name, vec![text])),
            }
        }
        frame_data.push(frame.run);
    }
    let Some(start_run) = frame_data.get(initial).cloned() else {
        return Err(Error::Core(t2spline::Error::MissingAlpha));
    };
    // The distance against alpha is the paper's: a frame per slider stop,
    // shown at the slider's stop whatever the reduction.
    let distance = distance_figure(job, start.get())?;
    let distances: Vec<Figure> = stops
        .alphas
        .iter()
        .map(|&a| with_alpha_rule(&distance, a))
        .collect();
    let probes = stops.probes(&heights);
    let mut all_probes = probes.clone();
    all_probes.extend(others.iter().map(|f| f.frame));
    let mut strings = Strings::default();
    let mut figs: Vec<Frames> = kinds
        .iter()
        .zip(["fn-", "s2-", "s3-", "s4-"])
        .map(|(list, prefix)| frames(list, initial, &all_probes, prefix, &mut strings))
        .collect();
    let mut da = frames(&distances, stops.initial, &probes, "da-", &mut strings);
    da.data["paper"] = json!(true);
    figs.push(da);
    let table_defs = tables::tables(&start_run);
    let stops_json: Vec<Value> = shown
        .iter()
        .zip(&frame_data)
        .map(|((a, _), r)| stop_json(a.get(), r, &heights, &table_defs))
        .collect();
    let data_block = json!({
        "initial": initial,
        "step": stops.step_text(),
        "reductions": reductions::json(&others),
        "stops": stops_json,
        "figures": figs.iter().map(|f| f.data.clone()).collect::<Vec<_>>(),
        "strings": strings.into_json(),
        "downloads": downloads::pack(&files),
        "files_at": with_files.index_json(&shown),
        "files_note": with_files.note(job),
    });
    // Frame `initial` is the start, with the job's reduction.
    let Some(fig_result) = start_figure_run else {
        return Err(Error::Core(t2spline::Error::MissingAlpha));
    };
    let surface = job.model.is_surface();
    let (stage1, sweep, compared, set_figures, measures) = if surface {
        let scene = SurfaceScene::new(&fig_result, &heights, options.view, options.aspect);
        (
            static_svg(&surface::stage1_figure(&scene)),
            None,
            None,
            None,
            None,
        )
    } else {
        let scene = CurveScene::new(&fig_result, &heights, options.aspect);
        let zero = set_view::regions(&job.model, Alpha::ZERO, &scene.axes())?;
        let set_figures = match job.model {
            t2spline::job::Model::Planar(_) => Some((
                static_svg(&membership_figure(job, &scene)?),
                static_svg(&section_figure(job, &scene, options.station)?),
            )),
            _ => None,
        };
        // Beyond MEASURES_MAX_POINTS the largest length and the area are
        // branch-and-bound brackets, too slow for a page (`t2spline measure`
        // gives them), and the section is left out.
        let measures = (job.model.control_point_count() <= MEASURES_MAX_POINTS)
            .then(|| measures_figure(job).map(|f| static_svg(&f)))
            .transpose()?;
        (
            static_svg(&stage1_figure(&scene, &zero)),
            Some(static_svg(&sweep_figure(job)?)),
            Some(static_svg(&reductions_figure(job, start, options.aspect)?)),
            set_figures,
            measures,
        )
    };
    let table_html: Vec<String> = table_defs
        .iter()
        .map(|t| tables::html(t, &start_run))
        .collect();
    let mut page = Page::default();
    let contents: Vec<(&str, &str)> = [
        ("number", "One number"),
        ("stage1", "Stage 1"),
        ("stage2", "Stage 2"),
        ("stage3", "Stage 3"),
        ("stage4", "Stage 4"),
        ("distance", "Distance and α"),
        ("measures", "Measures"),
        ("membership", "Membership"),
        ("section", "Section"),
        ("reductions", "Type reductions"),
        ("job", "The job"),
    ]
    .into_iter()
    .filter(|(id, _)| *id != "reductions" || compared.is_some())
    .filter(|(id, _)| *id != "measures" || measures.is_some())
    .filter(|(id, _)| !matches!(*id, "membership" | "section") || set_figures.is_some())
    .collect();
    page.header(job.description.as_deref(), &start_run, &heights, &contents);
    page.controls(
        &stops,
        &heights,
        &start_run,
        &reductions::selector(job.type_reduction),
        thinned_note(job).as_deref(),
    );
    let number_caption = format!(
        "Coordinate {} of control point {}: its upper (UMF), primary and lower (LMF) membership functions, the cut at α and the paper's type-reduced triangle with its centroid, and below the axis the other reductions (none uses α). Other numbers: t2spline report --point {} --axis x|y|z.",
        options.number.axis.name(),
        options.number.point_name(&job.model),
        if job.model.is_surface() { "I,J" } else { "I" }
    );
    let captions = if surface {
        SURFACE_CAPTIONS
    } else {
        CURVE_CAPTIONS
    };
    let compared_caption = format!(
        "The solution curve of every type reduction and its distance to the crisp curve; the paper's at the starting α = {}. Each equals t2spline run --type-reduction NAME.",
        number_text(Some(start.get()))
    );
    for s in [
        Section { id: "number", title: "One fuzzy number (paper Figs. 3.1, 4.1–4.4)", svg: &figs[0].svg, figure: "number", caption: &number_caption, csv: None, tables: vec![] },
        Section { id: "stage1", title: captions[0], svg: &stage1, figure: "stage1-fuzzy", caption: "Does not depend on α.", csv: Some("stage1-layers.csv"), tables: vec![fuzzy_points_table(job, &start_run)] },
        Section { id: "stage2", title: "Stage 2: alpha-cut (Fig. 5.2)", svg: &figs[1].svg, figure: "stage2-alpha-cut", caption: "Cut ends of every number at α; a lower end is null above its height h.", csv: Some("stage2-alpha-cut.csv"), tables: vec![table_html[0].clone()] },
        Section { id: "stage3", title: "Stage 3: type reduction (Fig. 5.3)", svg: &figs[2].svg, figure: "stage3-type-reduced", caption: captions[1], csv: Some("stage3-type-reduced.csv"), tables: vec![table_html[1].clone()] },
        Section { id: "stage4", title: "Stage 4: defuzzification and distance (Fig. 5.4)", svg: &figs[3].svg, figure: "stage4-defuzzified", caption: captions[2], csv: Some("stage4-defuzzified.csv"), tables: vec![table_html[2].clone(), table_html[3].clone()] },
        Section { id: "distance", title: "The distance as α varies", svg: &figs[4].svg, figure: "distance-alpha", caption: "Largest and rms distance against α for the paper's type reduction, with both sides of every h; the vertical line is the slider's α.", csv: None, tables: vec![] },
    ] {
        page.section(&s);
    }
    if let Some(measures) = &measures {
        page.section(&Section {
            id: "measures",
            title: "The fuzzy length and area (docs/method.md §11)",
            svg: measures,
            figure: "measures",
            caption: "The arc length and the area of every curve whose control points lie inside their cuts, as type-2 fuzzy numbers: at each level α the upper, primary and lower functions' intervals (the extension principle); the crisp curve's values marked. A layer curve's length is not a bound. Does not depend on the slider; t2spline measure prints the intervals.",
            csv: None,
            tables: vec![],
        });
    }
    if let Some(sweep) = &sweep {
        page.section(&Section {
            id: "sweep",
            title: "Where along the curve the solution moves",
            svg: sweep,
            figure: "alpha-sweep",
            caption: "‖D(t) − C(t)‖ against t for several α, the paper's type reduction; does not depend on the slider.",
            csv: None,
            tables: vec![],
        });
    }
    if let Some((map, section)) = &set_figures {
        page.section(&Section {
            id: "membership",
            title: "The fuzzy curve as a set: membership in the plane",
            svg: map,
            figure: "membership",
            caption: "The grade of every point of the plane, upper and lower: the largest α at which some curve with control points inside their cuts passes through it. The outlines are the regions at α = 0.2, 0.4, 0.6 and 0.8; stage 2 shades the region at the slider's α. Does not depend on the slider.",
            csv: None,
            tables: vec![],
        });
        page.section(&Section {
            id: "section",
            title: "The fuzzy value of y at a station",
            svg: section,
            figure: "section",
            caption: "The upper, primary and lower membership of y at the station (t2spline report --station X0), drawn as one fuzzy number, cut at the starting α; t2spline section prints its intervals.",
            csv: None,
            tables: vec![],
        });
    }
    if let Some(compared) = &compared {
        page.section(&Section {
            id: "reductions",
            title: "The type reductions compared (docs/method.md §9)",
            svg: compared,
            figure: "reductions",
            caption: &compared_caption,
            csv: None,
            tables: vec![],
        });
    }
    page.job(job_text);
    page.finish(&pack::pack(&data_block));
    Ok(page.html)
}

/// Titles of the stage 1 section, captions of the stage 3 and 4 sections.
const CURVE_CAPTIONS: [&str; 3] = [
    "Stage 1: the fuzzy control points and layer curves (Fig. 5.1)",
    "Each control point becomes a type-1 triangle (left, crisp, right); with the centroid or alpha-planes, left and right are the centroid interval [c_l, c_r], which need not contain crisp; with Nie–Tan they are its one value.",
    "The distance between the crisp and the defuzzified curve at equal t, over the whole domain; the right panel magnifies its largest value, with both curves computed anew there.",
];

/// [`CURVE_CAPTIONS`] of a surface job.
const SURFACE_CAPTIONS: [&str; 3] = [
    "Stage 1: the fuzzy control net and layer surfaces",
    "Each control point becomes a type-1 triangle (left, crisp, right), or with the centroid or alpha-planes the interval [c_l, c_r], with Nie–Tan one value; the map shows how far apart the left and right surfaces are.",
    "The crisp surface coloured by its distance to the defuzzified one at equal (u, v); the map marks where the distance is largest (error.max_at).",
];

/// The stops, and those that carry the downloads: as fine a grid as the
/// packed size of two sample stops allows within [`DATA_BUDGET`], less the
/// frames of the reductions other than the paper's, with the downloads at
/// every frame while that grid is 0.05 or finer, and always for a curve. A
/// larger surface job (sampled finely, its files are most of a stop: 2 MB at
/// 101 × 101) carries the downloads on a coarser grid, at the start only or
/// not at all ([`FileStops`]), so that its figures still get fine stops. The
/// samples (α = 0.3 and 0.9, the paper's reduction) do not depend on the
/// start, so a job gets the same grid whatever alpha its report starts at.
fn choose_stops(
    job: &Job,
    start: Alpha,
    options: &FigureOptions,
) -> Result<(Stops, FileStops), Error> {
    let heights = job.model.heights();
    // The packed sizes of each sample stop's files and figures, the two
    // stops in parallel.
    let sizes: Vec<Result<(usize, usize), Error>> = [0.3, 0.9]
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
            Ok((
                pack::packed_len(&json!(files)),
                pack::packed_len(&json!(figures)),
            ))
        })
        .collect();
    let (mut total, mut whole, mut figures_cost) = (0, 0, 0);
    for size in sizes {
        let (f, g) = size?;
        // Measured on jobs of 4 to 200 points: a stop's packed downloads take
        // a third of a whole result's files packed alone (half its numbers
        // change, and the CSV files repeat the result's), and its figure
        // parts a bit under half of its whole figures.
        total += f / 3 + g * 9 / 20;
        whole += f;
        figures_cost += g;
    }
    let per_stop = (total / 2).max(1);
    let others = reductions::count();
    let budget = DATA_BUDGET.saturating_sub(others.saturating_mul(per_stop));
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
enum FileStops {
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
    fn carries(&self, alpha: f64, method: TypeReduction) -> bool {
        let paper = method == TypeReduction::Paper;
        match self {
            FileStops::Every => true,
            FileStops::Grid(s) => paper && s.alphas.contains(&alpha),
            FileStops::Start(a) => paper && *a == alpha,
            FileStops::None(_) => false,
        }
    }

    /// Per frame of `shown`, the index of its downloads, or `null`.
    fn index_json(&self, shown: &[(Alpha, TypeReduction)]) -> Value {
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
    fn note(&self, job: &Job) -> Value {
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

/// What one frame of the report holds.
struct Frame {
    /// The figures that change: the number and stages 2–4.
    figures: [Figure; 4],
    /// The run whose numbers the frame shows.
    run: RunOutput,
    /// The downloads, if the frame carries them: (file name, text).
    files: Vec<(String, String)>,
    /// The run the figures were drawn from, kept for the start's frame.
    figure_run: Option<RunOutput>,
}

impl Frame {
    /// The frame at `alpha` with `method`; `start` keeps its figure run.
    fn compute(
        job: &Job,
        alpha: Alpha,
        method: TypeReduction,
        heights: &[f64],
        options: &FigureOptions,
        with_files: &FileStops,
        start: bool,
    ) -> Result<Frame, Error> {
        let (figures, figure_run) = stop_figures(job, alpha, method, heights, options)?;
        let kept = start.then(|| figure_run.clone());
        // The numbers a stop shows (control points, the distance's max, its
        // place and rms) do not depend on the samples, so the run its
        // figures were drawn from gives them; only the files need the run
        // at the job's own samples (at most [`MAX_FILE_SAMPLES`]).
        let (run, files) = if with_files.carries(alpha.get(), method) {
            let run = data::run_with(job, alpha, method, file_samples(job.samples))?;
            let files = files_of(&run)?;
            (run, files)
        } else {
            (figure_run, Vec::new())
        };
        Ok(Frame {
            figures,
            run,
            files,
            figure_run: kept,
        })
    }
}

/// The figures that change with alpha and the type reduction `method`: the
/// number and stages 2–4, with the run (at the figures' samples) they were
/// drawn from.
fn stop_figures(
    job: &Job,
    alpha: Alpha,
    method: TypeReduction,
    heights: &[f64],
    options: &FigureOptions,
) -> Result<([Figure; 4], RunOutput), Error> {
    let r = data::compute_within(job, alpha, method, data::REPORT_SURFACE_GRID)?;
    let figures = if job.model.is_surface() {
        let scene = SurfaceScene::new(&r, heights, options.view, options.aspect);
        [
            number_figure(job, alpha, method, options.number)?,
            surface::stage2_figure(&scene),
            surface::stage3_figure(&scene),
            surface::stage4_figure(job, &scene)?,
        ]
    } else {
        let scene = CurveScene::new(&r, heights, options.aspect);
        // The regions at the level stage 2 cuts at (0 for a reduction that
        // does not use alpha), so the slider shows the region at each stop.
        let at = set_view::regions(&job.model, Alpha::try_new(r.alpha)?, &scene.axes())?;
        [
            number_figure(job, alpha, method, options.number)?,
            stage2_figure(&scene, &at),
            stage3_figure(&scene),
            stage4_figure(job, &scene, Zoom::Always)?,
        ]
    };
    Ok((figures, r))
}

/// The distance figure with its alpha line at `alpha`.
fn with_alpha_rule(fig: &Figure, alpha: f64) -> Figure {
    let mut f = fig.clone();
    for p in &mut f.panels {
        for item in &mut p.items {
            if item.key == "alpha" {
                item.mark = crate::figures::curve::alpha_rule(alpha);
            }
        }
    }
    f
}

/// A figure that does not change with alpha, as one SVG.
fn static_svg(fig: &Figure) -> String {
    let mut l = layout::fit(&[fig]);
    l.tolerance = frames::REPORT_TOLERANCE;
    svg::document(&l, &fig.title, &svg::parts(fig, &l, ""), None)
}

/// One frame's numbers: alpha (null when the reduction does not use it),
/// the reduction, regime, the distance, the table cells.
fn stop_json(a: f64, r: &RunOutput, heights: &[f64], defs: &[tables::Table]) -> Value {
    let pair = |v: f64| json!([number_text(Some(v)), rounded(Some(v))]);
    let cells: serde_json::Map<String, Value> = defs
        .iter()
        .map(|t| (t.id.to_owned(), json!(tables::cells(t, r))))
        .collect();
    let mut bar = serde_json::Map::new();
    bar.insert("m-max".into(), pair(r.error.max));
    for (id, v) in page::max_at_ids(r.error.max_at) {
        bar.insert(id.into(), pair(v));
    }
    bar.insert("m-rms".into(), pair(r.error.rms));
    let (alpha, shown) = if r.alpha_used {
        (json!(number_text(Some(a))), json!(rounded(Some(a))))
    } else {
        (Value::Null, json!("not used"))
    };
    json!({
        "alpha": alpha,
        "shown": shown,
        "reduction": r.type_reduction.name(),
        "regime": reductions::regime_text(r),
        "at_h": r.alpha_used && heights.contains(&a),
        "bar": bar,
        "cells": cells,
    })
}

/// The stage-1 table: every number's seven values and height (the first
/// [`tables::MAX_TABLE_POINTS`] points).
fn fuzzy_points_table(job: &Job, r: &RunOutput) -> String {
    use std::fmt::Write as _;
    let n = r.control_points.crisp.len();
    let shown = n.min(tables::MAX_TABLE_POINTS);
    let open = if n == shown { " open" } else { "" };
    let mut s = format!("<details class=\"table\"{open}><summary>Fuzzy control points (the job)</summary>\n<div class=\"scroll\"><table id=\"table-fuzzy\"><thead><tr><th>point</th><th>coord.</th><th>weight</th>");
    for l in Layer::ALL {
        let _ = write!(s, "<th>{}</th>", l.name().replace('_', "."));
    }
    s.push_str("<th>h</th></tr></thead><tbody>\n");
    let cell =
        |v: Option<f64>| format!("<td data-value=\"{}\">{}</td>", number_text(v), rounded(v));
    for k in 0..shown {
        for (a, axis) in Axis::ALL.iter().take(r.dimension).enumerate() {
            let _ = write!(
                s,
                "<tr><th scope=\"row\">{k}</th><th scope=\"row\">{}</th>{}",
                axis.name(),
                cell(r.spline.weights().get(k).copied())
            );
            for l in Layer::ALL {
                let points = r
                    .control_points
                    .layers
                    .get(l)
                    .unwrap_or(&r.control_points.crisp);
                s.push_str(&cell(points.coord(a).get(k).copied()));
            }
            let h = data::number(&job.model, k, *axis)
                .ok()
                .map(|x| x.height().get());
            let _ = writeln!(s, "{}</tr>", cell(h));
        }
    }
    s.push_str("</tbody></table></div>\n");
    if n > shown {
        let _ = writeln!(
            s,
            "<p class=\"note\">The first {shown} control points; all {n} are in the job below.</p>"
        );
    }
    s.push_str("</details>\n");
    s
}

#[cfg(test)]
mod tests;
