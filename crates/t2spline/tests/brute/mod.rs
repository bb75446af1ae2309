//! What the brute-force checks of surface measures share
//! (`surface_measure.rs`, `cut_fill.rs`): a Gauss rule of 4 × 4 nodes on
//! each of `cells × cells` cells of every span rectangle of a surface.

use t2spline::{Direction, NurbsSurface};

/// The 4-point Gauss–Legendre rule on [−1, 1]: nodes and weights.
const GAUSS_4: ([f64; 4], [f64; 4]) = (
    [
        -0.861_136_311_594_052_6,
        -0.339_981_043_584_856_3,
        0.339_981_043_584_856_3,
        0.861_136_311_594_052_6,
    ],
    [
        0.347_854_845_137_453_9,
        0.652_145_154_862_546_1,
        0.652_145_154_862_546_1,
        0.347_854_845_137_453_9,
    ],
);

/// `f(u, v, w)` at every node of the rule over `s`'s parameter domain, `w`
/// the node's weight in `du dv`: the sum of `w·g(u, v)` is `∫∫ g du dv`.
pub fn gauss_cells(s: &NurbsSurface<3>, cells: usize, mut f: impl FnMut(f64, f64, f64)) {
    let (nodes, weights) = GAUSS_4;
    let spans = |d: Direction| -> Vec<[f64; 2]> { s.knots(d).spans().map(|(_, r)| r).collect() };
    for [u0, u1] in spans(Direction::U) {
        for [v0, v1] in spans(Direction::V) {
            let (hu, hv) = ((u1 - u0) / cells as f64, (v1 - v0) / cells as f64);
            for a in 0..cells {
                for b in 0..cells {
                    for (x, wx) in nodes.iter().zip(&weights) {
                        for (y, wy) in nodes.iter().zip(&weights) {
                            let u = u0 + hu * (a as f64 + 0.5 * (x + 1.0));
                            let v = v0 + hv * (b as f64 + 0.5 * (y + 1.0));
                            f(u, v, 0.25 * wx * wy * hu * hv);
                        }
                    }
                }
            }
        }
    }
}
