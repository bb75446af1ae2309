//! Where to sample: uniform parameters over the domain, or given ones.

use crate::error::Error;
use crate::nurbs::Domain;

/// The parameters at which a sampler evaluates its curves.
///
/// `Uniform(n)` is SPEC §8's grid over the curve's domain `[a, b]`,
///
/// ```text
/// tᵢ = a + (b − a)·i/(n − 1),  i = 0 … n − 1,  the last exactly b
/// ```
/// (the same values as [`Domain::uniform`], computed on the fly, so no parameter
/// array is stored or read). `Given` parameters may come in any order; sorted
/// ones are fastest, since the sampler then walks from span to span instead of
/// searching.
///
/// # Examples
/// ```
/// # use t2spline::sampling::Params;
/// let t = [0.0, 0.25, 1.0];
/// assert_eq!(Params::from(&t[..]).len(), 3);
/// assert_eq!(Params::Uniform(101).len(), 101);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Params<'a> {
    /// `n` uniform parameters over the domain, both ends included.
    Uniform(usize),
    /// The given parameters, each in the domain, in any order.
    Given(&'a [f64]),
}

impl<'a> From<&'a [f64]> for Params<'a> {
    fn from(t: &'a [f64]) -> Self {
        Params::Given(t)
    }
}

impl<'a> From<&'a Vec<f64>> for Params<'a> {
    fn from(t: &'a Vec<f64>) -> Self {
        Params::Given(t)
    }
}

impl<'a, const N: usize> From<&'a [f64; N]> for Params<'a> {
    fn from(t: &'a [f64; N]) -> Self {
        Params::Given(t)
    }
}

impl Params<'_> {
    /// The number of parameters.
    #[must_use]
    pub fn len(&self) -> usize {
        match self {
            Params::Uniform(n) => *n,
            Params::Given(t) => t.len(),
        }
    }

    /// Whether there are no parameters.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The parameters as a vector (for `Uniform`, [`Domain::uniform`]).
    #[must_use]
    pub fn to_vec(&self, domain: Domain) -> Vec<f64> {
        match self {
            Params::Uniform(n) => domain.uniform(*n),
            Params::Given(t) => t.to_vec(),
        }
    }

    /// `Ok` if every parameter lies in `domain`.
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first one that does not (or is NaN).
    pub(crate) fn check(&self, domain: Domain) -> Result<(), Error> {
        match self {
            Params::Uniform(_) => Ok(()),
            Params::Given(t) => match t.iter().find(|&&t| !domain.contains(t)) {
                Some(&t) => domain.check(t),
                None => Ok(()),
            },
        }
    }

    /// Writes the parameters `first .. first + out.len()` into `out`.
    #[inline]
    pub(crate) fn fill(&self, domain: Domain, first: usize, out: &mut [f64]) {
        match self {
            Params::Uniform(n) => {
                // Exactly `Domain::uniform`: lerp(i / (n − 1)), the last one b.
                let last = n.saturating_sub(1).max(1) as f64;
                for (i, t) in out.iter_mut().enumerate() {
                    *t = domain.lerp((first + i) as f64 / last);
                }
            }
            Params::Given(t) => out.copy_from_slice(&t[first..first + out.len()]),
        }
    }
}
