//! Brackets of a quantity that is monotone in a surface's heights, from its
//! values at the two extreme nets of a cut (docs/method.md §14): what the
//! volumes and plan area of one surface (`surface_measures.rs`) and the cut
//! and fill against a second (`cut_fill.rs`) share.

use crate::measure::bracket::Bracket;
use crate::measure::measures::{nested, Level, PerMembership};
use crate::measure::volume::VOLUME_TOLERANCE;

/// `f` of each item, on rayon's pool with the feature `parallel` (the
/// extreme nets are independent; each result is computed by the same
/// operations either way), in order.
pub(super) fn each<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync + Send) -> Vec<R> {
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        items.par_iter().map(f).collect()
    }
    #[cfg(not(feature = "parallel"))]
    {
        items.iter().map(f).collect()
    }
}

/// The levels of each function from their brackets, nested across levels
/// and functions (`measures::nested`); a level without a bracket is left out.
pub(super) fn finish(l: PerMembership<Vec<(f64, Option<Bracket>)>>) -> PerMembership<Vec<Level>> {
    let l = nested(l);
    PerMembership::from_fn(|m| {
        l.get(m)
            .iter()
            .filter_map(|(a, b)| b.map(|b| Level::of(*a, b)))
            .collect()
    })
}

/// The bracket of a non-negative quantity from its values `[value, error]`
/// at the extreme net where it is least and at the one where it is largest;
/// exact where both errors are within the tolerance of the largest value or
/// of `scale` (the plan area, times the greatest depth for a volume).
pub(super) fn from_nets(least: [f64; 2], largest: [f64; 2], scale: f64) -> Bracket {
    let scale = largest[0].abs().max(scale);
    let exact = least[1].max(largest[1]) <= VOLUME_TOLERANCE * scale;
    Bracket::from_ends(
        [(least[0] - least[1]).max(0.0), least[0]],
        [largest[0], largest[0] + largest[1]],
        exact,
    )
}
