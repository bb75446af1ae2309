//! Where to sample: uniform parameters over the domain, or given ones.

use crate::error::Error;
use crate::nurbs::Domain;

/// Parameters per block: the parameters, local variables and reciprocal
/// denominators of a block stay in the first-level cache.
pub(crate) const BLOCK: usize = 512;

/// `0, 1, …, BLOCK − 1` as floats.
const STEPS: [f64; BLOCK] = {
    let mut steps = [0.0; BLOCK];
    let mut k = 0;
    while k < BLOCK {
        steps[k] = k as f64;
        k += 1;
    }
    steps
};

/// The parameters at which a sampler evaluates its curves.
///
/// `Uniform(n)` is docs/jobs.md's grid over the curve's domain `[a, b]`,
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
    ///
    /// # Errors
    /// [`Error::Memory`] if they cannot be held in memory.
    pub fn to_vec(&self, domain: Domain) -> Result<Vec<f64>, Error> {
        match self {
            Params::Uniform(n) => domain.uniform(*n),
            Params::Given(t) => Ok(t.to_vec()),
        }
    }

    /// `Ok(sorted)` if every parameter lies in `domain`, where `sorted` says
    /// whether they never decrease (always for `Uniform`).
    ///
    /// # Errors
    /// [`Error::OutOfDomain`] for the first one that does not (or is NaN).
    pub(crate) fn check(&self, domain: Domain) -> Result<bool, Error> {
        match self {
            Params::Uniform(_) => Ok(true),
            Params::Given(t) => {
                let mut sorted = true;
                let mut previous = f64::NEG_INFINITY;
                for &x in *t {
                    domain.check(x)?;
                    sorted &= previous <= x;
                    previous = x;
                }
                Ok(sorted)
            }
        }
    }

    /// Writes the parameters `first .. first + out.len()` into `out`.
    #[inline]
    pub(crate) fn fill(&self, domain: Domain, first: usize, out: &mut [f64]) {
        match self {
            Params::Uniform(n) => {
                // Exactly `Domain::uniform`: lerp(i / (n − 1)), the last one b.
                // `first + STEPS[k]` is the integer `first + k` exactly (below
                // 2⁵³), without a slow unsigned conversion per parameter.
                // `lerp(s)` is `a + (b − a)·s` except at s = 1, which only the
                // last parameter reaches (then `b` exactly); so the loop has no
                // branch and the last one is set afterwards.
                let last = n.saturating_sub(1).max(1) as f64;
                let base = first as f64;
                let (a, width) = (domain.start, domain.end - domain.start);
                for (t, step) in out.iter_mut().zip(&STEPS) {
                    *t = a + width * ((base + step) / last);
                }
                if *n >= 2 && first + out.len() == *n {
                    if let Some(t) = out.last_mut() {
                        *t = domain.end;
                    }
                }
            }
            Params::Given(t) => out.copy_from_slice(&t[first..first + out.len()]),
        }
    }
}
