//! # t2spline-plot — figures and reports for t2spline
//!
//! Publication figures of every stage of the method (the paper's Figs. 3.1,
//! 4.1–4.4 and 5.1–5.4, an alpha sweep, and the type reductions of SPEC §10
//! compared) as SVG and PNG, and a self-contained HTML report with an alpha
//! slider and a type-reduction selector.
//!
//! - [`figures`]: one builder per figure, from a
//!   [`RunOutput`](t2spline::job::RunOutput) computed in [`data`] by the core's
//!   one run path (the only place numbers come from).
//! - [`scene`] → [`layout`] → [`svg`]: figures in data coordinates, placed on a
//!   page (equal aspect for curves, legends where they cover nothing, labels
//!   that avoid each other), written as deterministic SVG text.
//! - [`png`] (feature `png`, default): the same SVG rasterised with resvg and
//!   the bundled DejaVu Sans font.
//! - [`report`]: one HTML file with the figures, tables and the job.
//!
//! ```
//! use t2spline_plot::{all_figures, NumberChoice};
//! let job = t2spline_io::parse_job(r#"{
//!   "order": 2, "alpha": 0.5, "lower_height": 0.6,
//!   "points": [
//!     {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
//!      "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
//!     {"x": {"crisp": 3, "upper": [2, 4], "primary": [2.5, 3.5], "lower": [2.8, 3.2]},
//!      "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}
//!   ]}"#, "job.json")?;
//! let alpha = job.alpha.expect("the file gives alpha");
//! let figures = all_figures(&job, alpha, NumberChoice::default())?;
//! assert_eq!(figures.len(), 7);
//! let svg = t2spline_plot::svg::render(&figures[1]);
//! assert!(svg.contains("Stage 1"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod data;
mod error;
pub mod figures;
pub mod font;
pub mod geometry;
pub mod labels;
pub mod layout;
mod output;
#[cfg(feature = "png")]
pub mod png;
pub mod report;
pub mod scene;
pub mod style;
pub mod svg;
pub mod ticks;

pub use error::Error;
pub use figures::{all_figures, NumberChoice, FIGURE_NAMES};
pub use output::{render_files, Format};
