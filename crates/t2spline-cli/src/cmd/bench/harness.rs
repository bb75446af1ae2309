//! The timings behind `t2spline bench`: the sampling engine on one model,
//! timed as the median of five runs after one warm-up run.
//!
//! This module measures wall time (`std::time::Instant`) and nothing else; the
//! criterion benchmarks in `benches/` time the same cases on the same
//! benchmark curve ([`t2spline::sampling::benchmark_curve`]).

use std::fmt;
use std::hint::black_box;
use std::time::Instant;

use t2spline::job::{Model, ModelVisitor, Setting};
use t2spline::sampling::{
    benchmark_levels, CurveSamples, Grid, LayerSamples, Params, SweepSamples, MAX_OUTPUT_BYTES,
};
use t2spline::{Error, FuzzyCurve, FuzzySurface};

/// The side of the square grid of about `points` parameter values.
fn grid_side(points: usize) -> usize {
    ((points as f64).sqrt().round() as usize).max(2)
}

/// Timed runs per case; the median is reported.
pub const RUNS: usize = 5;

/// The most threads a benchmark may ask for.
pub const MAX_THREADS: usize = 1024;

/// What a benchmark case samples, at `points` uniform parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BenchCase {
    /// The crisp curve ([`t2spline::NurbsCurve::sample_soa`]).
    Crisp,
    /// All seven layer curves ([`FuzzyCurve::sample_layers`]).
    Fuzzy,
    /// Stages 1–4 at the 11 levels 0, 0.1, …, 1 ([`benchmark_levels`]) and
    /// every resulting curve ([`FuzzyCurve::sample_sweep`]).
    Sweep,
    /// The crisp surface on a `√N × √N` grid ([`t2spline::NurbsSurface::sample_grid`]).
    Surface,
    /// All seven layer surfaces on a `√N × √N` grid
    /// ([`FuzzySurface::sample_layers`]).
    SurfaceFuzzy,
}

impl BenchCase {
    /// Every case, in the order `all` runs them.
    pub const ALL: [BenchCase; 5] = [
        BenchCase::Crisp,
        BenchCase::Fuzzy,
        BenchCase::Sweep,
        BenchCase::Surface,
        BenchCase::SurfaceFuzzy,
    ];

    /// The name used on the command line and in the output.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            BenchCase::Crisp => "crisp",
            BenchCase::Fuzzy => "fuzzy",
            BenchCase::Sweep => "sweep",
            BenchCase::Surface => "surface",
            BenchCase::SurfaceFuzzy => "surface-fuzzy",
        }
    }

    /// Whether the case samples a surface (else a curve).
    #[must_use]
    pub fn is_surface(self) -> bool {
        matches!(self, BenchCase::Surface | BenchCase::SurfaceFuzzy)
    }

    /// The parameter values a run of this case samples when `points` are
    /// asked for: `points` along a curve, `s²` on the `s × s` grid of a
    /// surface with `s = round(√points)`.
    #[must_use]
    pub fn points(self, points: usize) -> usize {
        if self.is_surface() {
            let side = grid_side(points);
            side * side
        } else {
            points
        }
    }

    /// The number of sampled curves a run of this case writes: 1, 7, or the
    /// 7 layers and, per level, 6 alpha-cut, 2 type-reduced and 1
    /// defuzzified curve.
    #[must_use]
    pub fn curves(self) -> usize {
        match self {
            BenchCase::Crisp | BenchCase::Surface => 1,
            BenchCase::Fuzzy | BenchCase::SurfaceFuzzy => 7,
            BenchCase::Sweep => 7 + 9 * benchmark_levels().len(),
        }
    }
}

impl fmt::Display for BenchCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The measured time of one case.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BenchResult {
    /// The case.
    pub case: BenchCase,
    /// Parameter values per run.
    pub points: usize,
    /// Threads the engine was allowed.
    pub threads: usize,
    /// Whether the output arrays were kept and reused from run to run.
    pub reuse: bool,
    /// Median wall time of [`RUNS`] runs, in seconds.
    pub seconds: f64,
}

impl BenchResult {
    /// Parameter values per second: `points / seconds`.
    #[must_use]
    pub fn points_per_second(&self) -> f64 {
        self.points as f64 / self.seconds
    }
}

impl fmt::Display for BenchResult {
    /// `bench <case> points=<N> threads=<T> seconds=<median> points_per_second=<N/seconds>`,
    /// followed by ` output=reused` when the output arrays were reused.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "bench {} points={} threads={} seconds={} points_per_second={:.4e}",
            self.case,
            self.points,
            self.threads,
            self.seconds,
            self.points_per_second()
        )?;
        if self.reuse {
            f.write_str(" output=reused")?;
        }
        Ok(())
    }
}

