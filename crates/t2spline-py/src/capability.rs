//! The core's capabilities (`t2spline::capability`) as Python methods, one
//! implementation per operation for every class that has it: a crisp
//! object's value comes out as it is, a fuzzy object's seven layer values
//! with an axis of 7 before the value's own axes (layers in the order of
//! docs/method.md §1). The classes keep their own names and docstrings; their
//! bodies call these.

use pyo3::prelude::*;
use t2spline::{
    Bounded, Closest, ClosestPoint, ClosestSurfacePoint, Curvature, Differentiable, Layers,
    Parametric,
};

use crate::arrays::array;
use crate::closest::Targets;
use crate::construct::count;
use crate::errors::{compute, internal_error};
use crate::keyword;
use crate::py_types::{Obj, ObjResult, Pair};
use crate::sample::{at_pairs, at_params};

/// A capability's value at one parameter, as numbers in C order.
pub(crate) trait Values {
    /// The axes before the value's own: `[]` for a crisp object, `[7]` for a
    /// fuzzy one.
    const LAYERS: &'static [usize];

    /// Appends the numbers; a surface's derivatives fill the `rows × rows`
    /// table, NaN where `k + l` is above the order.
    fn extend_into(self, rows: usize, out: &mut Vec<f64>);
}

impl Values for f64 {
    const LAYERS: &'static [usize] = &[];

    fn extend_into(self, _rows: usize, out: &mut Vec<f64>) {
        out.push(self);
    }
}

/// A point: its coordinates.
impl<const D: usize> Values for [f64; D] {
    const LAYERS: &'static [usize] = &[];

    fn extend_into(self, _rows: usize, out: &mut Vec<f64>) {
        out.extend(self);
    }
}

/// A curve's derivatives `C⁽ᵏ⁾`, `k = 0..rows`.
impl<const D: usize> Values for Vec<[f64; D]> {
    const LAYERS: &'static [usize] = &[];

    fn extend_into(self, _rows: usize, out: &mut Vec<f64>) {
        out.extend(self.into_iter().flatten());
    }
}

/// A surface's derivatives `∂ᵏ⁺ˡS/∂uᵏ∂vˡ`, `k + l ≤ order`, in a square table.
impl<const D: usize> Values for Vec<Vec<[f64; D]>> {
    const LAYERS: &'static [usize] = &[];

    fn extend_into(self, rows: usize, out: &mut Vec<f64>) {
        for k in 0..rows {
            for l in 0..rows {
                match self.get(k).and_then(|row| row.get(l)) {
                    Some(value) => out.extend(value),
                    None => out.extend([f64::NAN; D]),
                }
            }
        }
    }
}

impl<X: Values> Values for Layers<X> {
    const LAYERS: &'static [usize] = &[7];

    fn extend_into(self, rows: usize, out: &mut Vec<f64>) {
        for value in self.into_array() {
            value.extend_into(rows, out);
        }
    }
}

/// The tail of an output: the layers' axis, then `own`.
fn tail<V: Values>(own: &[usize]) -> Vec<usize> {
    V::LAYERS.iter().chain(own).copied().collect()
}

/// The order of the derivatives asked for: `order`, default 1.
///
/// # Errors
/// `TypeError` or `ValueError` naming `order` for a value that is not a
/// count.
fn derivative_order(order: Option<&Obj<'_>>) -> PyResult<usize> {
    count(keyword::opt_int(order, "order")?.unwrap_or(1), "order", 0)
}

/// The point of a curve with `dimension` coordinates at every value of `t`
/// (the straightforward evaluator): shape `t.shape + (dimension,)`, with
/// `(7,)` before the last axis for a fuzzy curve's layers.
pub(crate) fn curve_points<'py, T>(
    py: Python<'py>,
    object: &T,
    t: &Obj<'py>,
    dimension: usize,
) -> ObjResult<'py>
where
    T: Parametric<Param = f64> + Sync,
    T::Point: Values,
{
    at_params(py, t, &tail::<T::Point>(&[dimension]), |v, out| {
        object.point_at(v)?.extend_into(0, out);
        Ok(())
    })
}

/// The point of a surface with `dimension` coordinates at every pair of `u`
/// and `v`: shape `broadcast(u, v).shape + (dimension,)`, with `(7,)` before
/// the last axis for a fuzzy surface's layers.
pub(crate) fn surface_points<'py, T>(
    py: Python<'py>,
    object: &T,
    [u, v]: [&Obj<'py>; 2],
    dimension: usize,
) -> ObjResult<'py>
where
    T: Parametric<Param = [f64; 2]> + Sync,
    T::Point: Values,
{
    at_pairs(py, u, v, &tail::<T::Point>(&[dimension]), |u, v, out| {
        object.point_at([u, v])?.extend_into(0, out);
        Ok(())
    })
}

/// The axis-aligned box `(min, max)` of a curve or surface, crisp or fuzzy
/// (a fuzzy object's box holds all seven layers), each of shape
/// `(dimension,)`.
pub(crate) fn bounding_box<'py, const D: usize, T: Bounded<D> + Sync>(
    py: Python<'py>,
    object: &T,
) -> PyResult<Pair<'py>> {
    let (lo, hi) = compute(py, || {
        let b = object.bounding_box();
        Ok((b.min.to_vec(), b.max.to_vec()))
    })?;
    Ok((array(py, lo, &[D])?, array(py, hi, &[D])?))
}

/// The curvature of a curve at every value of `t`: shape `t.shape` (a float
/// for a number) for a crisp curve, `t.shape + (7,)` for a fuzzy one.
pub(crate) fn curve_curvature<'py, T>(
    py: Python<'py>,
    object: &T,
    t: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>>
