//! Normal type-2 fuzzy data points in 2-D and 3-D (docs/method.md §5).

use std::fmt;

use crate::fuzzy::{Alpha, AlphaCut, Layer, Nt2Number, Tfn};
use crate::Error;

/// A coordinate axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Axis {
    /// The first coordinate.
    X,
    /// The second coordinate.
    Y,
    /// The third coordinate.
    Z,
}

impl Axis {
    /// The axes in order.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// The first `D` axes, in order: the check of a dimension that every
    /// constructor generic over `D` makes.
    ///
    /// # Errors
    /// [`Error::Dimension`] unless `1 ≤ D ≤ 3`: a point has one, two or three
    /// coordinates, each named by an axis.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Axis, Error};
    /// assert_eq!(Axis::first::<2>()?, [Axis::X, Axis::Y]);
    /// assert_eq!(Axis::first::<4>(), Err(Error::Dimension { dimension: 4 }));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn first<const D: usize>() -> Result<[Axis; D], Error> {
        if D == 0 || D > Axis::ALL.len() {
            return Err(Error::Dimension { dimension: D });
        }
        Ok(Axis::of::<D>())
    }

    /// The first `D` axes, for a `D` a constructor has checked
    /// ([`Axis::first`]); past the third every index names `z`, which no
    /// checked value reaches.
    pub(crate) fn of<const D: usize>() -> [Axis; D] {
        std::array::from_fn(|i| Axis::from_index(i).unwrap_or(Axis::Z))
    }

    /// The axis with this index (`0 → x`), if any.
    #[must_use]
    pub fn from_index(i: usize) -> Option<Axis> {
        Axis::ALL.get(i).copied()
    }

    /// Index of the coordinate (`x → 0`).
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The key used in job files: `"x"`, `"y"` or `"z"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
            Axis::Z => "z",
        }
    }
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A normal type-2 fuzzy data (or control) point: one [`Nt2Number`] per
/// coordinate (docs/method.md §5, the paper's NT2FDP). Every operation acts per coordinate.
///
/// # Examples
/// ```
/// # use t2spline::{Alpha, Layer, Nt2Number, Nt2Point};
/// let p = Nt2Point::new([
///     Nt2Number::try_new(1.0, [0.4, 1.9], [0.6, 1.6], [0.8, 1.3], 0.6)?,
///     Nt2Number::try_new(1.0, [0.2, 1.5], [0.5, 1.35], [0.75, 1.2], 0.6)?,
/// ]);
/// assert_eq!(p.layer(Layer::UpperLeft), [0.4, 0.2]);
/// let d = p.defuzzify(Alpha::try_new(0.8)?);
/// assert!((d[0] - 3.05 / 3.0).abs() < 1e-15 && (d[1] - 2.955 / 3.0).abs() < 1e-15);
/// # Ok::<(), t2spline::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nt2Point<const D: usize> {
    coords: [Nt2Number; D],
}

#[cfg(feature = "serde")]
impl<const D: usize> serde::Serialize for Nt2Point<D> {
    /// A point serializes as the list of its coordinates' numbers.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.coords.as_slice().serialize(s)
    }
}

/// A 2-D fuzzy point.
pub type Nt2Point2 = Nt2Point<2>;
/// A 3-D fuzzy point.
pub type Nt2Point3 = Nt2Point<3>;

impl<const D: usize> Nt2Point<D> {
    /// Makes a point from one validated number per coordinate.
    #[must_use]
    pub fn new(coords: [Nt2Number; D]) -> Self {
        Nt2Point { coords }
    }

    /// The numbers, one per coordinate.
    #[must_use]
    pub fn coords(&self) -> &[Nt2Number; D] {
        &self.coords
    }

    /// The number of one coordinate, if the point has that axis.
    #[must_use]
    pub fn coord(&self, axis: Axis) -> Option<&Nt2Number> {
        self.coords.get(axis.index())
    }

    /// The crisp point.
    #[must_use]
    pub fn crisp(&self) -> [f64; D] {
        self.layer(Layer::Crisp)
    }

    /// The point made of one layer's values, e.g. all `upper.left` ends (the
    /// paper's "left(x)/lower(y)" footprint point for [`Layer::UpperLeft`]).
    #[must_use]
    pub fn layer(&self, layer: Layer) -> [f64; D] {
        self.coords.map(|x| x.layer(layer))
    }

    /// The alpha-cut of every coordinate (docs/method.md §2).
    #[must_use]
    pub fn alpha_cut(&self, alpha: Alpha) -> [AlphaCut; D] {
        self.coords.map(|x| x.alpha_cut(alpha))
    }

    /// Alpha-cut then type reduction of every coordinate (docs/method.md §2–§3).
    #[must_use]
    pub fn type_reduce(&self, alpha: Alpha) -> [Tfn; D] {
        self.alpha_cut(alpha).map(|c| c.type_reduce())
    }

    /// Alpha-cut, type reduction and defuzzification of every coordinate
    /// (docs/method.md §2–§4): the paper's crisp type-2 solution point.
    #[must_use]
    pub fn defuzzify(&self, alpha: Alpha) -> [f64; D] {
        self.type_reduce(alpha).map(|t| t.defuzzify())
    }
}
