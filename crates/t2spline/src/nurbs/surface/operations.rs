//! The curve operations of a surface, in either direction: isoparametric
//! curves, knot insertion and refinement, degree elevation and splitting.
//!
//! Every operation of The NURBS Book on a surface in the direction u acts on
//! each column of the net as the curve operation on its control points, with
//! the same coefficients for every column (§5.2–5.5: A5.3 inserts "for each
//! row/column", A5.5 refines likewise). The curve algorithms here already take
//! homogeneous rows of any width (`nurbs/homogeneous.rs`), so a line of the net
//! across `direction` is stacked into one row — for u, row `i` of the net is
//! the row `(wᵢ₀Pᵢ₀, wᵢ₀, wᵢ₁Pᵢ₁, wᵢ₁, …)` of width `nv·(D + 1)` — the curve
//! algorithm runs once on those rows with the knots of `direction`, and the
//! result is unstacked. So no algorithm is written twice, and the fuzzy
//! surfaces (`pipeline/fuzzy_surface.rs`) stack their seven layers into the
//! same rows.

use super::tensor_product::NurbsSurface;
use crate::error::Error;
use crate::nurbs::basis::basis_functions;
use crate::nurbs::degree_elevation::{check_elevation, elevate};
use crate::nurbs::homogeneous::{check_rows, from_rows, to_rows, Row};
use crate::nurbs::knot_insertion::{insert, refine};
use crate::nurbs::split::segment;
use crate::nurbs::{KnotVector, NurbsCurve};
use crate::place::Direction;

/// The knots `[U, V]` and the homogeneous rows of a net, row by row
/// (`rows[i·nv + j]`, each of the same width).
pub(crate) type RowNet = ([KnotVector; 2], Vec<Row>);

/// The lines of a net across `direction`, each stacked into one row: for `U`
/// the `nu` rows `(row(i, 0), row(i, 1), …)`, for `V` the `nv` rows
/// `(row(0, j), row(1, j), …)`.
fn stack(rows: &[Row], shape: [usize; 2], direction: Direction) -> Vec<Row> {
    let [nu, nv] = shape;
    match direction {
        Direction::U => (0..nu)
            .map(|i| rows[i * nv..(i + 1) * nv].concat())
            .collect(),
        Direction::V => (0..nv)
            .map(|j| {
                (0..nu)
                    .flat_map(|i| rows[i * nv + j].iter().copied())
                    .collect()
            })
            .collect(),
    }
}

/// The net back from lines stacked across `direction` (see [`stack`]), each
/// holding `other` entries of `width` values; row by row.
fn unstack(stacked: &[Row], other: usize, width: usize, direction: Direction) -> Vec<Row> {
    let entry = |line: &Row, k: usize| line[k * width..(k + 1) * width].to_vec();
    match direction {
        Direction::U => stacked
            .iter()
            .flat_map(|line| (0..other).map(move |k| entry(line, k)))
            .collect(),
        Direction::V => (0..other)
            .flat_map(|i| stacked.iter().map(move |line| entry(line, i)))
            .collect(),
    }
}

/// Runs a curve operation on the lines of a net across `direction` (see the
/// module's documentation) and returns the new net; an error of the
/// operation names the direction.
pub(crate) fn map_net(
    (knots, rows): (&[KnotVector; 2], &[Row]),
    direction: Direction,
    op: impl FnOnce(&KnotVector, &[Row]) -> Result<(KnotVector, Vec<Row>), Error>,
) -> Result<RowNet, Error> {
    let d = direction.index();
    let shape = knots.each_ref().map(KnotVector::count);
    let width = rows.first().map_or(0, Vec::len);
    let stacked = stack(rows, shape, direction);
    let (new, stacked) = op(&knots[d], &stacked).map_err(|e| e.in_direction(direction))?;
    let mut knots = knots.clone();
    knots[d] = new;
    let rows = unstack(&stacked, shape[1 - d], width, direction);
    Ok((knots, rows))
}

/// The homogeneous control points of the isoparametric curve at `t` in
/// `direction`: `Qʷₖ = Σᵢ Nᵢ(t) Pʷᵢₖ` over the lines across `direction`
/// (The NURBS Book §4.5); the curve runs in the other direction.
pub(crate) fn isocurve_rows(
    (knots, rows): (&[KnotVector; 2], &[Row]),
    direction: Direction,
    t: f64,
) -> Vec<Row> {
    let d = direction.index();
    let shape = knots.each_ref().map(KnotVector::count);
    let width = rows.first().map_or(0, Vec::len);
    let stacked = stack(rows, shape, direction);
    let k = &knots[d];
    let p = k.degree();
    let span = k.find_span(t);
    let mut n = vec![0.0; p + 1];
    basis_functions(k.as_slice(), p, span, t, &mut n);
    let mut line = vec![0.0; stacked[0].len()];
    for (c, row) in n.iter().zip(&stacked[span - p..]) {
        for (o, x) in line.iter_mut().zip(row) {
            *o += c * x;
        }
    }
    unstack(&[line], shape[1 - d], width, Direction::U)
}

