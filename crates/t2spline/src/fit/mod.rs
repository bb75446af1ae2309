//! Fitting curves to data: global interpolation and least squares, crisp and
//! fuzzy (The NURBS Book, 2nd ed., §9.2.1 and §9.4.1).
//!
//! - [`Parametrization`]: parameters of the data points (Eqs. 9.3–9.6).
//! - [`averaging_knots`] (Eq. 9.8) and [`approximation_knots`] (Eqs. 9.68–9.69).
//! - [`fit_curve`]: a crisp B-spline through the data (Algorithm A9.1) or
//!   approximating them with the end points interpolated (§9.4.1); or, with
//!   [`FitOptions::closed`], a closed curve around a loop of data: loop
//!   parameters with the closing chord, [`periodic_knots`], the wrapped
//!   columns folded (`cyclic.rs`).
//! - [`fuzzify`]: fuzzy data points from repeated readings (median,
//!   quartiles, 10th–90th percentiles, extremes widened by the instrument's
//!   accuracy; [`FuzzifyRule`]).
//! - [`fit_surface`] and [`fit_fuzzy_surface`]: the same for a net of data
//!   points (§9.2.5 Algorithm A9.4, §9.4.3 Algorithm A9.7), the parameters
//!   averaged over rows and columns (A9.3), one direction fitted after the
//!   other ([`SurfaceFitOptions`]).
//! - [`fit_fuzzy`]: a fuzzy curve through fuzzy data points, with the order of
//!   docs/method.md §1 kept by construction ([`FuzzyFitMode::Valid`]) or each layer
//!   fitted on its own and checked ([`FuzzyFitMode::Independent`]).
//!
//! All linear systems are banded and solved by Givens QR
//! (`banded.rs`; a closed fit's cyclic band becomes a plain band of width
//! `2p + 1` once its columns are interleaved); the valid fuzzy fit adds non-negative least squares
//! (Lawson–Hanson, `nnls.rs`).
//!
//! ```
//! use t2spline::fit::{fit_curve, FitOptions, Parametrization};
//! let q = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0], [6.0, 0.0]];
//! let options = FitOptions::interpolation(3)?.with_parametrization(Parametrization::Centripetal);
//! let fit = fit_curve(&q, &options)?;
//! let c = fit.curve.eval(fit.params[2])?;
//! assert!((c[0] - 3.0).abs() < 1e-12 && (c[1] - 3.0).abs() < 1e-12);
//! # Ok::<(), t2spline::Error>(())
//! ```

pub(crate) mod banded;
mod curve;
mod cyclic;
mod data;
mod design;
mod fuzzify;
mod fuzzy;
mod fuzzy_net;
mod knots;
mod net;
mod nnls;
mod parametrization;
mod surface;
mod system;

pub use curve::{fit_curve, CurveFit, FitOptions};
pub use data::{FitOutcome, FitSummary, FuzzyData, LoopCounts, NetCounts};
pub use fuzzify::{
    fuzzify, fuzzify_number, percentile, FuzzifyRule, Readings, DEFAULT_LOWER_HEIGHT, MIN_READINGS,
};
pub use fuzzy::{fit_fuzzy, Deviation, FuzzyFit, FuzzyFitMode, OrderViolation};
pub use fuzzy_net::{fit_fuzzy_surface, FuzzySurfaceFit};
pub use knots::{approximation_knots, averaging_knots, periodic_knots};
pub use net::SurfaceFitOptions;
pub use parametrization::Parametrization;
pub use surface::{fit_surface, SurfaceFit};
