//! The normal triangular type-2 fuzzy number (NT2TFN) of docs/method.md §1.

use super::interval::Interval;
use super::layer::{Layer, Layers};
use crate::error::{Error, Place};
use crate::limits::{within_magnitude, MAGNITUDE_RANGE};

/// The height `h` of the lower membership function, in `(0, 1]` (docs/method.md §1).
///
/// `h < 1` is the paper's *normal* case (Def. 4.1); `h = 1` is accepted too.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Height(f64);

impl Height {
    /// Validates a height.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if `value` is NaN or not in `(0, 1]`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Height;
    /// assert_eq!(Height::try_new(0.6)?.get(), 0.6);
    /// assert!(Height::try_new(0.0).is_err());
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_new(value: f64) -> Result<Self, Error> {
        if value > 0.0 && value <= 1.0 {
            Ok(Height(value))
        } else {
            Err(Error::OutOfRange {
                place: Place::NONE,
                what: "lower_height",
                value,
                range: "(0, 1]",
            })
        }
    }

    /// The value.
    #[must_use]
    pub fn get(self) -> f64 {
        self.0
    }
}

/// Which of the three triangles of a number (docs/method.md §1, "Membership functions").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Membership {
    /// Upper membership function `T(x; upper.left, crisp, upper.right, 1)`.
    Upper,
    /// Primary (type-1) membership function `T(x; primary.left, crisp, primary.right, 1)`.
    Primary,
    /// Lower membership function `T(x; lower.left, crisp, lower.right, h)`.
    Lower,
}

/// A normal triangular type-2 fuzzy number (docs/method.md §1, paper Def. 4.1).
///
/// Seven ordered values and the height `h` of the lower membership function:
/// ```text
/// upper.left ≤ primary.left ≤ lower.left ≤ crisp ≤ lower.right ≤ primary.right ≤ upper.right
/// 0 < h ≤ 1
/// ```
/// The three triangles share the apex `crisp`; UMF and primary have height 1, the
/// LMF height `h`. The footprint of uncertainty lies between UMF and LMF.
///
/// # Examples
/// ```
/// # use t2spline::{Alpha, Nt2Number};
/// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
/// let d = x.alpha_cut(Alpha::try_new(0.8)?).type_reduce().defuzzify();
/// assert!((d - 3.05 / 3.0).abs() < 1e-15);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Nt2Number {
    crisp: f64,
    upper: Interval,
    primary: Interval,
    lower: Interval,
    height: Height,
}

/// Names of the seven values in the order of docs/method.md §1, for messages.
const NAMES: [&str; 7] = [
    "upper.left",
    "primary.left",
    "lower.left",
    "crisp",
    "lower.right",
    "primary.right",
    "upper.right",
];

/// The six inequalities of docs/method.md §1, as text.
pub(crate) const RULES: [&str; 6] = [
    "upper.left <= primary.left",
    "primary.left <= lower.left",
    "lower.left <= crisp",
    "crisp <= lower.right",
    "lower.right <= primary.right",
    "primary.right <= upper.right",
];

impl Nt2Number {
    /// Makes a number from its crisp value, its three `[left, right]` pairs and
    /// the lower height `h`.
    ///
    /// # Errors
    /// The first of [`Nt2Number::problems`]: [`Error::NotFinite`],
    /// [`Error::Order`] or [`Error::OutOfRange`] (for `h`, or a value of
    /// magnitude above [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE)).
    pub fn try_new(
        crisp: f64,
        upper: [f64; 2],
        primary: [f64; 2],
        lower: [f64; 2],
        height: f64,
    ) -> Result<Self, Error> {
        match Self::problems(crisp, upper, primary, lower, height)
            .into_iter()
            .next()
        {
            Some(e) => Err(e),
            None => Ok(Nt2Number {
                crisp,
                upper: Interval::new_unchecked(upper[0], upper[1]),
                primary: Interval::new_unchecked(primary[0], primary[1]),
                lower: Interval::new_unchecked(lower[0], lower[1]),
                height: Height(height),
            }),
        }
    }

