//! The system of a curve fit, open or closed: one face for the fuzzy fit,
//! which fits every layer through it alike.

use crate::error::Error;
use crate::fit::cyclic::CyclicDesign;
use crate::fit::design::Design;
use crate::nurbs::KnotVector;

/// The basis at the data parameters of an open curve (clamped knots, both
/// end values fixed to the end data: [`Design`]) or of a closed one
/// (periodic knots, columns folded: [`CyclicDesign`]).
#[derive(Clone, Debug)]
pub(crate) enum System {
    Open(Design),
    Closed(CyclicDesign),
}

impl System {
    /// The system of `params` and `knots`: closed for a closed fit's loop
    /// parameters and periodic knots.
    ///
    /// # Errors
    /// As [`Design::new`] and [`CyclicDesign::new`].
    pub(crate) fn new(params: &[f64], knots: &KnotVector, closed: bool) -> Result<Self, Error> {
        Ok(if closed {
            System::Closed(CyclicDesign::new(params, knots)?)
        } else {
            System::Open(Design::new(params, knots)?)
        })
    }

    /// The estimated condition number of the system.
    pub(crate) fn condition(&self) -> f64 {
        match self {
            System::Open(d) => d.condition(),
            System::Closed(d) => d.condition(),
        }
    }

    /// The control values fitting `q`, one per parameter.
    ///
    /// # Errors
    /// [`Error::SingularFit`] if the data do not determine them.
    pub(crate) fn fit<const R: usize>(&self, q: &[[f64; R]]) -> Result<Vec<[f64; R]>, Error> {
        match self {
            System::Open(d) => d.fit(q),
            System::Closed(d) => d.fit(q),
        }
    }

    /// Non-negative control values fitting `q`.
    ///
    /// # Errors
    /// As [`System::fit`].
    pub(crate) fn fit_nonnegative(&self, q: &[f64]) -> Result<Vec<f64>, Error> {
        match self {
            System::Open(d) => d.fit_nonnegative(q),
            System::Closed(d) => d.fit_nonnegative(q),
        }
    }

    /// The curve values at every parameter.
    pub(crate) fn values<const R: usize>(&self, control: &[[f64; R]]) -> Vec<[f64; R]> {
        match self {
            System::Open(d) => d.values(control),
            System::Closed(d) => d.values(control),
        }
    }
}