/// Checks the points of a benchmark: at least 2, and an output of `case` on a
/// model of `dimension` coordinates within [`MAX_OUTPUT_BYTES`].
///
/// # Errors
/// [`Error::Setting`] ([`Setting::Points`]) naming the rule (examples in
/// this module's tests).
pub fn check_points(points: u64, case: BenchCase, dimension: usize) -> Result<usize, Error> {
    let refuse = |message: String| Error::Setting {
        setting: Setting::Points,
        message,
    };
    if points < 2 {
        return Err(refuse(format!("points = {points}: at least 2 are needed")));
    }
    let bytes = u128::from(points) * (case.curves() * dimension * 8) as u128;
    if bytes > u128::from(MAX_OUTPUT_BYTES) {
        return Err(refuse(format!(
            "points = {points}: the output of case {case} would take {:.0} GB, more than the limit of {:.1} GB",
            bytes as f64 / 1e9,
            MAX_OUTPUT_BYTES as f64 / 1e9
        )));
    }
    usize::try_from(points)
        .map_err(|_| refuse(format!("points = {points} does not fit this machine")))
}

/// Times `case` on `model` at `points` uniform parameters, with the engine
/// allowed `threads` threads: one warm-up run, then the median of [`RUNS`].
///
/// Without `reuse` each run allocates its output and drops it, as a caller of
/// `sample_soa`, `sample_layers` or `sample_sweep` sees it; the first write to
/// freshly mapped memory (page faults) is then part of the time. With `reuse`
/// the runs write into the arrays of the previous run (`sample_soa_into`,
/// `sample_layers_into`, `sample_sweep_into`), which times the evaluation and
/// the stores alone.
///
/// # Errors
/// [`Error::Setting`]: points refused by [`check_points`], threads outside
/// `1 ..= MAX_THREADS`, or a thread pool the system cannot make (examples
/// in this module's tests).
pub fn run_case(
    model: &Model,
    case: BenchCase,
    points: u64,
    threads: usize,
    reuse: bool,
) -> Result<BenchResult, Error> {
    let points = check_points(points, case, model.dimension())?;
    if case.is_surface() != model.is_surface() {
        return Err(Error::Setting {
            setting: Setting::Points,
            message: format!(
                "case {case} samples a {}, and the model is a {}",
                if case.is_surface() {
                    "surface"
                } else {
                    "curve"
                },
                if model.is_surface() {
                    "surface"
                } else {
                    "curve"
                }
            ),
        });
    }
    if !(1..=MAX_THREADS).contains(&threads) {
        return Err(Error::Setting {
            setting: Setting::Threads,
            message: format!("threads = {threads}: must be in 1 ..= {MAX_THREADS}"),
        });
    }
    let seconds = with_threads(threads, || {
        model.visit(Time {
            case,
            points,
            reuse,
        })
    })?;
    Ok(BenchResult {
        case,
        points: case.points(points),
        threads,
        reuse,
        seconds,
    })
}

/// Runs `f` on a rayon pool of `threads` threads.
fn with_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T, Error> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Error::Setting {
            setting: Setting::Threads,
            message: format!("threads = {threads}: {e}"),
        })?;
    Ok(pool.install(f))
}

/// The timing of one case on one kind of model.
struct Time {
    case: BenchCase,
    points: usize,
    reuse: bool,
}

impl ModelVisitor for Time {
    type Output = f64;

    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> f64 {
        let Time {
            case,
            points,
            reuse,
        } = self;
        let params = Params::Uniform(points);
        let crisp = curve.crisp_curve();
        let levels = benchmark_levels();
        let mut crisp_out = CurveSamples::empty();
        let mut layers_out = LayerSamples::empty();
        let mut sweep_out = SweepSamples::empty();
        // Uniform parameters lie in the domain, so sampling cannot fail (and
        // the results are checked by the tests); a fresh output is dropped
        // inside the timed region, as a caller's would be eventually.
        let mut once = || match (case, reuse) {
            (BenchCase::Crisp | BenchCase::Surface, false) => {
                drop(black_box(crisp.sample_soa(params)));
            }
            (BenchCase::Fuzzy | BenchCase::SurfaceFuzzy, false) => {
                drop(black_box(curve.sample_layers(params)));
            }
            (BenchCase::Sweep, false) => drop(black_box(curve.sample_sweep(params, &levels))),
            (BenchCase::Crisp | BenchCase::Surface, true) => {
                drop(black_box(crisp.sample_soa_into(params, &mut crisp_out)));
            }
            (BenchCase::Fuzzy | BenchCase::SurfaceFuzzy, true) => {
                drop(black_box(curve.sample_layers_into(params, &mut layers_out)));
            }
            (BenchCase::Sweep, true) => {
                drop(black_box(curve.sample_sweep_into(
                    params,
                    &levels,
                    &mut sweep_out,
                )));
            }
        };
        median_time(&mut once)
    }

