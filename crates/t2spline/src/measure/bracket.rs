//! The result of one quantity under one membership function at one level:
//! the interval of its values over the box of cut control points
//! (docs/method.md §11), exact or certified.

/// The interval `[min, max]` of a quantity over the box of cut control
/// points, never narrower than the truth.
///
/// With `lo` and `hi` the true least and largest values,
/// `min ≤ lo ≤ min + gap` and `max − gap ≤ hi ≤ max`: `min` and `max` are
/// certified outer bounds, and `gap` is how far each may lie outside the
/// truth. `exact` says that `gap` is rounding or the stated tolerance only
/// (vertex enumeration, signed coefficients, a convex minimum solved to
/// 1e-9 of the value); where it is `false` the interval is a certified
/// enclosure (branch and bound, interval arithmetic) whose `gap` is the
/// distance between the outer bounds and values actually attained.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Bracket {
    /// A lower bound of the least value (at most `gap` below it).
    pub min: f64,
    /// An upper bound of the largest value (at most `gap` above it).
    pub max: f64,
    /// Whether both ends are exact to rounding or the stated tolerance.
    pub exact: bool,
    /// The largest distance of either end from a value attained.
    pub gap: f64,
}

impl Bracket {
    /// The bracket of a value known exactly: `[value, value]`.
    #[must_use]
    pub fn point(value: f64) -> Self {
        Bracket {
            min: value,
            max: value,
            exact: true,
            gap: 0.0,
        }
    }

    /// From bounds of each end: the least value lies in `least` (a certified
    /// lower bound and a value attained), the largest in `largest` (a value
    /// attained and a certified upper bound).
    pub(crate) fn from_ends(least: [f64; 2], largest: [f64; 2], exact: bool) -> Self {
        let gap = (least[1] - least[0]).max(largest[1] - largest[0]).max(0.0);
        Bracket {
            min: least[0].min(least[1]),
            max: largest[1].max(largest[0]),
            exact,
            gap,
        }
    }

    /// Whether `value` lies inside, with a relative slack `slack` of the
    /// interval's magnitude (for tests of values computed another way).
    #[must_use]
    pub fn holds(&self, value: f64, slack: f64) -> bool {
        let scale = self.min.abs().max(self.max.abs()).max(value.abs());
        value >= self.min - slack * scale && value <= self.max + slack * scale
    }

    /// Whether `self` contains `inner`, with a relative slack.
    #[must_use]
    pub fn contains(&self, inner: &Bracket, slack: f64) -> bool {
        self.holds(inner.min, slack) && self.holds(inner.max, slack)
    }
}
