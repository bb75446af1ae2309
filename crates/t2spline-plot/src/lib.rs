//! # t2spline-plot — figures and reports for t2spline
//!
//! Publication figures of every stage of the method (the paper's Figs. 3.1,
//! 4.1–4.4 and 5.1–5.4, the distance along the curve for several alphas and
//! against alpha, and the type reductions of docs/method.md §9 compared) as SVG and
//! PNG, and a self-contained HTML report with an alpha slider, a
//! type-reduction selector and downloads.
//!
//! - [`all_figures`]: every figure of a job at one alpha, built in data
//!   coordinates ([`Figure`]: panels of keyed [`Mark`]s, a legend, notes) from
//!   numbers the core computes (`Job::run`, its sampling engine and distance;
//!   plotting never recomputes the method).
//! - [`fit_layout`] → [`render_svg`]: figures placed on a page (equal aspect
//!   for curves unless [`Aspect::Auto`], legends and labels where they cover
//!   nothing, per-point detail thinned for jobs of many points), written as
//!   deterministic SVG text; [`svg_to_png`] (feature `png`, default) rasterises
//!   the same SVG with resvg and the bundled DejaVu Sans font, at 300 dpi.
//! - [`notebook_figures`], [`number_notebook_figure`],
//!   [`region_notebook_figure`], [`measures_notebook_figure`],
//!   [`section_notebook_figure`]: the figures of one object for a notebook's
//!   picture (the Python package's `_repr_html_`), thinned to stay small;
//!   [`render_svg_prefixed`] writes several into one page with distinct ids.
//! - [`render_report`]: one HTML file with the figures, tables, downloads and
//!   the job.
//!
//! Curve figures are one family (`figures/curve/`); the layout, legend, colour
//! bar, labels and SVG/PNG output know nothing of curves, so other families
//! of figures can use them as they are.
//!
//! ```
//! use t2spline_plot::{all_figures, FigureOptions};
//! let job = t2spline_io::parse_job(r#"{
//!   "order": 2, "alpha": 0.5, "lower_height": 0.6,
//!   "points": [
//!     {"x": {"crisp": 0, "upper": [-1, 1], "primary": [-0.5, 0.5], "lower": [-0.2, 0.2]},
//!      "y": {"crisp": 0, "upper": [-1, 2], "primary": [-0.5, 1], "lower": [-0.2, 0.5]}},
//!     {"x": {"crisp": 3, "upper": [2, 4], "primary": [2.5, 3.5], "lower": [2.8, 3.2]},
//!      "y": {"crisp": 1, "upper": [0, 3], "primary": [0.5, 2], "lower": [0.8, 1.5]}}
//!   ]}"#, "job.json")?;
//! let alpha = job.alpha.expect("the file gives alpha");
//! let figures = all_figures(&job, alpha, &FigureOptions::default())?;
//! assert_eq!(figures.len(), 11);
//! let svg = t2spline_plot::render_svg(&figures[1]);
//! assert!(svg.contains("Stage 1"));
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

/// Whether this build writes PNG (feature `png`); without it, figures are
/// SVG only.
pub const PNG: bool = cfg!(feature = "png");

mod chart;
mod data;
mod error;
mod figures;
mod measure_view;
mod output;
mod report;
mod set_view;
mod terrain_view;

pub use chart::geometry::{Px, Rect};
pub use chart::labels::{place as place_labels, Placed};
pub use chart::layout::{fit as fit_layout, Layout, LegendLayout};
pub use chart::obstacles::{panel_obstacles, Obstacles};
pub use chart::paint::{viridis, Color, Fill, Marker, Shape, Stroke};
pub use chart::panel_layout::{AxisLayout, PanelLayout};
#[cfg(feature = "png")]
pub use chart::png::{svg_to_png, Pixmap, PNG_DPI, PNG_SCALE};
pub use chart::scene::{ColorBar, Facet, Figure, Item, LegendEntry, Mark, Panel, Priority, Xy};
pub use chart::simplify::simplify;
pub use chart::svg::{render as render_svg, render_prefixed as render_svg_prefixed};
pub use error::Error;
pub use figures::surface::View;
pub use figures::{
    all_figures, measures_notebook_figure, notebook_figures, number_notebook_figure, palette,
    region_notebook_figure, section_notebook_figure, set_figures_left_out, terrain_figures,
    terrain_left_out, Aspect, FigureOptions, NumberChoice, Stages, TerrainFigures, FIGURE_NAMES,
    MEASURES_MAX_POINTS, NOTEBOOK_MAX_REGION_POINTS, NOTEBOOK_MAX_SAMPLES, NOTEBOOK_SURFACE_GRID,
    TERRAIN_FIGURE_NAMES,
};
pub use output::{render_files, Format};
pub use report::{render as render_report, Stops, DATA_BUDGET, MAX_FILE_GRID, MAX_FILE_SAMPLES};
pub use terrain_view::{
    DATUM, SURFACE_AREA_LEVELS, SURFACE_AREA_MAX_POINTS, TERRAIN_MEASURE_LEVELS, WIDTH_MAP_CELLS,
};

/// The colours of the figures: the Okabe–Ito palette, distinguishable with
/// the common colour-vision deficiencies, and greys.
pub mod palette {
    pub use crate::chart::paint::{
        BLACK, BLUE, GREEN, GREY, GRID, INK, MUTED, ORANGE, PURPLE, SKY, VERMILLION, WHITE,
    };
}
