//! Every frame of a report computed: the paper's reduction at each stop and
//! each other reduction once, in parallel, then gathered in order (the
//! figures that change, the run whose numbers a frame shows, its downloads).

use rayon::prelude::*;
use t2spline::job::{Job, RunOutput};
use t2spline::{Alpha, TypeReduction};

use super::budget::file_samples;
use super::downloads::files_of;
use super::file_stops::FileStops;
use super::reductions::{self, ReductionFrame};
use super::stop_figures::stop_figures;
use super::stops::Stops;
use crate::chart::scene::Figure;
use crate::data;
use crate::error::Error;
use crate::figures::FigureOptions;

/// The frames of a report, gathered in order.
pub(super) struct Computed {
    /// Frames 0..stops: the paper's reduction at every stop; then one frame
    /// per other reduction, which does not use alpha.
    pub shown: Vec<(Alpha, TypeReduction)>,
    /// The other reductions' frames.
    pub others: Vec<ReductionFrame>,
    /// The frame the page starts at (the job's reduction at the start).
    pub initial: usize,
    /// Per kind of changing figure (number, stages 2–4), its every frame.
    pub kinds: [Vec<Figure>; 4],
    /// The downloads: per file name, its text at each frame that has it.
    pub files: Vec<(String, Vec<String>)>,
    /// Per frame, the run whose numbers it shows.
    pub runs: Vec<RunOutput>,
    /// The run the start's figures were drawn from; it also draws the
    /// figures that do not change.
    pub figure_run: RunOutput,
}

impl Computed {
    /// Every frame of `job`'s report at `stops`, starting at `start`.
    pub(super) fn all(
        job: &Job,
        start: Alpha,
        stops: &Stops,
        with_files: &FileStops,
        options: &FigureOptions,
    ) -> Result<Computed, Error> {
        let heights = job.model.heights();
        let others = reductions::frames(stops.alphas.len());
        let initial =
            reductions::initial_frame(&others, job.type_reduction).unwrap_or(stops.initial);
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
                    with_files,
                    k == initial,
                )
            })
            .collect();
        let mut runs = Vec::with_capacity(shown.len());
        let mut kinds: [Vec<Figure>; 4] = Default::default();
        let mut files: Vec<(String, Vec<String>)> = Vec::new();
        let mut figure_run = None;
        for frame in computed {
            let frame = frame?;
            figure_run = figure_run.or(frame.figure_run);
            for (list, f) in kinds.iter_mut().zip(frame.figures) {
                list.push(f);
            }
            for (k, (name, text)) in frame.files.into_iter().enumerate() {
                match files.get_mut(k) {
                    Some((_, texts)) => texts.push(text),
                    None => files.push((name, vec![text])),
                }
            }
            runs.push(frame.run);
        }
        let Some(figure_run) = figure_run else {
            return Err(Error::Core(t2spline::Error::MissingAlpha));
        };
        Ok(Computed {
            shown,
            others,
            initial,
            kinds,
            files,
            runs,
            figure_run,
        })
    }

    /// The run of the frame the page starts at.
    pub(super) fn start_run(&self) -> Result<&RunOutput, Error> {
        self.runs
            .get(self.initial)
            .ok_or(Error::Core(t2spline::Error::MissingAlpha))
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