    fn surface<const D: usize>(self, surface: &FuzzySurface<D>) -> f64 {
        let Time {
            case,
            points,
            reuse,
        } = self;
        let side = Params::Uniform(grid_side(points));
        let crisp = surface.crisp_surface();
        let mut crisp_out = Grid::buffer(CurveSamples::empty());
        let mut layers_out = Grid::buffer(LayerSamples::empty());
        // As for curves: uniform parameters lie in the domain.
        let mut once = || match (case, reuse) {
            (BenchCase::SurfaceFuzzy, false) => drop(black_box(surface.sample_layers(side, side))),
            (BenchCase::SurfaceFuzzy, true) => {
                drop(black_box(surface.sample_layers_into(
                    side,
                    side,
                    &mut layers_out,
                )));
            }
            (_, false) => drop(black_box(crisp.sample_grid(side, side))),
            (_, true) => drop(black_box(crisp.sample_grid_into(
                side,
                side,
                &mut crisp_out,
            ))),
        };
        median_time(&mut once)
    }
}

/// One warm-up run of `once`, then the median wall time of [`RUNS`] runs.
fn median_time(once: &mut dyn FnMut()) -> f64 {
    once();
    let mut times: Vec<f64> = (0..RUNS)
        .map(|_| {
            let start = Instant::now();
            once();
            start.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[RUNS / 2]
}

#[cfg(test)]
mod tests {
    use super::*;
    use t2spline::sampling::{benchmark_curve, benchmark_surface};

    #[test]
    fn points_are_checked_against_the_output_limit() {
        assert_eq!(check_points(1000, BenchCase::Fuzzy, 2), Ok(1000));
        let e = check_points(100_000_000_000, BenchCase::Crisp, 2).unwrap_err();
        assert_eq!(
            e.to_string(),
            "points = 100000000000: the output of case crisp would take 1600 GB, more than the limit of 8.6 GB"
        );
    }

    #[test]
    fn a_case_runs_and_says_what_it_timed() {
        let model = Model::Planar(t2spline::sampling::benchmark_curve());
        let r = run_case(&model, BenchCase::Fuzzy, 1000, 1, false).unwrap();
        assert!(r
            .to_string()
            .starts_with("bench fuzzy points=1000 threads=1 seconds="));
    }

    #[test]
    fn every_case_runs_and_reports_in_the_documented_format() {
        let curve = Model::Planar(benchmark_curve());
        let surface = Model::Surface(benchmark_surface());
        for (case, reuse) in BenchCase::ALL
            .into_iter()
            .zip([false, true, false, true, false])
        {
            let model = if case.is_surface() { &surface } else { &curve };
            // 1000 points: a 32 × 32 grid of 1024 for surfaces.
            let r = run_case(
                model,
                case,
                if case.is_surface() { 1024 } else { 1000 },
                2,
                reuse,
            )
            .unwrap();
            assert!(r.seconds > 0.0 && r.seconds.is_finite(), "{r:?}");
            let line = r.to_string();
            let fields: Vec<&str> = line.split(' ').collect();
            let points = if case.is_surface() {
                "points=1024"
            } else {
                "points=1000"
            };
            assert_eq!(fields[..4], ["bench", case.name(), points, "threads=2"]);
            assert!(fields[4].starts_with("seconds="), "{line}");
            let rate: f64 = fields[5]
                .strip_prefix("points_per_second=")
                .unwrap()
                .parse()
                .unwrap();
            assert!(
                (rate - r.points as f64 / r.seconds).abs() <= 1e-3 * rate,
                "{line}"
            );
            assert_eq!(fields.get(6), reuse.then_some(&"output=reused"), "{line}");
        }
    }

    #[test]
    fn bad_threads_and_points_are_errors_before_any_work() {
        let model = Model::Planar(benchmark_curve());
        let e = run_case(&model, BenchCase::Surface, 100, 1, false).unwrap_err();
        assert_eq!(
            e.to_string(),
            "case surface samples a surface, and the model is a curve"
        );
        let e = run_case(&model, BenchCase::Crisp, 10, 0, false).unwrap_err();
        assert_eq!(e.to_string(), "threads = 0: must be in 1 ..= 1024");
        let e = run_case(&model, BenchCase::Crisp, 1, 1, false).unwrap_err();
        assert_eq!(e.to_string(), "points = 1: at least 2 are needed");
        // The sweep writes 106 curves: 10⁷ points of two coordinates are 17 GB.
        let e = run_case(&model, BenchCase::Sweep, 10_000_000, 1, false).unwrap_err();
        assert!(e.to_string().contains("would take 17 GB"), "{e}");
    }
}
