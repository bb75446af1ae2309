//! The grades of one point in a fuzzy curve or surface as a set
//! (docs/method.md §10), one per membership function.

use crate::fuzzy::Membership;

/// The grades of one point under the three membership functions, each in
/// `[0, 1]` (the lower in `[0, h]`), with `lower ≤ primary ≤ upper`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Grades {
    /// `mu_upper(p)`: the largest level at which some curve with control
    /// points inside their upper cuts passes through `p`.
    pub upper: f64,
    /// `mu_primary(p)`, the same with the primary cuts.
    pub primary: f64,
    /// `mu_lower(p)`, the same with the lower cuts.
    pub lower: f64,
}

impl Grades {
    /// The grade under `membership`.
    #[must_use]
    pub fn get(&self, membership: Membership) -> f64 {
        match membership {
            Membership::Upper => self.upper,
            Membership::Primary => self.primary,
            Membership::Lower => self.lower,
        }
    }

    /// The three grades from the sups found for each function, kept in the
    /// order `lower ≤ primary ≤ upper`, which holds exactly (every lower cut
    /// lies inside the primary cut at the same level, and that inside the
    /// upper) and which separate searches could break in the last bits.
    pub(crate) fn ordered([upper, primary, lower]: [f64; 3]) -> Self {
        let upper = upper.clamp(0.0, 1.0);
        let primary = primary.clamp(0.0, upper);
        Grades {
            upper,
            primary,
            lower: lower.clamp(0.0, primary),
        }
    }
}
