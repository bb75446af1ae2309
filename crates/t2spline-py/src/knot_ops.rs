//! The core's knot operations ([`KnotOperations`]: insertion, refinement,
//! degree elevation, splitting) on a curve or surface of either dimension,
//! crisp or fuzzy, written once for the four classes: `along` is `()` for a
//! curve and the [`Direction`](t2spline::Direction) for a surface. Each runs
//! with the GIL released.

use pyo3::prelude::*;
use t2spline::{Error, KnotOperations};

use crate::dim::{ByDim, Family};
use crate::errors::{compute, internal_error};

/// One knot operation and its arguments.
#[derive(Clone, Copy, Debug)]
pub(crate) enum KnotOp<'a> {
    /// Insert the knot `t` this many times (The NURBS Book A5.1).
    Insert(f64, usize),
    /// Insert every knot of the slice, in order (A5.4).
    Refine(&'a [f64]),
    /// Raise the degree this many times (A5.9).
    Elevate(usize),
    /// Split at `t` into the pieces before and after it (§5.3).
    Split(f64),
}

impl KnotOp<'_> {
    /// The operation on `x` along `along`: one object, two for a split.
    fn on<T: KnotOperations>(self, x: &T, along: T::Along) -> Result<Vec<T>, Error> {
        Ok(match self {
            KnotOp::Insert(t, times) => vec![x.insert_knot_along(along, t, times)?],
            KnotOp::Refine(new) => vec![x.refine_knots_along(along, new)?],
            KnotOp::Elevate(times) => vec![x.elevate_degree_along(along, times)?],
            KnotOp::Split(t) => x.split_along(along, t)?.into(),
        })
    }
}

/// `op` on `value` along `along`: the `N` results (1, or 2 for a split), of
/// the dimension of `value`.
///
/// # Errors
/// The core's, as Python exceptions.
pub(crate) fn apply<F, A, const N: usize>(
    py: Python<'_>,
    value: &ByDim<F>,
    along: A,
    op: KnotOp<'_>,
) -> PyResult<[ByDim<F>; N]>
where
    F: Family,
    A: Copy + Send + Sync,
    F::Of<2>: KnotOperations<Along = A>,
    F::Of<3>: KnotOperations<Along = A>,
{
    let results: Vec<ByDim<F>> = compute(py, || {
        Ok(match value {
            ByDim::Planar(c) => op.on(c, along)?.into_iter().map(ByDim::Planar).collect(),
            ByDim::Spatial(c) => op.on(c, along)?.into_iter().map(ByDim::Spatial).collect(),
        })
    })?;
    results.try_into().map_err(|v: Vec<_>| {
        internal_error(&format!("{} results where {N} were expected", v.len()))
    })
}
