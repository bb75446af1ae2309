//! The fuzzy points of a job's or a data file's numbers as read.

use t2spline::{Nt2Number, Nt2Point};

use super::raw::RawNumber;

/// The points of `D` coordinates whose numbers are `numbers`, point after
/// point; a number without a height of its own takes `height`, and a bare
/// number (crisp) takes `height` or else 1.
pub(super) fn fuzzy_points<const D: usize>(
    numbers: &[RawNumber],
    height: Option<f64>,
) -> Option<Vec<Nt2Point<D>>> {
    let numbers = numbers
        .iter()
        .map(|n| {
            let h = n.height.or(height).or(n.bare.then_some(1.0))?;
            Nt2Number::try_new(n.crisp, n.upper, n.primary, n.lower, h).ok()
        })
        .collect::<Option<Vec<_>>>()?;
    numbers
        .chunks_exact(D)
        .map(|p| p.try_into().ok().map(Nt2Point::new))
        .collect()
}