    /// A crisp (certain) value: all seven values equal `x`, height 1.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if `x` is NaN or infinite.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Alpha, Nt2Number};
    /// let x = Nt2Number::try_crisp(2.5)?;
    /// assert_eq!(x.alpha_cut(Alpha::try_new(0.3)?).type_reduce().defuzzify(), 2.5);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn try_crisp(x: f64) -> Result<Self, Error> {
        Self::try_new(x, [x, x], [x, x], [x, x], 1.0)
    }

    /// Every rule of docs/method.md §1 that these values break, in order; empty if they
    /// make a valid number. A non-finite value is reported as
    /// [`Error::NotFinite`], a finite one of magnitude above
    /// [`MAX_MAGNITUDE`](crate::MAX_MAGNITUDE) as [`Error::OutOfRange`]; either
    /// is left out of the order checks.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::Nt2Number;
    /// // primary.left > lower.left and h > 1: two problems.
    /// let p = Nt2Number::problems(1.0, [0.4, 1.9], [0.9, 1.6], [0.8, 1.3], 1.5);
    /// assert_eq!(p.len(), 2);
    /// ```
    #[must_use]
    pub fn problems(
        crisp: f64,
        upper: [f64; 2],
        primary: [f64; 2],
        lower: [f64; 2],
        height: f64,
    ) -> Vec<Error> {
        let values = [
            upper[0], primary[0], lower[0], crisp, lower[1], primary[1], upper[1],
        ];
        let mut out = Vec::new();
        for (what, &value) in NAMES.iter().zip(&values) {
            if !value.is_finite() {
                out.push(Error::NotFinite {
                    place: Place::NONE,
                    what,
                    value,
                });
            } else if !within_magnitude(value) {
                out.push(Error::OutOfRange {
                    place: Place::NONE,
                    what,
                    value,
                    range: MAGNITUDE_RANGE,
                });
            }
        }
        for (i, rule) in RULES.iter().enumerate() {
            let (left, right) = (values[i], values[i + 1]);
            // A value already reported (not finite, or out of range) is left
            // out: its order says nothing more.
            if within_magnitude(left) && within_magnitude(right) && left > right {
                out.push(Error::Order {
                    place: Place::NONE,
                    rule,
                    left,
                    right,
                });
            }
        }
        if let Err(e) = Height::try_new(height) {
            out.push(e);
        }
        out
    }

    /// The apex `crisp` (paper: P).
    #[must_use]
    pub fn crisp(&self) -> f64 {
        self.crisp
    }

    /// Feet of the upper membership function.
    #[must_use]
    pub fn upper(&self) -> Interval {
        self.upper
    }

    /// Feet of the primary membership function.
    #[must_use]
    pub fn primary(&self) -> Interval {
        self.primary
    }

    /// Feet of the lower membership function.
    #[must_use]
    pub fn lower(&self) -> Interval {
        self.lower
    }

    /// Height `h` of the lower membership function.
    #[must_use]
    pub fn height(&self) -> Height {
        self.height
    }

    /// The value of one layer.
    #[must_use]
    pub fn layer(&self, layer: Layer) -> f64 {
        match layer {
            Layer::UpperLeft => self.upper.left(),
            Layer::PrimaryLeft => self.primary.left(),
            Layer::LowerLeft => self.lower.left(),
            Layer::Crisp => self.crisp,
            Layer::LowerRight => self.lower.right(),
            Layer::PrimaryRight => self.primary.right(),
            Layer::UpperRight => self.upper.right(),
        }
    }

    /// All seven values, in docs/method.md §1 order.
    #[must_use]
    pub fn layers(&self) -> Layers<f64> {
        Layers::from_fn(|l| self.layer(l))
    }

    /// Rebuilds a number from seven layer values and a height; used for numbers
    /// that are convex combinations of valid numbers, which are valid again.
    pub(crate) fn from_layers_unchecked(v: &Layers<f64>, height: Height) -> Self {
        let a = v.as_array();
        debug_assert!(a.windows(2).all(|w| w[0] <= w[1]), "layers {a:?}");
        Nt2Number {
            crisp: a[3],
            upper: Interval::new_unchecked(a[0], a[6]),
            primary: Interval::new_unchecked(a[1], a[5]),
            lower: Interval::new_unchecked(a[2], a[4]),
            height,
        }
    }

    /// The membership grade of `x` in one of the three triangles (docs/method.md §1).
    ///
    /// ```text
    /// T(x; a, c, b, top) = top·(x − a)/(c − a) on [a, c],  top·(b − x)/(b − c) on [c, b],  0 elsewhere
    /// ```
    /// A side of zero width is a vertical edge: `T(c) = top`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Membership, Nt2Number};
    /// let x = Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?;
    /// assert!((x.membership(Membership::Lower, 0.9) - 0.3).abs() < 1e-12);
    /// assert_eq!(x.membership(Membership::Upper, 1.0), 1.0);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    #[must_use]
    pub fn membership(&self, which: Membership, x: f64) -> f64 {
        let (feet, top) = match which {
            Membership::Upper => (self.upper, 1.0),
            Membership::Primary => (self.primary, 1.0),
            Membership::Lower => (self.lower, self.height.get()),
        };
        triangle(x, feet.left(), self.crisp, feet.right(), top)
    }
}

