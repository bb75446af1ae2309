//! The box of cut control points `K_m(alpha)`: every coordinate of every
//! control point anywhere in its cut under one membership function at one
//! level (docs/method.md §11).

use crate::fuzzy::{Alpha, Membership, Nt2Point};

/// The box `K_m(alpha) = Π over i, c of [lo_ic, hi_ic]`, as one variable per
/// coordinate of each control point, flattened: variable `i·D + c`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CutBox {
    /// The dimension `D`.
    pub(crate) dim: usize,
    /// The left cut ends.
    pub(crate) lo: Vec<f64>,
    /// The right cut ends.
    pub(crate) hi: Vec<f64>,
    /// The crisp values (inside every cut).
    pub(crate) crisp: Vec<f64>,
}

impl CutBox {
    /// The box of `points` under `membership` at `alpha`; `None` where a
    /// number has no cut there (the lower function above its height).
    pub(crate) fn of<const D: usize>(
        points: &[Nt2Point<D>],
        membership: Membership,
        alpha: Alpha,
    ) -> Option<Self> {
        let n = points.len() * D;
        let (mut lo, mut hi, mut crisp) = (
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
        );
        for p in points {
            for x in p.coords() {
                let cut = x.alpha_cut(alpha);
                let interval = match membership {
                    Membership::Upper => cut.upper(),
                    Membership::Primary => cut.primary(),
                    Membership::Lower => cut.lower()?,
                };
                // The cut holds the crisp value exactly, also after rounding.
                let c = x.crisp();
                lo.push(interval.left().min(c));
                hi.push(interval.right().max(c));
                crisp.push(c);
            }
        }
        Some(CutBox {
            dim: D,
            lo,
            hi,
            crisp,
        })
    }

    /// The variables whose cut has a width (`lo < hi`).
    pub(crate) fn free(&self) -> Vec<usize> {
        (0..self.lo.len())
            .filter(|&v| self.lo[v] < self.hi[v])
            .collect()
    }

    /// The largest magnitude of a value in the box (at least the smallest
    /// normal float): the scale of rounding errors.
    pub(crate) fn magnitude(&self) -> f64 {
        self.lo
            .iter()
            .chain(&self.hi)
            .fold(f64::MIN_POSITIVE, |m, x| m.max(x.abs()))
    }
}
