//! The one place the command line tells the kinds of a job's model apart: a
//! plane curve, a space curve or a surface. Every command asks here for the
//! kind it needs, so that no command matches the core's `Model` itself, and
//! a kind this command line does not know is refused here, once.

use t2spline::job::Model;
use t2spline::{FuzzyCurve, FuzzySurface};

use crate::exit::OptionError;

/// A job's model by the kind the commands tell apart, borrowed.
#[derive(Clone, Copy, Debug)]
pub enum ModelKind<'a> {
    /// A curve through points `x`, `y`.
    PlaneCurve(&'a FuzzyCurve<2>),
    /// A curve through points `x`, `y`, `z`.
    SpaceCurve(&'a FuzzyCurve<3>),
    /// A surface over a net of points `x`, `y`, `z`.
    Surface(&'a FuzzySurface<3>),
}

impl<'a> ModelKind<'a> {
    /// The kind of `model`.
    ///
    /// # Errors
    /// A kind of model this command line does not know (the core's `Model`
    /// may gain kinds), named as the job's.
    pub fn of(model: &'a Model) -> Result<Self, OptionError> {
        match model {
            Model::Planar(c) => Ok(Self::PlaneCurve(c)),
            Model::Spatial(c) => Ok(Self::SpaceCurve(c)),
            Model::Surface(s) => Ok(Self::Surface(s)),
            _ => Err(OptionError {
                option: "JOB",
                message: "the job's model is of a kind this command line does not know".into(),
            }),
        }
    }

    /// The surface, if the model is one.
    pub fn surface(self) -> Option<&'a FuzzySurface<3>> {
        match self {
            Self::Surface(s) => Some(s),
            Self::PlaneCurve(_) | Self::SpaceCurve(_) => None,
        }
    }

    /// Whether the model is a plane curve.
    pub fn is_plane_curve(self) -> bool {
        matches!(self, Self::PlaneCurve(_))
    }

    /// The number of coordinates of a point (2 or 3).
    pub fn dimension(self) -> usize {
        match self {
            Self::PlaneCurve(_) => 2,
            Self::SpaceCurve(_) | Self::Surface(_) => 3,
        }
    }

    /// The kind in words, as messages name it: `a plane curve`, `a space
    /// curve`, `a surface`.
    pub fn name(self) -> &'static str {
        match self {
            Self::PlaneCurve(_) => "a plane curve",
            Self::SpaceCurve(_) => "a space curve",
            Self::Surface(_) => "a surface",
        }
    }
}