/// Checks `a < b`, both in the domain of `knots`, for a piece in `direction`.
fn check_piece(knots: &KnotVector, [a, b]: [f64; 2], direction: Direction) -> Result<(), Error> {
    let domain = knots.domain();
    let check = || {
        domain.check(a)?;
        domain.check(b)?;
        if a >= b {
            return Err(Error::SplitOutside {
                t: b,
                start: a,
                end: domain.end,
            });
        }
        Ok(())
    };
    check().map_err(|e| e.in_direction(direction))
}

/// The piece of a net over `[u₀, u₁] × [v₀, v₁]`, clamped in both directions.
///
/// # Errors
/// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] or
/// [`Error::SplitOutside`] for a bad range.
pub(crate) fn segment_net(
    (knots, rows): (&[KnotVector; 2], &[Row]),
    u: [f64; 2],
    v: [f64; 2],
) -> Result<RowNet, Error> {
    for (direction, range) in Direction::BOTH.into_iter().zip([u, v]) {
        check_piece(&knots[direction.index()], range, direction)?;
    }
    let net = map_net((knots, rows), Direction::U, |k, r| {
        segment(k, r, u[0], u[1])
    })?;
    map_net((&net.0, &net.1), Direction::V, |k, r| {
        segment(k, r, v[0], v[1])
    })
}

/// The two nets of a net split at `t` in `direction`.
pub(crate) fn split_net(
    net: (&[KnotVector; 2], &[Row]),
    direction: Direction,
    t: f64,
) -> Result<[RowNet; 2], Error> {
    let d = net.0[direction.index()].domain();
    if !(d.start < t && t < d.end) {
        return Err(Error::SplitOutside {
            t,
            start: d.start,
            end: d.end,
        }
        .in_direction(direction));
    }
    Ok([
        map_net(net, direction, |k, r| segment(k, r, d.start, t))?,
        map_net(net, direction, |k, r| segment(k, r, t, d.end))?,
    ])
}

impl<const D: usize> NurbsSurface<D> {
    /// The homogeneous control points, row by row.
    pub(crate) fn rows(&self) -> Vec<Row> {
        to_rows(self.control_points(), self.weights())
    }

    /// A surface from a net of homogeneous rows that `operation` derived from
    /// a valid surface.
    ///
    /// # Errors
    /// [`Error::IllConditioned`] if the rows are outside the input ranges
    /// (see `nurbs/homogeneous.rs::check_rows`).
    fn try_from_net((knots, rows): RowNet, operation: &'static str) -> Result<Self, Error> {
        check_rows(&rows, operation)?;
        let (points, weights) = from_rows(&rows);
        Ok(Self::from_parts_unchecked(points, weights, knots))
    }

    /// Runs a curve operation in `direction` on this surface's net.
    fn map(
        &self,
        direction: Direction,
        operation: &'static str,
        op: impl FnOnce(&KnotVector, &[Row]) -> Result<(KnotVector, Vec<Row>), Error>,
    ) -> Result<Self, Error> {
        let rows = self.rows();
        Self::try_from_net(map_net((&self.knots, &rows), direction, op)?, operation)
    }