/// `T(x; a, c, b, top)` of docs/method.md §1.
fn triangle(x: f64, a: f64, c: f64, b: f64, top: f64) -> f64 {
    if x == c {
        top
    } else if x < c && x >= a {
        top * (x - a) / (c - a)
    } else if x > c && x <= b {
        top * (b - x) / (b - c)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn problems_reports_every_broken_rule() {
        let p = Nt2Number::problems(1.0, [2.0, 0.0], [0.6, 1.6], [0.8, 1.3], 0.0);
        let rules: Vec<_> = p
            .iter()
            .map(|e| match e {
                Error::Order { rule, .. } => *rule,
                Error::OutOfRange { what, .. } => what,
                _ => "other",
            })
            .collect();
        assert_eq!(
            rules,
            [
                "upper.left <= primary.left",
                "primary.right <= upper.right",
                "lower_height"
            ]
        );
    }

    #[test]
    fn non_finite_values_are_named() {
        let p = Nt2Number::problems(
            1.0,
            [f64::NEG_INFINITY, 1.9],
            [0.6, f64::NAN],
            [0.8, 1.3],
            0.5,
        );
        assert_eq!(p.len(), 2);
        assert!(matches!(
            p[0],
            Error::NotFinite {
                what: "upper.left",
                ..
            }
        ));
        assert!(matches!(
            p[1],
            Error::NotFinite {
                what: "primary.right",
                ..
            }
        ));
    }

    #[test]
    fn equal_neighbours_are_allowed() {
        let x = Nt2Number::try_new(1.0, [1.0, 1.0], [1.0, 1.0], [1.0, 1.0], 1.0).unwrap();
        assert_eq!(x.layers().as_array(), &[1.0; 7]);
    }

    #[test]
    fn membership_has_vertical_edges_for_zero_width_sides() {
        let x = Nt2Number::try_new(1.0, [1.0, 2.0], [1.0, 1.5], [1.0, 1.2], 0.5).unwrap();
        assert_eq!(x.membership(Membership::Upper, 1.0), 1.0);
        assert_eq!(x.membership(Membership::Upper, 0.999), 0.0);
        assert!((x.membership(Membership::Lower, 1.1) - 0.25).abs() < 1e-15);
        assert_eq!(x.membership(Membership::Primary, 1.5), 0.0);
    }
}
