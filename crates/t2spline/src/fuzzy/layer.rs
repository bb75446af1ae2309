//! The seven ordered values of a fuzzy number, and containers indexed by them.

pub use crate::place::Layer;

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

    /// Builds the seven values from a fallible function of the layer, in
    /// docs/method.md §1 order, stopping at the first error.
    ///
    /// # Errors
    /// The first error of `f`.
    pub fn try_from_fn<E>(mut f: impl FnMut(Layer) -> Result<T, E>) -> Result<Self, E> {
        let mut values = Vec::with_capacity(Layer::ALL.len());
        for layer in Layer::ALL {
            values.push(f(layer)?);
        }
        let mut values = values.into_iter();
        // One value was pushed per layer, in the same order.
        #[allow(clippy::expect_used)]
        Ok(Layers::from_fn(|_| {
            values.next().expect("one value per layer")
        }))
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
