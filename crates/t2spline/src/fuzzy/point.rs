//! Normal type-2 fuzzy data points in 2-D and 3-D (docs/method.md §5).

use super::alpha::Alpha;
use super::alpha_cut::AlphaCut;
use super::layer::Layer;
use super::number::Nt2Number;
use crate::error::Error;
pub use crate::place::Axis;

impl Axis {
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
}
