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

mod geometry;
mod near_height;
mod output;
mod points;
mod run;
#[cfg(feature = "serde")]
mod serialize;
mod settings;
mod units;

pub use crate::error::Setting;
pub use geometry::{Geometry, NamedCurve};
pub use near_height::{NearHeight, NEAR_HEIGHT_ULPS};
pub use output::{
    ControlPoints, CrispDefuzzified, Distance, LeftRight, Parameter, Parameters, Regime, RunOutput,
    Sampled, SixLayers, Spline,
};
pub use points::Points;
pub use settings::{
    check_derivative_order, check_grid_samples, check_samples, Overrides, Samples, Settings,
    DEFAULT_SAMPLES, DEFAULT_SURFACE_SAMPLES, MAX_DERIVATIVE_ORDER, MAX_SAMPLES,
};
pub use units::LengthUnit;

use crate::fuzzy::{Alpha, Axis, Nt2Number, Nt2Point};
use crate::pipeline::{FuzzyCurve, FuzzySurface};
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
    /// leaves it to the geometry (docs/method.md §11, [`FuzzyCurve::closure`]).
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

/// The fuzzy model of a job: a curve in the plane or in space, or a surface.
///
/// Code that works for every kind of model is written once, as a
/// [`ModelVisitor`], and [`Model::visit`] is the one place that tells the
/// kinds apart.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Model {
    /// A curve through points with coordinates `x`, `y`.
    Planar(FuzzyCurve<2>),
    /// A curve through points with coordinates `x`, `y`, `z`.
    Spatial(FuzzyCurve<3>),
    /// A surface over a net of points with coordinates `x`, `y`, `z` (docs/method.md §8).
    Surface(FuzzySurface<3>),
}

/// Work done on any [`Model`]: one generic method per kind of model.
pub trait ModelVisitor {
    /// What the work gives.
    type Output;
    /// The work on a fuzzy curve of `D` dimensions.
    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> Self::Output;
    /// The work on a fuzzy surface of `D` dimensions.
    fn surface<const D: usize>(self, surface: &FuzzySurface<D>) -> Self::Output;
}

impl Model {
    /// Does `work` on the model, whatever its kind.
    pub fn visit<V: ModelVisitor>(&self, work: V) -> V::Output {
        match self {
            Model::Planar(c) => work.curve(c),
            Model::Spatial(c) => work.curve(c),
            Model::Surface(s) => work.surface(s),
        }
    }

    /// The numbers of every fuzzy control point (a surface's net row by row),
    /// one per coordinate.
    #[must_use]
    pub fn numbers(&self) -> Vec<Vec<Nt2Number>> {
        self.visit(Numbers)
    }

    /// The smallest lower height `h` of the model's numbers: the lowest
    /// level where the paper's reduction jumps (docs/method.md §3).
    #[must_use]
    pub fn least_height(&self) -> f64 {
        self.numbers()
            .iter()
            .flatten()
            .map(|x| x.height().get())
            .fold(1.0, f64::min)
    }

    /// Whether the model is a surface.
    #[must_use]
    pub fn is_surface(&self) -> bool {
        matches!(self, Model::Surface(_))
    }

    /// One line on the model: `2-D curve, 4 control points, order 3` or
    /// `surface, 5 × 4 control points, orders 3 × 2`.
    #[must_use]
    pub fn summary(&self) -> String {
        struct Summary;
        impl ModelVisitor for Summary {
            type Output = String;
            fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> String {
                format!(
                    "{D}-D curve, {} control points, order {}",
                    c.points().len(),
                    c.order()
                )
            }
            fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> String {
                let ([nu, nv], [p, q]) = (s.shape(), s.degree());
                format!(
                    "{D}-D surface, {nu} × {nv} control points, orders {} × {}",
                    p + 1,
                    q + 1
                )
            }
        }
        self.visit(Summary)
    }

    /// The shape `[nu, nv]` of a surface's control net; `None` for a curve.
    #[must_use]
    pub fn net_shape(&self) -> Option<[usize; 2]> {
        struct NetShape;
        impl ModelVisitor for NetShape {
            type Output = Option<[usize; 2]>;
            fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> Option<[usize; 2]> {
                None
            }
            fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Option<[usize; 2]> {
                Some(s.shape())
            }
        }
        self.visit(NetShape)
    }

    /// The number of coordinates of a point (2 or 3).
    #[must_use]
    pub fn dimension(&self) -> usize {
        self.visit(Dimension)
    }

    /// The number of fuzzy control points (of a surface: `nu · nv`).
    #[must_use]
    pub fn control_point_count(&self) -> usize {
        self.numbers().len()
    }

    /// The fuzzy number of one coordinate of one control point (of a
    /// surface: point `i·nv + j` of the net, row by row); `None` if the model
    /// has no such point or axis.
    #[must_use]
    pub fn number(&self, point: usize, axis: Axis) -> Option<Nt2Number> {
        self.numbers().get(point)?.get(axis.index()).copied()
    }

    /// The distinct lower heights of the model's numbers, ascending: the
    /// levels where the solution jumps (docs/method.md §3).
    #[must_use]
    pub fn heights(&self) -> Vec<f64> {
        let mut h: Vec<f64> = self
            .numbers()
            .iter()
            .flatten()
            .map(|x| x.height().get())
            .collect();
        h.sort_by(f64::total_cmp);
        h.dedup();
        h
    }
}

/// [`Model::numbers`].
struct Numbers;

impl ModelVisitor for Numbers {
    type Output = Vec<Vec<Nt2Number>>;
    fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Self::Output {
        numbers_of(c.points())
    }
    fn surface<const D: usize>(self, s: &FuzzySurface<D>) -> Self::Output {
        numbers_of(s.points())
    }
}

fn numbers_of<const D: usize>(points: &[Nt2Point<D>]) -> Vec<Vec<Nt2Number>> {
    points.iter().map(|p| p.coords().to_vec()).collect()
}

/// [`Model::dimension`].
struct Dimension;

impl ModelVisitor for Dimension {
    type Output = usize;
    fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> usize {
        D
    }
    fn surface<const D: usize>(self, _: &FuzzySurface<D>) -> usize {
        D
    }
}
