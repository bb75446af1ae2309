//! The bounds of an envelope: per level and membership function, the least
//! and the greatest height per plan point, and their gathering.

use crate::fuzzy::{Alpha, Membership};

/// The least and the greatest height per plan point (NaN: NODATA).
#[derive(Clone, Debug, PartialEq)]
pub struct EnvelopeBounds {
    /// The least height.
    pub least: Vec<f64>,
    /// The greatest height.
    pub greatest: Vec<f64>,
}

/// The envelope of every membership function at one level; `None` where the
/// function has no cut at this level.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvelopeLevel {
    /// The level.
    pub alpha: f64,
    /// The upper function's bounds.
    pub upper: Option<EnvelopeBounds>,
    /// The primary function's bounds.
    pub primary: Option<EnvelopeBounds>,
    /// The lower function's bounds.
    pub lower: Option<EnvelopeBounds>,
}

impl EnvelopeLevel {
    /// The bounds of one function.
    #[must_use]
    pub fn get(&self, membership: Membership) -> Option<&EnvelopeBounds> {
        match membership {
            Membership::Upper => self.upper.as_ref(),
            Membership::Primary => self.primary.as_ref(),
            Membership::Lower => self.lower.as_ref(),
        }
    }
}

/// Bounds being gathered: per level, per function (upper, primary, lower),
/// `None` where the function has no cut at that level.
pub(crate) struct Gathered {
    pub(crate) levels: Vec<(f64, [Option<EnvelopeBounds>; 3])>,
}

impl Gathered {
    /// Empty bounds (`+∞`, `−∞`) for `n` points, at each level where
    /// `present(alpha)` holds per function.
    pub(crate) fn new(n: usize, levels: &[Alpha], present: impl Fn(usize, f64) -> bool) -> Self {
        let levels = levels
            .iter()
            .map(|a| {
                let alpha = a.get();
                let bounds = [0, 1, 2].map(|k| {
                    present(k, alpha).then(|| EnvelopeBounds {
                        least: vec![f64::INFINITY; n],
                        greatest: vec![f64::NEG_INFINITY; n],
                    })
                });
                (alpha, bounds)
            })
            .collect();
        Gathered { levels }
    }

    /// The finished levels: points never reached NaN; ends that rounding
    /// crossed (at a function's top, where both are the same sum) put in
    /// order; and the order of the functions (upper ⊇ primary ⊇ lower) made
    /// exact where rounding of the separate sums could break it by an ulp.
    pub(crate) fn finish(self) -> Vec<EnvelopeLevel> {
        self.levels
            .into_iter()
            .map(|(alpha, bounds)| {
                let [mut upper, mut primary, mut lower] = bounds;
                for b in [&mut upper, &mut primary, &mut lower].into_iter().flatten() {
                    for (lo, hi) in b.least.iter_mut().zip(&mut b.greatest) {
                        if *lo == f64::INFINITY {
                            (*lo, *hi) = (f64::NAN, f64::NAN);
                        } else if *lo > *hi {
                            (*lo, *hi) = (*hi, *lo);
                        }
                    }
                }
                nest(upper.as_ref(), primary.as_mut());
                nest(primary.as_ref(), lower.as_mut());
                EnvelopeLevel {
                    alpha,
                    upper,
                    primary,
                    lower,
                }
            })
            .collect()
    }
}

/// Clamps `inner` into `outer` where both have data.
fn nest(outer: Option<&EnvelopeBounds>, inner: Option<&mut EnvelopeBounds>) {
    let (Some(o), Some(i)) = (outer, inner) else {
        return;
    };
    let pairs = o.least.iter().zip(&o.greatest);
    for ((lo, hi), (olo, ohi)) in i.least.iter_mut().zip(&mut i.greatest).zip(pairs) {
        if lo.is_nan() || olo.is_nan() {
            continue;
        }
        *lo = lo.max(*olo);
        *hi = hi.min(*ohi);
        if *lo > *hi {
            // Intervals that rounding moved apart by an ulp (at a top, where
            // both are one value): the point between, inside the outer.
            let m = (0.5 * (*lo + *hi)).max(*olo).min(*ohi);
            (*lo, *hi) = (m, m);
        }
    }
}
