//! The measurements behind `t2spline bench`: the sampling engine on one curve,
//! timed as the median of five runs after one warm-up run.

use std::fmt;
use std::hint::black_box;
use std::time::Instant;

use t2spline::sampling::{
    benchmark_curve, benchmark_levels, CurveSamples, LayerSamples, Params, SweepSamples,
};
use t2spline::FuzzyCurve;

use crate::{Error, JobCurve};

/// Timed runs per case; the median is reported.
pub const RUNS: usize = 5;

/// What a benchmark case samples, at `points` uniform parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BenchCase {
    /// The crisp curve ([`t2spline::NurbsCurve::sample_soa`]).
    Crisp,
    /// All seven layer curves ([`FuzzyCurve::sample_layers`]).
    Fuzzy,
    /// Stages 1–4 at the 11 levels 0, 0.1, …, 1
    /// ([`t2spline::sampling::benchmark_levels`]) and every resulting curve
    /// ([`FuzzyCurve::sample_sweep`]).
    Sweep,
}

impl BenchCase {
    /// Every case, in the order `--case all` runs them.
    pub const ALL: [BenchCase; 3] = [BenchCase::Crisp, BenchCase::Fuzzy, BenchCase::Sweep];

    /// The name used on the command line and in the output.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            BenchCase::Crisp => "crisp",
            BenchCase::Fuzzy => "fuzzy",
            BenchCase::Sweep => "sweep",
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

/// The default benchmark curve, [`t2spline::sampling::benchmark_curve`]:
/// degree 3, ten control points, unequal spreads.
///
/// # Examples
/// ```
/// let c = t2spline_io::bench::default_curve();
/// assert_eq!((c.degree(), c.points().len()), (3, 10));
/// ```
#[must_use]
pub fn default_curve() -> FuzzyCurve<2> {
    benchmark_curve()
}

/// Times `case` on `curve` at `points` uniform parameters, with the engine
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
/// [`Error::Option`] if `threads` is 0 or the thread pool cannot be made.
pub fn run_case(
    curve: &JobCurve,
    case: BenchCase,
    points: usize,
    threads: usize,
    reuse: bool,
) -> Result<BenchResult, Error> {
    let seconds = with_threads(threads, || match curve {
        JobCurve::Planar(c) => time_case(c, case, points, reuse),
        JobCurve::Spatial(c) => time_case(c, case, points, reuse),
    })?;
    Ok(BenchResult {
        case,
        points,
        threads,
        reuse,
        seconds,
    })
}

/// Runs `f` on a rayon pool of `threads` threads (on the calling thread only,
/// without the `parallel` feature of the core crate).
fn with_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> Result<T, Error> {
    if threads == 0 {
        return Err(Error::Option {
            option: "--threads",
            message: "at least 1 thread is needed".to_owned(),
        });
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| Error::Option {
            option: "--threads",
            message: e.to_string(),
        })?;
    Ok(pool.install(f))
}

fn time_case<const D: usize>(
    curve: &FuzzyCurve<D>,
    case: BenchCase,
    points: usize,
    reuse: bool,
) -> f64 {
    let params = Params::Uniform(points);
    let crisp = curve.crisp_curve();
    let levels = benchmark_levels();
    let mut crisp_out = CurveSamples::empty();
    let mut layers_out = LayerSamples::empty();
    let mut sweep_out = SweepSamples::empty();
    // Uniform parameters lie in the domain, so sampling cannot fail (and the
    // results are checked by the tests); a fresh output is dropped inside the
    // timed region, as a caller's would be eventually.
    let mut once = || match (case, reuse) {
        (BenchCase::Crisp, false) => drop(black_box(crisp.sample_soa(params))),
        (BenchCase::Fuzzy, false) => drop(black_box(curve.sample_layers(params))),
        (BenchCase::Sweep, false) => drop(black_box(curve.sample_sweep(params, &levels))),
        (BenchCase::Crisp, true) => drop(black_box(crisp.sample_soa_into(params, &mut crisp_out))),
        (BenchCase::Fuzzy, true) => {
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

    #[test]
    fn every_case_runs_and_reports_in_the_documented_format() {
        let curve = JobCurve::Planar(default_curve());
        for (case, reuse) in BenchCase::ALL.into_iter().zip([false, true, false]) {
            let r = run_case(&curve, case, 1000, 2, reuse).unwrap();
            assert!(r.seconds > 0.0 && r.seconds.is_finite(), "{r:?}");
            let line = r.to_string();
            let fields: Vec<&str> = line.split(' ').collect();
            assert_eq!(
                fields[..4],
                ["bench", case.name(), "points=1000", "threads=2"]
            );
            assert!(fields[4].starts_with("seconds="), "{line}");
            let rate: f64 = fields[5]
                .strip_prefix("points_per_second=")
                .unwrap()
                .parse()
                .unwrap();
            assert!((rate - 1000.0 / r.seconds).abs() <= 1e-3 * rate, "{line}");
            assert_eq!(fields.get(6), reuse.then_some(&"output=reused"), "{line}");
        }
    }

    #[test]
    fn zero_threads_is_an_error() {
        let curve = JobCurve::Planar(default_curve());
        let e = run_case(&curve, BenchCase::Crisp, 10, 0, false).unwrap_err();
        assert_eq!(e.to_string(), "--threads: at least 1 thread is needed");
    }

    #[test]
    fn default_curve_is_the_documented_one() {
        let c = default_curve();
        assert_eq!(
            c.weights(),
            &[1.0, 0.5, 2.0, 1.0, 3.0, 0.7, 1.0, 1.5, 0.8, 1.0]
        );
        assert_eq!(c.points()[5].crisp(), [5.0, 2.5]);
        assert_eq!(c.knots().as_slice()[4], 1.0 / 7.0);
    }
}
