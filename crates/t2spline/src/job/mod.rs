//! Jobs: a fuzzy model with how to run it, and running it (SPEC §7–§8).
//!
//! A [`Job`] is what a job file describes, in memory: a fuzzy curve of 2 or 3
//! dimensions ([`Model`]), the level alpha, the number of samples and a
//! description. [`Job::settings`] combines it with what a front end overrides
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
//! let settings = job.settings(&Overrides { samples: Some(3), ..Overrides::default() })?;
//! let out = job.run(&settings)?;
//! assert_eq!(out.curves.params, [0.0, 0.5, 1.0]);
//! assert_eq!(out.curves.crisp.point(1), Some(vec![1.5, 2.0]));
//! // Right spreads exceed left spreads: the solution lies right of the crisp curve.
//! assert!(out.curves.defuzzified.coord(0)[1] > 1.5);
//! # Ok::<(), t2spline::Error>(())
//! ```

mod geometry;
mod output;
mod points;
mod run;
mod settings;

pub use crate::error::Setting;
pub use geometry::{Geometry, NamedCurve};
pub use output::{
    ControlPoints, CrispDefuzzified, Curves, LeftRight, Regime, RunOutput, SixLayers,
};
pub use points::Points;
pub use settings::{
    check_derivative_order, check_samples, Overrides, Settings, DEFAULT_SAMPLES,
    MAX_DERIVATIVE_ORDER, MAX_SAMPLES,
};

use crate::fuzzy::{Alpha, Axis, Nt2Number};
use crate::pipeline::FuzzyCurve;

/// A validated job (SPEC §8): the fuzzy model and how to run it.
#[derive(Clone, Debug, PartialEq)]
pub struct Job {
    /// Free text carried along to the result.
    pub description: Option<String>,
    /// The level alpha; may be left to the front end ([`Overrides::alpha`]).
    pub alpha: Option<Alpha>,
    /// Number of uniform parameters at which curves are sampled (2 ..=
    /// [`MAX_SAMPLES`], checked by [`Job::settings`]).
    pub samples: usize,
    /// The fuzzy model.
    pub model: Model,
}

impl Job {
    /// A job of `model` with the defaults of SPEC §8: no description, alpha
    /// left to the front end, [`DEFAULT_SAMPLES`] samples.
    #[must_use]
    pub fn new(model: Model) -> Job {
        Job {
            description: None,
            alpha: None,
            samples: DEFAULT_SAMPLES,
            model,
        }
    }
}

/// The fuzzy model of a job: a curve in the plane or in space.
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
}

/// Work done on any [`Model`]: one generic method per kind of model.
pub trait ModelVisitor {
    /// What the work gives.
    type Output;
    /// The work on a fuzzy curve of `D` dimensions.
    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> Self::Output;
}

impl Model {
    /// Does `work` on the model, whatever its kind.
    pub fn visit<V: ModelVisitor>(&self, work: V) -> V::Output {
        match self {
            Model::Planar(c) => work.curve(c),
            Model::Spatial(c) => work.curve(c),
        }
    }

    /// The number of coordinates of a point (2 or 3).
    #[must_use]
    pub fn dimension(&self) -> usize {
        struct Dimension;
        impl ModelVisitor for Dimension {
            type Output = usize;
            fn curve<const D: usize>(self, _: &FuzzyCurve<D>) -> usize {
                D
            }
        }
        self.visit(Dimension)
    }

    /// The number of fuzzy control points.
    #[must_use]
    pub fn control_point_count(&self) -> usize {
        struct Count;
        impl ModelVisitor for Count {
            type Output = usize;
            fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> usize {
                c.points().len()
            }
        }
        self.visit(Count)
    }

    /// The order `k` (degree + 1).
    #[must_use]
    pub fn order(&self) -> usize {
        struct Order;
        impl ModelVisitor for Order {
            type Output = usize;
            fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> usize {
                c.order()
            }
        }
        self.visit(Order)
    }

    /// The fuzzy number of one coordinate of one control point; `None` if the
    /// model has no such point or axis.
    #[must_use]
    pub fn number(&self, point: usize, axis: Axis) -> Option<Nt2Number> {
        struct Number(usize, Axis);
        impl ModelVisitor for Number {
            type Output = Option<Nt2Number>;
            fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Option<Nt2Number> {
                c.points()
                    .get(self.0)?
                    .coords()
                    .get(self.1.index())
                    .copied()
            }
        }
        self.visit(Number(point, axis))
    }

    /// The distinct lower heights of the model's numbers, ascending: the
    /// levels where the solution jumps (SPEC §3).
    #[must_use]
    pub fn heights(&self) -> Vec<f64> {
        struct Heights;
        impl ModelVisitor for Heights {
            type Output = Vec<f64>;
            fn curve<const D: usize>(self, c: &FuzzyCurve<D>) -> Vec<f64> {
                c.points()
                    .iter()
                    .flat_map(|p| p.coords().iter().map(|x| x.height().get()))
                    .collect()
            }
        }
        let mut h = self.visit(Heights);
        h.sort_by(f64::total_cmp);
        h.dedup();
        h
    }
}
