//! Jobs: a fuzzy model with how to run it, and running it (docs/method.md §7–§8).
//!
//! A [`Job`] is what a job file describes, in memory: a fuzzy curve of 2 or 3
//! dimensions or a surface ([`Model`]), the level alpha, the type reduction,
//! the number of samples and a description. [`Job::settings`] combines it with what a front end overrides
//! ([`Overrides`]: `--alpha` on the command line, `alpha=` in Python) into
//! checked [`Settings`], and [`Job::run`] computes every stage into a
//! [`RunOutput`]: the one path from job to result that the command-line tool,
//! the figures and the Python bindings all take. [`Job::geometry`] gives the
//! same run's curves exactly, named, for CAD files. Reading job files and
//! writing results are the I/O crate's; this module only computes.
//!
//! ```
//! use t2spline::job::{Job, Model, Overrides};
//! use t2spline::{Alpha, FuzzyCurve, Nt2Number, Nt2Point};
//! let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
//! let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(3.0)?, n(4.0)?])];
//! let job = Job {
//!     alpha: Some(Alpha::try_new(0.5)?),
//!     ..Job::new(Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?))
//! };
//! let settings = job.settings(&Overrides { samples: Some(vec![3]), ..Overrides::default() })?;
//! let out = job.run(&settings)?;
//! assert_eq!(out.samples.params.along(), [0.0, 0.5, 1.0]);
//! assert_eq!(out.samples.crisp.point(1), Some(vec![1.5, 2.0]));
//! // Right spreads exceed left spreads: the solution lies right of the crisp curve.
//! assert!(out.samples.defuzzified.coord(0)[1] > 1.5);
//! # Ok::<(), t2spline::Error>(())
//! ```

// The input decides the indices here: no indexing that can panic (`get`,
// iterators, `split_first`), as ARCHITECTURE.md explains.
#![cfg_attr(not(test), deny(clippy::indexing_slicing))]

mod alpha_note;
mod geometry;
mod model;
mod near_height;
mod output;
mod points;
mod run;
#[cfg(feature = "serde")]
mod serialize;
mod settings;
mod units;

pub use crate::error::Setting;
pub use alpha_note::{AlphaNote, UnusedBy, ALPHA_IGNORED};
pub use geometry::{Geometry, NamedCurve};
pub use model::{Model, ModelVisitor};
pub use near_height::{NearHeight, NEAR_HEIGHT_ULPS};
pub use output::{
    ControlPoints, CrispDefuzzified, Distance, Envelope, LeftRight, Parameter, Parameters, Regime,
    RunOutput, Sampled, SixLayers, Spline,
};
pub use points::Points;
pub use settings::{
    check_derivative_order, check_grid_samples, check_samples, Overrides, Samples, Settings,
    DEFAULT_SAMPLES, DEFAULT_SURFACE_SAMPLES, MAX_DERIVATIVE_ORDER, MAX_SAMPLES,
};
pub use units::LengthUnit;

use crate::fuzzy::Alpha;
use crate::reduction::TypeReduction;

/// A validated job (docs/jobs.md): the fuzzy model and how to run it.
#[derive(Clone, Debug, PartialEq)]
pub struct Job {
    /// Free text carried along to the result.
    pub description: Option<String>,
    /// The level alpha; may be left to the front end ([`Overrides::alpha`]).
    /// Only the paper's type reduction uses it (see [`Job::settings`]).
    pub alpha: Option<Alpha>,
    /// The type reduction of stages 3–4 (docs/method.md §9; the job file's
    /// `"type_reduction"`, default [`TypeReduction::Paper`]).
    pub type_reduction: TypeReduction,
    /// Uniform parameters at which curves or surfaces are sampled (checked by
    /// [`Job::settings`]).
    pub samples: Samples,
    /// Whether a curve is closed (the job file's `"closed"`): `Some(true)`
    /// asks that it close, `Some(false)` that it be measured as open, `None`
    /// leaves it to the geometry (docs/method.md §11, [`FuzzyCurve::closure`](crate::pipeline::FuzzyCurve::closure)).
    pub closed: Option<bool>,
    /// The unit of the coordinates (the job file's `"units"`), for the
    /// files that record one (CAD export); `None`: not said (millimetres
    /// there).
    pub units: Option<LengthUnit>,
    /// The fuzzy model.
    pub model: Model,
}

impl Job {
    /// A job of `model` with the defaults of docs/jobs.md and docs/method.md §8: no description,
    /// alpha left to the front end, the paper's type reduction,
    /// [`DEFAULT_SAMPLES`] samples along a curve
    /// or a grid of [`DEFAULT_SURFACE_SAMPLES`]² over a surface.
    #[must_use]
    pub fn new(model: Model) -> Job {
        let samples = match model {
            Model::Surface(_) => Samples::Grid([DEFAULT_SURFACE_SAMPLES; 2]),
            _ => Samples::Along(DEFAULT_SAMPLES),
        };
        Job {
            description: None,
            alpha: None,
            type_reduction: TypeReduction::Paper,
            samples,
            closed: None,
            units: None,
            model,
        }
    }
}
