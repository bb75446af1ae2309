//! The plan of a fuzzy surface with crisp x and y (docs/method.md §14): the
//! rational tensor basis and its first partial derivatives on a span
//! rectangle, the plan map's Jacobian, and the check that the surface is the
//! graph of a height over its plan.
//!
//! With `W = Σ wₖNᵢ(u)Mⱼ(v)` (`k = i·nv + j`) and `Rₖ = wₖNᵢMⱼ/W`:
//!
//! ```text
//! Rₖ,u = (wₖNᵢ'Mⱼ − Rₖ·W_u)/W,   Rₖ,v = (wₖNᵢMⱼ' − Rₖ·W_v)/W
//! J(u, v) = x_u·y_v − x_v·y_u,   x_u = Σ Rₖ,u·xₖ, …
//! ```
//! The plan map `(u, v) ↦ (x, y)` is the same for every admissible net (x
//! and y crisp). The surface is a graph `z = f(x, y)` over its plan where
//! the plan map is one to one; `J` keeping one sign says so locally, and is
//! checked at every node of a 16 × 16 Gauss rule and at the corners of every
//! span rectangle: a sign change (a fold) or a span rectangle where `J`
//! vanishes throughout (a vertical part) is refused, naming the place.

use crate::cubature::gauss_legendre;
use crate::error::Error;
use crate::nurbs::derivatives::basis_derivatives;
use crate::nurbs::{Direction, KnotVector};
use crate::pipeline::FuzzySurface;

/// The crisp plan of a surface: knots, weights, x and y of each point.
#[derive(Clone, Debug)]
pub(crate) struct Plan {
    pub(crate) knots: [KnotVector; 2],
    pub(crate) weights: Vec<f64>,
    pub(crate) xy: Vec<[f64; 2]>,
    /// Columns of the net (points along v).
    pub(crate) nv: usize,
    /// The non-empty span rectangles `[su, sv]` and their parameter ranges.
    pub(crate) spans: Vec<([usize; 2], [[f64; 2]; 2])>,
}

/// The basis of one direction at a parameter: first index, values, slopes.
#[derive(Clone, Debug)]
pub(crate) struct Basis1 {
    pub(crate) first: usize,
    pub(crate) n: Vec<f64>,
    pub(crate) d: Vec<f64>,
}

impl Basis1 {
    /// The B-spline functions of `knots` on `span` at `t`, with slopes.
    pub(crate) fn at(knots: &KnotVector, span: usize, t: f64) -> Self {
        let p = knots.degree();
        let mut b = basis_derivatives(knots.as_slice(), p, span, t, 1);
        let d = b.pop().unwrap_or_default();
        let n = b.pop().unwrap_or_default();
        Basis1 {
            first: span - p,
            n,
            d,
        }
    }
}

/// The rational basis and its partials at one parameter, for the
/// `(p + 1)(q + 1)` points of a span rectangle (`a·(q + 1) + b` is point
/// `(first[0] + a)·nv + first[1] + b`).
#[derive(Clone, Debug, Default)]
pub(crate) struct Local {
    pub(crate) first: [usize; 2],
    pub(crate) r: Vec<f64>,
    pub(crate) ru: Vec<f64>,
    pub(crate) rv: Vec<f64>,
    /// `[x_u, x_v, y_u, y_v]`.
    pub(crate) plan: [f64; 4],
    /// `q + 1`: local functions per row.
    pub(crate) columns: usize,
}

impl Local {
    /// The jacobian `x_u·y_v − x_v·y_u`.
    pub(crate) fn jacobian(&self) -> f64 {
        let [xu, xv, yu, yv] = self.plan;
        xu * yv - xv * yu
    }

    /// The index of each local function's control point.
    pub(crate) fn point(&self, nv: usize, local: usize) -> usize {
        (self.first[0] + local / self.columns) * nv + self.first[1] + local % self.columns
    }
}

impl Plan {
    /// The plan of `s`, or the first control point whose x or y is fuzzy.
    pub(crate) fn of(s: &FuzzySurface<3>) -> Result<Self, Error> {
        let nv = s.shape()[1];
        for (k, p) in s.points().iter().enumerate() {
            for (axis, c) in [crate::Axis::X, crate::Axis::Y]
                .into_iter()
                .zip(&p.coords()[..2])
            {
                if c.upper().width() != 0.0 {
                    return Err(Error::FuzzyPlan {
                        row: k / nv,
                        column: k % nv,
                        axis,
                    });
                }
            }
        }
        let knots = [s.knots(Direction::U).clone(), s.knots(Direction::V).clone()];
        let mut spans = Vec::new();
        for (su, ru) in knots[0].spans() {
            for (sv, rv) in knots[1].spans() {
                spans.push(([su, sv], [ru, rv]));
            }
        }
        Ok(Plan {
            weights: s.weights().to_vec(),
            xy: s
                .points()
                .iter()
                .map(|p| [p.coords()[0].crisp(), p.coords()[1].crisp()])
                .collect(),
            nv,
            knots,
            spans,
        })
    }

