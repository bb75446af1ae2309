//! What the terrain tests share (`contour.rs`, `envelope.rs`,
//! `surface_measure.rs`): the cut of a height under one membership
//! function, the crisp net with every height picked from its cut, and the
//! node positions of random spacings.

use t2spline::{Alpha, Direction, FuzzySurface, Interval, Membership, Nt2Number, NurbsSurface};

/// The cut of `z` at level `a` under function `m`; `None` where the lower
/// function has no cut.
pub fn cut(z: &Nt2Number, m: Membership, a: Alpha) -> Option<Interval> {
    let c = z.alpha_cut(a);
    match m {
        Membership::Upper => Some(c.upper()),
        Membership::Primary => Some(c.primary()),
        Membership::Lower => c.lower(),
    }
}

/// The crisp surface of the net with heights `pick(cut)` and the plan's
/// crisp x and y; `None` where a height has no cut.
pub fn net(
    s: &FuzzySurface<3>,
    m: Membership,
    a: Alpha,
    mut pick: impl FnMut(Interval) -> f64,
) -> Option<NurbsSurface<3>> {
    let [nu, nv] = s.shape();
    let mut rows = Vec::with_capacity(nu);
    for i in 0..nu {
        let mut row = Vec::with_capacity(nv);
        for j in 0..nv {
            let [x, y, z] = s.points()[i * nv + j].coords();
            row.push([x.crisp(), y.crisp(), pick(cut(z, m, a)?)]);
        }
        rows.push(row);
    }
    let weights = s.weights().chunks(nv).map(<[f64]>::to_vec).collect();
    let knots = [s.knots(Direction::U).clone(), s.knots(Direction::V).clone()];
    Some(NurbsSurface::try_new(rows, weights, knots).expect("a valid net"))
}

/// The running sums of `spacings`: node positions along one axis.
pub fn cumulative(spacings: &[f64]) -> Vec<f64> {
    spacings
        .iter()
        .scan(0.0, |s, x| {
            *s += x;
            Some(*s)
        })
        .collect()
}
