//! The seven ordered values of a fuzzy number, and containers indexed by them.

use std::fmt;

/// One of the seven values of a normal type-2 fuzzy number, in docs/method.md §1 order.
///
/// A fuzzy curve has one *layer curve* per variant: the rational B-spline through
/// that value of every control point.
///
/// ```text
/// UpperLeft ≤ PrimaryLeft ≤ LowerLeft ≤ Crisp ≤ LowerRight ≤ PrimaryRight ≤ UpperRight
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Layer {
    /// Left foot of the upper membership function (paper: left-left).
    UpperLeft,
    /// Left foot of the primary membership function (paper: left).
    PrimaryLeft,
    /// Left foot of the lower membership function (paper: right-left).
    LowerLeft,
    /// The apex shared by all three triangles (paper: P).
    Crisp,
    /// Right foot of the lower membership function (paper: left-right).
    LowerRight,
    /// Right foot of the primary membership function (paper: right).
    PrimaryRight,
    /// Right foot of the upper membership function (paper: right-right).
    UpperRight,
}

impl Layer {
    /// All seven layers in docs/method.md §1 order.
    pub const ALL: [Layer; 7] = [
        Layer::UpperLeft,
        Layer::PrimaryLeft,
        Layer::LowerLeft,
        Layer::Crisp,
        Layer::LowerRight,
        Layer::PrimaryRight,
        Layer::UpperRight,
    ];

    /// Position in [`Layer::ALL`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The snake-case name used in job and result files (`"upper_left"`, ...).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Layer::UpperLeft => "upper_left",
            Layer::PrimaryLeft => "primary_left",
            Layer::LowerLeft => "lower_left",
            Layer::Crisp => "crisp",
            Layer::LowerRight => "lower_right",
            Layer::PrimaryRight => "primary_right",
            Layer::UpperRight => "upper_right",
        }
    }

    /// Whether this is an end of the lower membership function, which has no
    /// alpha-cut above its height (docs/method.md §2).
    #[must_use]
    pub fn is_lower(self) -> bool {
        matches!(self, Layer::LowerLeft | Layer::LowerRight)
    }
}

impl fmt::Display for Layer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One `T` per [`Layer`], indexed by layer.
///
/// ```
/// # use t2spline::{Layer, Layers};
/// let l = Layers::from_fn(|layer| layer.index() * 10);
/// assert_eq!(l[Layer::Crisp], 30);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Layers<T>([T; 7]);

impl<T> Layers<T> {
    /// Builds the seven values from a function of the layer.
    pub fn from_fn(mut f: impl FnMut(Layer) -> T) -> Self {
        Layers(Layer::ALL.map(&mut f))
    }

    /// Applies `f` to every value.
    pub fn map<U>(self, f: impl FnMut(T) -> U) -> Layers<U> {
        Layers(self.0.map(f))
    }

    /// The seven values in docs/method.md §1 order.
    #[must_use]
    pub fn as_array(&self) -> &[T; 7] {
        &self.0
    }

    /// The seven values in docs/method.md §1 order, by value.
    #[must_use]
    pub fn into_array(self) -> [T; 7] {
        self.0
    }

    /// `(layer, value)` pairs in docs/method.md §1 order.
    pub fn iter(&self) -> impl Iterator<Item = (Layer, &T)> {
        Layer::ALL.into_iter().zip(self.0.iter())
    }
}

impl<T> std::ops::Index<Layer> for Layers<T> {
    type Output = T;
    fn index(&self, layer: Layer) -> &T {
        &self.0[layer.index()]
    }
}

impl<T> std::ops::IndexMut<Layer> for Layers<T> {
    fn index_mut(&mut self, layer: Layer) -> &mut T {
        &mut self.0[layer.index()]
    }
}
