//! Small vector helpers on coordinates: the dot and cross products, the
//! difference, and the Euclidean norm. A leaf of the crate: it imports
//! nothing, and the curves, surfaces, distances and the set view share it.

/// `a·b = Σ aᵢ bᵢ`.
pub(crate) fn dot<const D: usize>(a: &[f64; D], b: &[f64; D]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `a − b`.
pub(crate) fn sub<const D: usize>(a: &[f64; D], b: &[f64; D]) -> [f64; D] {
    std::array::from_fn(|d| a[d] - b[d])
}

/// The cross product `a × b` of two vectors in space.
pub(crate) fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The Euclidean norm `√(Σ vᵢ²)` as it is computed, for vectors whose
/// components are known to lie well inside the range of `f64` (derivatives
/// and differences of points within the limits of job files).
pub(crate) fn norm<const D: usize>(v: &[f64; D]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The Euclidean norm `‖v‖₂ = √(Σ vᵢ²)`. Components from 1e-150 to 1e150
/// are squared as they are; beyond, they are first divided by the largest one,
/// so that neither the squares of components near 1e300 overflow nor those
/// near 1e-170 underflow (as `f64::hypot` does for two).
///
/// # Examples
/// ```
/// # use t2spline::vector::euclidean_norm;
/// assert_eq!(euclidean_norm(&[3.0, 4.0]), 5.0);
/// assert_eq!(euclidean_norm(&[3e300, 4e300]), 5e300);
/// assert_eq!(euclidean_norm(&[3e-300, -4e-300, 0.0]), 5e-300);
/// assert_eq!(euclidean_norm(&[]), 0.0);
/// ```
#[must_use]
pub fn euclidean_norm(v: &[f64]) -> f64 {
    let largest = v.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if (1e-150..=1e150).contains(&largest) {
        v.iter().map(|x| x * x).sum::<f64>().sqrt()
    } else if largest == 0.0 || !largest.is_finite() {
        largest
    } else {
        let scaled: f64 = v.iter().map(|x| (x / largest) * (x / largest)).sum();
        largest * scaled.sqrt()
    }
}