    /// `(p + 1, q + 1)`.
    pub(crate) fn orders(&self) -> [usize; 2] {
        [self.knots[0].degree() + 1, self.knots[1].degree() + 1]
    }

    /// The rational basis and its partials from the two directions' bases.
    pub(crate) fn local(&self, bu: &Basis1, bv: &Basis1) -> Local {
        let [ku, kv] = self.orders();
        let nv = self.nv;
        let count = ku * kv;
        let (mut r, mut ru, mut rv) = (vec![0.0; count], vec![0.0; count], vec![0.0; count]);
        let (mut w0, mut wu, mut wv) = (0.0, 0.0, 0.0);
        for a in 0..ku {
            for b in 0..kv {
                let k = (bu.first + a) * nv + bv.first + b;
                let w = self.weights[k];
                let l = a * kv + b;
                r[l] = w * bu.n[a] * bv.n[b];
                ru[l] = w * bu.d[a] * bv.n[b];
                rv[l] = w * bu.n[a] * bv.d[b];
                w0 += r[l];
                wu += ru[l];
                wv += rv[l];
            }
        }
        let mut plan = [0.0; 4];
        for l in 0..count {
            r[l] /= w0;
            ru[l] = (ru[l] - r[l] * wu) / w0;
            rv[l] = (rv[l] - r[l] * wv) / w0;
            let k = (bu.first + l / kv) * nv + bv.first + l % kv;
            let [x, y] = self.xy[k];
            plan[0] += ru[l] * x;
            plan[1] += rv[l] * x;
            plan[2] += ru[l] * y;
            plan[3] += rv[l] * y;
        }
        Local {
            first: [bu.first, bv.first],
            r,
            ru,
            rv,
            plan,
            columns: kv,
        }
    }

    /// The jacobian `x_u·y_v − x_v·y_u` from the two directions' bases,
    /// without the rational basis: with `X = Σ wₖNᵢMⱼxₖ` (and `Y`, `W`
    /// alike), `x_u = (X_u − x·W_u)/W`.
    pub(crate) fn jacobian(&self, bu: &Basis1, bv: &Basis1) -> f64 {
        let [ku, kv] = self.orders();
        // [W, X, Y] and their u- and v-slopes.
        let (mut s, mut su, mut sv) = ([0.0; 3], [0.0; 3], [0.0; 3]);
        for a in 0..ku {
            for b in 0..kv {
                let k = (bu.first + a) * self.nv + bv.first + b;
                let w = self.weights[k];
                let [x, y] = self.xy[k];
                let (n, nu, nv) = (bu.n[a] * bv.n[b], bu.d[a] * bv.n[b], bu.n[a] * bv.d[b]);
                for (out, f) in [(&mut s, n), (&mut su, nu), (&mut sv, nv)] {
                    out[0] += w * f;
                    out[1] += w * f * x;
                    out[2] += w * f * y;
                }
            }
        }
        let (x, y) = (s[1] / s[0], s[2] / s[0]);
        let (x_u, y_u) = ((su[1] - x * su[0]) / s[0], (su[2] - y * su[0]) / s[0]);
        let (x_v, y_v) = ((sv[1] - x * sv[0]) / s[0], (sv[2] - y * sv[0]) / s[0]);
        x_u * y_v - x_v * y_u
    }

    /// The local basis at `(u, v)` on the span rectangle `spans`.
    pub(crate) fn local_at(&self, [su, sv]: [usize; 2], u: f64, v: f64) -> Local {
        self.local(
            &Basis1::at(&self.knots[0], su, u),
            &Basis1::at(&self.knots[1], sv, v),
        )
    }

    /// The plan point `(x, y)` at a local basis.
    pub(crate) fn xy_of(&self, local: &Local) -> [f64; 2] {
        let mut p = [0.0; 2];
        for (l, r) in local.r.iter().enumerate() {
            let [x, y] = self.xy[local.point(self.nv, l)];
            p[0] += r * x;
            p[1] += r * y;
        }
        p
    }

