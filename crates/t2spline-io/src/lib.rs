//! # t2spline-io — job files, result files and CSV export for t2spline
//!
//! This crate reads and writes; the core crate `t2spline` computes.
//!
//! - [`parse_job`] / [`read_job`]: the job file of docs/jobs.md (a curve) or docs/method.md §8
//!   (a surface, its points as rows of a net), validated with every problem
//!   reported at once, each naming its place (`points[2].y`,
//!   `points[2][1].y`, `weights[1]`, `knots.v`) with its line and column, and
//!   its rule, into the core's [`Job`](t2spline::job::Job); [`job_json`]
//!   writes a job back.
//! - [`write_json_pretty`]: a run's [`RunOutput`](t2spline::job::RunOutput)
//!   (or any serde value) as the result file: indented, arrays of numbers on
//!   one line, streamed without an intermediate tree.
//! - [`render_csv`] / [`write_csv`] / [`stage_csv`]: the sampled curves (or
//!   surfaces, one row per grid point) as CSV, one file per curve family.
//! - `write_parquet` (feature `parquet`, default): the sampled curves as one
//!   Apache Parquet table, the rest of the result as key-value metadata.
//! - [`write_jobs_jsonl`] (and `write_jobs_parquet`): the sampled curves of
//!   many runs as one table, JSON Lines (or Parquet), one schema whatever
//!   the regime.
//! - [`JobSummary`], [`write_summary_csv`] (and `write_summary_parquet`): the
//!   summary of a run of many jobs.
//! - [`Prepared`]: the one way every front end prepares and runs a job
//!   (read, settings checked once, run, every number finite), with errors
//!   that keep their kind ([`RunError`]).
//! - [`check_finite`]: the last guard before writing, naming the first NaN or
//!   infinity of an output by its path.
//! - [`Staged`] / [`write_atomic`]: output files that are complete or absent,
//!   never half written; devices and FIFOs written through, symbolic links
//!   followed; [`remove_temporary_files`] for a front end's signal handler.
//! - [`parse_data`] / [`FitData`]: data files for `t2spline fit` (fuzzy data
//!   points), and the fitted model written back as a job file.
//! - [`render_cad`]: a run's exact curves ([`t2spline::job::Geometry`]) as
//!   DXF, STEP, IGES or OBJ, rational B-splines at full precision.
//! - [`parse_readings`] / [`ReadingsFile`]: repeated readings of stations
//!   (CSV as spreadsheets write it), which the core turns into fuzzy data
//!   points ([`t2spline::fit::fuzzify`]).
//!
//! ```
//! use t2spline::job::Overrides;
//! let job = t2spline_io::parse_job(r#"{
//!   "order": 2, "alpha": 0.5, "lower_height": 0.5, "samples": 3,
//!   "points": [
//!     {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
//!      "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
//!     {"x": {"crisp": 1, "upper": [0, 2], "primary": [0.5, 1.5], "lower": [0.8, 1.2]},
//!      "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}
//!   ]}"#, "job.json")?;
//! let result = job.run(&job.settings(&Overrides::default())?)?;
//! let mut text = Vec::new();
//! t2spline_io::write_json_pretty(&mut text, &result)?;
//! let text = String::from_utf8(text)?;
//! assert!(text.contains("\"params\": [0.0, 0.5, 1.0]"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

// No panic reachable from input: outside tests, `unwrap`, `expect`, `panic!`
// and `unreachable!` are refused; the few sites that cannot fail carry an
// `#[allow]` with the invariant that makes them safe (ARCHITECTURE.md,
// "Decisions and reasons").
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::unreachable,
        clippy::todo,
        clippy::unimplemented
    )
)]

mod atomic;
mod cad;
mod csv;
mod error;
mod finite;
mod fit_data;
pub mod job;
mod job_json;
mod jsonl;
#[cfg(feature = "parquet")]
mod keys;
mod limits;
mod number;
#[cfg(feature = "parquet")]
mod parquet;
mod prepared;
mod pretty;
mod printable;
mod read;
mod readings;
pub mod set;
mod status;
mod summary;
mod table;
mod target;
mod temporary;

pub use crate::atomic::{sync_file_systems, write_all_atomic, write_atomic, Staged};
pub use crate::cad::{render_cad, CadFormat, CadMeta};
pub use crate::csv::{render_csv, stage_csv, write_csv, CSV_FILES, DERIVATIVES_CSV};
pub use error::{Error, Problem};
pub use finite::check_finite;
pub use fit_data::FitData;
pub use job::{job_json, parse_data, parse_job, read_data, read_job};
pub use jsonl::write_jobs_jsonl;
#[cfg(feature = "parquet")]
pub use parquet::{write_jobs_parquet, write_parquet, write_summary_parquet, JobsParquet};
pub use prepared::{MissingAlpha, Prepared, RunError};
pub use pretty::{to_json_pretty, write_json_pretty};
pub use printable::printable;
pub use readings::{
    data_json, data_json_text, fuzzify_net, fuzzify_readings, is_readings, parse_ascii_grid,
    parse_grid_csv, parse_net_readings, parse_npy, parse_readings, read_npy, read_readings,
    NetReadings, Raster, RasterGeometry, ReadingsError, ReadingsFile, ReadingsOption,
    ReadingsOptions, StationSource, DEFAULT_DEGREE, MAX_NPY_BYTES, MAX_RASTER_CELLS, MAX_ROWS,
};
pub use status::Status;
pub use summary::{write_summary_csv, JobSummary, SUMMARY_COLUMNS};
pub use table::{sample_column_names, sample_columns, SampleColumn};
pub use temporary::remove_temporary_files;
