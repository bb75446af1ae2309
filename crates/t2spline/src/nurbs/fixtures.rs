//! Curves shared by the unit tests of the curve operations.

use crate::nurbs::{KnotVector, NurbsCurve};

/// A rational quadratic with six points and a double interior knot at 0.3.
pub(crate) fn six_point_quadratic() -> NurbsCurve<2> {
    NurbsCurve::try_new(
        vec![
            [0.0, 0.0],
            [1.0, 3.0],
            [3.0, -1.0],
            [4.0, 2.0],
            [6.0, 0.0],
            [7.0, 1.0],
        ],
        vec![1.0, 2.5, 0.4, 1.0, 3.0, 0.7],
        KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.3, 0.3, 0.8, 1.0, 1.0, 1.0], 2, 6).unwrap(),
    )
    .unwrap()
}

/// A rational cubic with five points and one interior knot at 0.4.
pub(crate) fn five_point_cubic() -> NurbsCurve<2> {
    NurbsCurve::try_new(
        vec![[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0], [6.0, 0.0]],
        vec![1.0, 2.5, 0.4, 1.0, 3.0],
        KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0], 3, 5).unwrap(),
    )
    .unwrap()
}

/// A polyline that jumps at t = 0.5 (knot of full multiplicity): from (0, 0)
/// to (1, 0), then from (5, 5) to (6, 5).
pub(crate) fn jump() -> NurbsCurve<2> {
    NurbsCurve::try_new(
        vec![[0.0, 0.0], [1.0, 0.0], [5.0, 5.0], [6.0, 5.0]],
        vec![1.0; 4],
        KnotVector::try_new(vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0], 1, 4).unwrap(),
    )
    .unwrap()
}

/// An unclamped rational quadratic with the knots 0 … 6 (domain [2, 4]).
pub(crate) fn unclamped_quadratic() -> NurbsCurve<2> {
    NurbsCurve::try_new(
        vec![[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0]],
        vec![1.0, 2.0, 0.5, 1.0],
        KnotVector::try_new(vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], 2, 4).unwrap(),
    )
    .unwrap()
}

/// Asserts that two curves agree at `n` uniform parameters of `a`'s domain to
/// `tol` in every coordinate.
pub(crate) fn assert_same_geometry<const D: usize>(
    a: &NurbsCurve<D>,
    b: &NurbsCurve<D>,
    n: usize,
    tol: f64,
) {
    for t in a.domain().uniform(n).unwrap() {
        let (p, q) = (a.eval(t).unwrap(), b.eval(t).unwrap());
        for d in 0..D {
            assert!((p[d] - q[d]).abs() < tol, "t = {t}: {p:?} vs {q:?}");
        }
    }
}