where
    T: Curvature<Param = f64> + Sync,
    T::Curvature: Values,
{
    at_params(py, t, &tail::<T::Curvature>(&[]), |v, out| {
        object.curvature_at(v)?.extend_into(0, out);
        Ok(())
    })
}

/// The derivatives of a curve with `dimension` coordinates up to `order`
/// (default 1) at every value of `t`: shape `t.shape + (order + 1, dimension)`, with `(7,)` before the last two axes
/// for a fuzzy curve.
pub(crate) fn curve_derivatives<'py, T>(
    py: Python<'py>,
    object: &T,
    t: &Obj<'py>,
    order: Option<&Obj<'py>>,
    dimension: usize,
) -> ObjResult<'py>
where
    T: Differentiable<Param = f64> + Sync,
    T::Derivatives: Values,
{
    let order = derivative_order(order)?;
    // The order is checked by the core before anything is computed.
    let rows = order.min(t2spline::nurbs::MAX_DERIVATIVE_ORDER) + 1;
    at_params(
        py,
        t,
        &tail::<T::Derivatives>(&[rows, dimension]),
        |v, out| {
            object.derivatives_at(v, order)?.extend_into(rows, out);
            Ok(())
        },
    )
}

/// The derivatives of a surface up to `order` (default 1) at every pair of `u` and `v`:
/// shape `broadcast(u, v).shape + (order + 1, order + 1, dimension)`, NaN
/// where `k + l > order`, with `(7,)` before the last three axes for a fuzzy
/// surface.
pub(crate) fn surface_derivatives<'py, T>(
    py: Python<'py>,
    object: &T,
    [u, v]: [&Obj<'py>; 2],
    order: Option<&Obj<'py>>,
    dimension: usize,
) -> ObjResult<'py>
where
    T: Differentiable<Param = [f64; 2]> + Sync,
    T::Derivatives: Values,
{
    let order = derivative_order(order)?;
    let rows = order.min(t2spline::nurbs::MAX_DERIVATIVE_ORDER) + 1;
    at_pairs(
        py,
        u,
        v,
        &tail::<T::Derivatives>(&[rows, rows, dimension]),
        |u, v, out| {
            object.derivatives_at([u, v], order)?.extend_into(rows, out);
            Ok(())
        },
    )
}

/// A nearest point as columns: its parameters (`t` of a curve, `u` and `v`
/// of a surface), its coordinates and its distance.
pub(crate) trait Nearest {
    /// The parameters: 1 for a curve, 2 for a surface.
    const PARAMS: usize;
    /// `[]` for a crisp object, `[7]` for a fuzzy one.
    const LAYERS: &'static [usize];

    /// Appends to the columns: the parameters, then the point, then the
    /// distance.
    fn push_into(&self, columns: &mut [Vec<f64>]);
}

impl<const D: usize> Nearest for ClosestPoint<D> {
    const PARAMS: usize = 1;
    const LAYERS: &'static [usize] = &[];

    fn push_into(&self, columns: &mut [Vec<f64>]) {
        for (column, values) in
            columns
                .iter_mut()
                .zip([&[self.t][..], &self.point, &[self.distance]])
        {
            column.extend_from_slice(values);
        }
    }
}

impl<const D: usize> Nearest for ClosestSurfacePoint<D> {
    const PARAMS: usize = 2;
    const LAYERS: &'static [usize] = &[];

    fn push_into(&self, columns: &mut [Vec<f64>]) {
        let values = [&[self.u][..], &[self.v], &self.point, &[self.distance]];
        for (column, values) in columns.iter_mut().zip(values) {
            column.extend_from_slice(values);
        }
    }
}

impl<X: Nearest> Nearest for Layers<X> {
    const PARAMS: usize = X::PARAMS;
    const LAYERS: &'static [usize] = &[7];

    fn push_into(&self, columns: &mut [Vec<f64>]) {
        for (_, found) in self.iter() {
            found.push_into(columns);
        }
    }
}

/// The nearest point of a curve or surface, crisp or fuzzy, to every target
/// of `point` (one point `(D,)` or many `(m, D)`): the `N` arrays
/// `(parameters…, point, distance)`, each of the targets' shape (a float for
/// one target), then `(7,)` for a fuzzy object, then `(D,)` for the point.
///
/// # Errors
/// Those of [`Targets::extract`]; the core's.
pub(crate) fn closest<'py, const D: usize, const N: usize, T>(
    py: Python<'py>,
    object: &T,
    point: &Obj<'py>,
) -> PyResult<[Obj<'py>; N]>
where
    T: Closest<D> + Sync,
    T::Nearest: Nearest,
{
    let targets = Targets::extract(point, D)?;
    let params = <T::Nearest as Nearest>::PARAMS;
    let columns = compute(py, || {
        let mut columns = vec![Vec::new(); params + 2];
        for target in targets.rows::<D>() {
            object.closest_to(target)?.push_into(&mut columns);
        }
        Ok(columns)
    })?;
    let layers = <T::Nearest as Nearest>::LAYERS;
    let point: Vec<usize> = layers.iter().copied().chain([D]).collect();
    let arrays = columns
        .into_iter()
        .enumerate()
        .map(|(k, values)| {
            let inner = if k == params { &point[..] } else { layers };
            targets.pack(py, values, inner)
        })
        .collect::<PyResult<Vec<_>>>()?;
    items(arrays)
}

/// `N` results as a tuple's items.
fn items<'py, const N: usize>(values: Vec<Obj<'py>>) -> PyResult<[Obj<'py>; N]> {
    values.try_into().map_err(|v: Vec<_>| {
        internal_error(&format!("{} results where {N} were expected", v.len()))
    })
}
