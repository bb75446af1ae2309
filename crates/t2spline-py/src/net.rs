//! Control nets as numpy arrays. The control points of a curve form a net of
//! shape `(n,)`, those of a surface a net of shape `(nu, nv)` (row `i` along
//! u, column `j` along v, as `points[i][j]` in job files); every array of
//! per-point values has the net's shape followed by the value's: `(n, d)`
//! and `(nu, nv, d)` for points, `(nu, nv)` for weights, `(nu, nv, d, 2)`
//! for the feet of fuzzy numbers.

use pyo3::prelude::*;
use t2spline::{
    FuzzyCurve, FuzzySurface, Nt2Number, Nt2Point, NurbsCurve, NurbsSurface, Solution,
    SurfaceSolution,
};

use crate::arrays::array;

/// A model with a net of control points.
pub(crate) trait Net {
    /// The shape of the net: `[n]` for a curve, `[nu, nv]` for a surface.
    fn net(&self) -> Vec<usize>;
}

/// `nets! { Type: |value| net; … }`: [`Net`] for `Type<D>` of every
/// dimension, the net read off `value`.
macro_rules! nets {
    ($($ty:ident: |$value:ident| $net:expr;)*) => {$(
        impl<const D: usize> Net for $ty<D> {
            fn net(&self) -> Vec<usize> {
                let $value = self;
                $net
            }
        }
    )*};
}

nets! {
    NurbsCurve: |c| vec![c.control_points().len()];
    FuzzyCurve: |c| vec![c.points().len()];
    Solution: |s| s.fuzzy_curve().net();
    NurbsSurface: |s| s.shape().to_vec();
    FuzzySurface: |s| s.shape().to_vec();
    SurfaceSolution: |s| s.fuzzy_surface().net();
}

/// `net` followed by `tail`: the shape of an array of per-point values.
pub(crate) fn shape(net: &[usize], tail: &[usize]) -> Vec<usize> {
    net.iter().chain(tail).copied().collect()
}

/// Points in net order (row by row) as an array of shape `net + (D,)`.
pub(crate) fn points_array<'py, const D: usize>(
    py: Python<'py>,
    points: Vec<[f64; D]>,
    net: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    array(py, points.into_flattened(), &shape(net, &[D]))
}

/// One value per control point and coordinate, `f(number)` each, as an
/// array of shape `net + (D,) + tail`.
pub(crate) fn per_number<'py, const D: usize>(
    py: Python<'py>,
    points: &[Nt2Point<D>],
    net: &[usize],
    tail: &[usize],
    f: impl Fn(&Nt2Number, &mut Vec<f64>),
) -> PyResult<Bound<'py, PyAny>> {
    let mut values = Vec::new();
    for number in points.iter().flat_map(|p| p.coords()) {
        f(number, &mut values);
    }
    array(py, values, &shape(net, &shape(&[D], tail)))
}