    /// Refuses a plan map that folds or has a vertical part (module docs).
    pub(crate) fn check_graph(&self) -> Result<(), Error> {
        let (nodes, _) = gauss_legendre(16);
        let mut samples: Vec<f64> = nodes.iter().map(|x| 0.5 * (x + 1.0)).collect();
        samples.extend([0.0, 1.0]);
        // Per span: the extreme jacobians and where they are.
        let mut found: Vec<([f64; 2], [[f64; 2]; 2])> = Vec::new();
        let mut largest = 0.0_f64;
        for &(spans, [[u0, u1], [v0, v1]]) in &self.spans {
            let bv_row: Vec<(f64, Basis1)> = samples
                .iter()
                .map(|&t| {
                    let v = v0 + t * (v1 - v0);
                    (v, Basis1::at(&self.knots[1], spans[1], v))
                })
                .collect();
            let mut lo = (f64::INFINITY, [u0, v0]);
            let mut hi = (f64::NEG_INFINITY, [u0, v0]);
            for &s in &samples {
                let u = u0 + s * (u1 - u0);
                let bu = Basis1::at(&self.knots[0], spans[0], u);
                for (v, bv) in &bv_row {
                    let v = *v;
                    let j = self.jacobian(&bu, bv);
                    if j < lo.0 {
                        lo = (j, [u, v]);
                    }
                    if j > hi.0 {
                        hi = (j, [u, v]);
                    }
                }
            }
            largest = largest.max(lo.0.abs()).max(hi.0.abs());
            found.push(([lo.0, hi.0], [lo.1, hi.1]));
        }
        let tiny = 1e-12 * largest;
        let positive = found.iter().filter(|f| f.0[1] > tiny).count();
        let negative = found.iter().filter(|f| f.0[0] < -tiny).count();
        let place = |span: usize, uv: [f64; 2], rule: &'static str| {
            let (spans, _) = self.spans[span];
            let xy = self.xy_of(&self.local_at(spans, uv[0], uv[1]));
            Error::NotAGraph {
                u: uv[0],
                v: uv[1],
                x: xy[0],
                y: xy[1],
                rule,
            }
        };
        if positive > 0 && negative > 0 {
            // Name a place of the sign held by fewer span rectangles.
            let want_negative = negative <= positive;
            for (k, f) in found.iter().enumerate() {
                if want_negative && f.0[0] < -tiny {
                    return Err(place(k, f.1[0], FOLDS));
                }
                if !want_negative && f.0[1] > tiny {
                    return Err(place(k, f.1[1], FOLDS));
                }
            }
        }
        for (k, f) in found.iter().enumerate() {
            if f.0[0].abs().max(f.0[1].abs()) <= tiny {
                return Err(place(k, f.1[0], VERTICAL));
            }
        }
        Ok(())
    }
}

impl Plan {
    /// The first difference between two plans, `None` where they are one
    /// plan map: the net's shape, a degree, the knots, a weight, an x or a
    /// y (compared exactly; `other`'s value first).
    pub(crate) fn difference(&self, other: &Plan) -> Option<String> {
        let shape = |p: &Plan| [p.xy.len() / p.nv.max(1), p.nv];
        let [a, b] = [shape(other), shape(self)];
        if a != b {
            return Some(format!(
                "net shape: {} × {} control points, not {} × {}",
                a[0], a[1], b[0], b[1]
            ));
        }
        for (d, name) in ["u", "v"].into_iter().enumerate() {
            let [mine, theirs] = [&self.knots[d], &other.knots[d]];
            if mine.degree() != theirs.degree() {
                return Some(format!(
                    "degree in {name}: {}, not {}",
                    theirs.degree(),
                    mine.degree()
                ));
            }
            if mine.as_slice() != theirs.as_slice() {
                return Some(format!("knots in {name}"));
            }
        }
        let at = |k: usize| format!("points[{}][{}]", k / self.nv, k % self.nv);
        for k in 0..self.xy.len() {
            if self.weights[k] != other.weights[k] {
                return Some(format!(
                    "weight of {}: {}, not {}",
                    at(k),
                    other.weights[k],
                    self.weights[k]
                ));
            }
            for (c, axis) in ["x", "y"].into_iter().enumerate() {
                if self.xy[k][c] != other.xy[k][c] {
                    return Some(format!(
                        "{axis} of {}: {}, not {}",
                        at(k),
                        other.xy[k][c],
                        self.xy[k][c]
                    ));
                }
            }
        }
        None
    }
}

const FOLDS: &str = "the plan map folds there (its Jacobian changes sign)";
const VERTICAL: &str =
    "the surface is vertical there (the plan map's Jacobian vanishes on a whole span rectangle)";