    /// The isoparametric curve at `t` in `direction`: for [`Direction::U`] the
    /// curve `v ↦ S(t, v)` (degree q, knots V), for [`Direction::V`] the curve
    /// `u ↦ S(u, t)`. Its homogeneous control points are
    /// `Qʷⱼ = Σᵢ Nᵢ,ₚ(t) Pʷᵢⱼ` (The NURBS Book §4.5), so it equals the surface
    /// exactly (at a knot of full multiplicity, the piece to the right of `t`).
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] if `t` is
    /// outside the domain of `direction`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Direction, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]])?;
    /// let c = s.isocurve(Direction::U, 0.25)?; // v ↦ S(0.25, v)
    /// let (a, b) = (c.eval(0.6)?, s.eval(0.25, 0.6)?);
    /// assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn isocurve(&self, direction: Direction, t: f64) -> Result<NurbsCurve<D>, Error> {
        self.domain(direction)
            .check(t)
            .map_err(|e| e.in_direction(direction))?;
        let rows = isocurve_rows((&self.knots, &self.rows()), direction, t);
        let knots = self.knots(direction.other()).clone();
        Ok(NurbsCurve::from_rows(knots, &rows))
    }

    /// The same surface with the knot `t` inserted `times` times in
    /// `direction` (The NURBS Book A5.1 on every line of the net, as A5.3).
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] or
    /// [`Error::KnotInsertion`], as [`NurbsCurve::insert_knot`].
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Direction, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]])?;
    /// let r = s.insert_knot(Direction::V, 0.5, 1)?;
    /// assert_eq!(r.shape(), [2, 3]);
    /// let (a, b) = (s.eval(0.3, 0.8)?, r.eval(0.3, 0.8)?);
    /// assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn insert_knot(&self, direction: Direction, t: f64, times: usize) -> Result<Self, Error> {
        self.map(direction, "knot insertion", |k, r| insert(k, r, t, times))
    }

    /// The same surface with all knots of `new` inserted in `direction` (knot
    /// refinement, A5.4 on every line of the net, as A5.5).
    ///
    /// # Errors
    /// As [`NurbsSurface::insert_knot`].
    pub fn refine_knots(&self, direction: Direction, new: &[f64]) -> Result<Self, Error> {
        self.map(direction, "knot refinement", |k, r| refine(k, r, new))
    }

    /// The same surface with its degree in `direction` raised by `times`
    /// (A5.9 on every line of the net); an unclamped direction comes back
    /// clamped with the same domain. Accuracy as
    /// [`NurbsCurve::elevate_degree`].
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfRange`] if the new degree
    /// would exceed [`MAX_ELEVATED_DEGREE`](crate::nurbs::MAX_ELEVATED_DEGREE)
    /// or the degree is 0; [`Error::IllConditioned`] as for curves.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Direction, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]])?;
    /// let e = s.elevate_degree(Direction::U, 2)?;
    /// assert_eq!((e.degree(), e.shape()), ([3, 1], [4, 2]));
    /// let (a, b) = (s.eval(0.3, 0.8)?, e.eval(0.3, 0.8)?);
    /// assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn elevate_degree(&self, direction: Direction, times: usize) -> Result<Self, Error> {
        check_elevation(self.degree()[direction.index()], times)
            .map_err(|e| e.in_direction(direction))?;
        self.map(direction, "degree elevation", |k, r| {
            Ok(elevate(k, r, times))
        })
    }

    /// The two surfaces on either side of `t` in `direction` (The NURBS Book
    /// §5.3 on every line of the net): for `U` the pieces over
    /// `[a, t] × [c, d]` and `[t, b] × [c, d]`. Both keep the parameters and
    /// are clamped in `direction`; at a knot of full multiplicity the first
    /// piece ends with the left limit.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::SplitOutside`] unless `t` lies
    /// strictly inside the domain of `direction`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Direction, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]])?;
    /// let [low, high] = s.split_at(Direction::U, 0.4)?;
    /// assert_eq!((low.domain(Direction::U).end, high.domain(Direction::U).start), (0.4, 0.4));
    /// let (a, b) = (s.eval(0.7, 0.2)?, high.eval(0.7, 0.2)?);
    /// assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn split_at(&self, direction: Direction, t: f64) -> Result<[Self; 2], Error> {
        let rows = self.rows();
        let [a, b] = split_net((&self.knots, &rows), direction, t)?;
        Ok([
            Self::try_from_net(a, "splitting")?,
            Self::try_from_net(b, "splitting")?,
        ])
    }

    /// The piece of the surface over the rectangle `[u₀, u₁] × [v₀, v₁]` of
    /// its domain, clamped in both directions, with the same parameters.
    ///
    /// # Errors
    /// [`Error::InDirection`] wrapping [`Error::OutOfDomain`] for an end
    /// outside the domain and [`Error::SplitOutside`] unless `u₀ < u₁` and
    /// `v₀ < v₁`.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::{Direction, NurbsSurface};
    /// let net = vec![vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], vec![[1.0, 0.0, 0.0], [1.0, 1.0, 1.0]]];
    /// let s = NurbsSurface::try_clamped([1, 1], net, vec![vec![1.0, 2.0], vec![1.0, 1.0]])?;
    /// let piece = s.segment([0.2, 0.6], [0.5, 1.0])?;
    /// assert_eq!(piece.domain(Direction::V).start, 0.5);
    /// let (a, b) = (s.eval(0.3, 0.7)?, piece.eval(0.3, 0.7)?);
    /// assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-15));
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn segment(&self, u: [f64; 2], v: [f64; 2]) -> Result<Self, Error> {
        let net = segment_net((&self.knots, &self.rows()), u, v)?;
        Self::try_from_net(net, "splitting")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stacking_and_unstacking_are_inverse_in_both_directions() {
        let rows: Vec<Row> = (0..6).map(|k| vec![k as f64, 10.0 + k as f64]).collect();
        let shape = [2, 3];
        let u = stack(&rows, shape, Direction::U);
        assert_eq!(u[1], vec![3.0, 13.0, 4.0, 14.0, 5.0, 15.0]);
        assert_eq!(unstack(&u, 3, 2, Direction::U), rows);
        let v = stack(&rows, shape, Direction::V);
        assert_eq!(v[2], vec![2.0, 12.0, 5.0, 15.0]);
        assert_eq!(unstack(&v, 2, 2, Direction::V), rows);
    }
}
