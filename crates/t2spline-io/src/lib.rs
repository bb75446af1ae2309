//! # t2spline-io — job files, result files and CSV export for t2spline
//!
//! - [`Job`]: the job file of SPEC §8, validated with every problem reported at
//!   once, each naming its place (`points[2].y`, `weights[1]`, JSON line and
//!   column for syntax errors) and its rule.
//! - [`RunResult`]: what a run computes — control points and sampled curves of
//!   the four stages and the crisp-to-defuzzified distance — as serde types.
//! - [`render_csv`] / [`write_csv`]: the sampled curves as CSV, one file per
//!   curve family.
//! - [`derivatives`]: `--derivatives K`, derivatives and arc lengths of the
//!   crisp and the defuzzified curve.
//! - [`bench`](mod@bench): the timings behind `t2spline bench`.
//! - [`write_atomic`]: output files that are complete or absent, never half
//!   written.
//! - [`FitData`]: data files for `t2spline fit` (fuzzy data points), fitted
//!   into a job file.
//!
//! ```
//! use t2spline_io::{Job, RunResult};
//! let job = Job::parse(r#"{
//!   "order": 2, "alpha": 0.5, "lower_height": 0.5, "samples": 3,
//!   "points": [
//!     {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
//!      "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
//!     {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
//!      "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}
//!   ]}"#, "job.json")?;
//! let alpha = job.alpha.expect("the file gives alpha");
//! let result = RunResult::compute(&job, alpha, job.samples);
//! assert_eq!(result.curves.params, vec![0.0, 0.5, 1.0]);
//! assert_eq!(result.curves.crisp[1], vec![0.5, 0.5]);
//! # Ok::<(), t2spline_io::Error>(())
//! ```

mod atomic;
pub mod bench;
mod csv;
pub mod derivatives;
mod error;
mod finite;
pub mod fit_data;
pub mod job;
mod pretty;
pub mod result;

pub use crate::atomic::{write_all_atomic, write_atomic, Staged};
pub use crate::csv::{render_csv, stage_csv, write_csv, CSV_FILES, DERIVATIVES_CSV};
pub use error::{Error, Problem};
pub use finite::check_finite;
pub use fit_data::{DataPoints, FitData, FitOutcome, FitSummary};
pub use job::{Job, JobCurve, DEFAULT_SAMPLES, MAX_SAMPLES};
pub use pretty::{to_json_pretty, write_json_pretty};
pub use result::RunResult;
