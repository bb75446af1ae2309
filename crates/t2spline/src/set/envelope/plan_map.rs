//! Where the plan map of a surface with crisp x and y takes a plan point:
//! the parameters `(u, v)` with `(x(u, v), y(u, v)) = (x0, y0)`.
//!
//! With crisp x and y every admissible net has the same plan map
//!
//! ```text
//! (u, v) ↦ (x(u, v), y(u, v)) = Σᵢⱼ Rᵢⱼ(u, v)·(xᵢⱼ, yᵢⱼ)
//! ```
//! so it is inverted once per plan point, for every level and function.
//!
//! **Separable maps** (the fast path). Where `xᵢⱼ = aᵢ` does not depend on
//! `j`, `yᵢⱼ = bⱼ` not on `i` (or the two the other way round) and the
//! weights are a product `wᵢⱼ·w₀₀ = wᵢ₀·w₀ⱼ`, the basis is a product,
//! `Rᵢⱼ(u, v) = Rᵢ(u)·Rⱼ(v)`, and the map is two functions of one variable,
//! `x(u) = Σ Rᵢ(u)·aᵢ` and `y(v) = Σ Rⱼ(v)·bⱼ` (a regular net of stations,
//! as a terrain's). With strictly monotone `aᵢ` such a function takes each
//! value `c` at most once: `x(u) − c` has the sign of `Σ αᵢ Nᵢ(u)·(aᵢ − c)`,
//! a B-spline function with at most one sign change in its coefficients, and
//! a B-spline function changes sign no more often than its coefficients do
//! (variation diminishing, The NURBS Book §2.2, Schoenberg); so each column and each row of a grid is inverted by
//! bisection, to the last bit: `nx + ny` inversions for `nx·ny` cells. A
//! net that is separable only to within `1e-9` of the plan's size (a fitted
//! net of regular stations, whose x wander by rounding along a row) is
//! inverted so for a start, from which Newton's method (below) solves the
//! true map at each cell.
//!
//! **Any other map**: the map is tabulated on 8 × 8 parameters per span
//! rectangle; every plan point is looked up among the table's quadrilaterals
//! (in buckets over the plan extent) and Newton's method is run from the
//! centre of each quadrilateral whose box, widened by half its size, holds
//! the point. Every parameter where the residual falls below `1e-12` of the
//! plan's size counts, so a map that folds gives every layer found.

use crate::nurbs::basis::basis_functions;
use crate::nurbs::{Direction, KnotVector, NurbsSurface};

/// Steps of the table per span, in each direction.
const TABLE_STEPS: usize = 8;
/// Table nodes per direction at most.
const MAX_TABLE_NODES: usize = 1025;
/// Newton steps per start.
const NEWTON_STEPS: usize = 40;
/// Preimages kept per plan point at most.
const MAX_PREIMAGES: usize = 8;
/// The residual, relative to the plan's size, below which Newton's method
/// has found the point.
const RESIDUAL: f64 = 1e-12;

/// A function of one parameter `f(t) = Σ αₖ Nₖ(t)·cₖ / Σ αₖ Nₖ(t)`: the plan
/// map of a separable net along one direction.
pub(crate) struct Axis1 {
    pub(crate) knots: KnotVector,
    /// The weights `αₖ` along this direction.
    pub(crate) weights: Vec<f64>,
    /// The coordinates `cₖ`, strictly monotone.
    values: Vec<f64>,
}

impl Axis1 {
    /// The rational basis at `t`: its first index and the `p + 1` values.
    pub(crate) fn basis(&self, t: f64, out: &mut [f64]) -> usize {
        let p = self.knots.degree();
        let span = self.knots.find_span(t);
        basis_functions(self.knots.as_slice(), p, span, t, out);
        let first = span - p;
        let mut sum = 0.0;
        for (b, w) in out.iter_mut().zip(&self.weights[first..]) {
            *b *= w;
            sum += *b;
        }
        // Some Nₖ(t) ≥ 1/(p + 1) and every weight is positive.
        for b in out.iter_mut() {
            *b /= sum;
        }
        first
    }

    /// `f(t)`.
    fn eval(&self, t: f64, scratch: &mut [f64]) -> f64 {
        let first = self.basis(t, scratch);
        scratch
            .iter()
            .zip(&self.values[first..])
            .map(|(b, c)| b * c)
            .sum()
    }

    /// The parameter where `f` takes `target`, by bisection to adjacent
    /// floats; `None` outside the range of `f` or where `f` jumps over it
    /// (degree 0).
    pub(crate) fn invert(&self, target: f64) -> Option<f64> {
        let mut scratch = vec![0.0; self.knots.degree() + 1];
        let d = self.knots.domain();
        let (mut a, mut b) = (d.start, d.end);
        let (fa, fb) = (self.eval(a, &mut scratch), self.eval(b, &mut scratch));
        let increasing = fa <= fb;
        let (lo, hi) = if increasing { (fa, fb) } else { (fb, fa) };
        if !(lo <= target && target <= hi) {
            return None;
        }
        // Invariant: f(a) is on the low side of target (in the direction of
        // increase), f(b) on the high side.
        for _ in 0..2100 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            let below = self.eval(m, &mut scratch) < target;
            if below == increasing {
                a = m;
            } else {
                b = m;
            }
        }
        let (ea, eb) = (
            (self.eval(a, &mut scratch) - target).abs(),
            (self.eval(b, &mut scratch) - target).abs(),
        );
        let (t, e) = if ea <= eb { (a, ea) } else { (b, eb) };
        // A jump (degree 0) is bisected to its place but not closed.
        (e <= RESIDUAL * (hi - lo).max(target.abs() * f64::EPSILON)).then_some(t)
    }
}

/// A separable plan map: x along one direction, y along the other.
pub(crate) struct Separable {
    /// Whether x runs along u (and y along v); else x along v, y along u.
    pub(crate) x_along_u: bool,
    /// Whether the net is separable exactly; else within `1e-9` of the plan.
    pub(crate) exact: bool,
    /// The map of u and of v.
    pub(crate) axes: [Axis1; 2],
}

impl Separable {
    /// The separable form of the plan map of `s`, if it has one with strictly
    /// monotone coordinates: exactly (`exact`), or with each coordinate
    /// within `1e-9` of the plan's size of its row's or column's mean (a
    /// fitted net of regular stations, whose rounding moves x along a row),
    /// a map whose inversion is a start for Newton's method on the true map.
    pub(crate) fn of(s: &NurbsSurface<3>) -> Option<Separable> {
        let [nu, nv] = s.shape();
        let (pts, w) = (s.control_points(), s.weights());
        let at = |i: usize, j: usize| pts[i * nv + j];
        let mut b = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in pts {
            b = [
                b[0].min(p[0]),
                b[1].max(p[0]),
                b[2].min(p[1]),
                b[3].max(p[1]),
            ];
        }
        let slack = 1e-9 * (b[1] - b[0]).max(b[3] - b[2]);
        let w00 = w[0];
        let product = (0..nu).all(|i| {
            (0..nv).all(|j| {
                let (l, r) = (w[i * nv + j] * w00, w[i * nv] * w[j]);
                (l - r).abs() <= 1e-13 * l.abs().max(r.abs())
            })
        });
        if !product {
            return None;
        }
        // Coordinate c constant along v (a function of i only), or along u,
        // to within `tol`.
        let along_u = |c: usize, tol: f64| {
            (0..nu).all(|i| (0..nv).all(|j| (at(i, j)[c] - at(i, 0)[c]).abs() <= tol))
        };
        let along_v = |c: usize, tol: f64| {
            (0..nu).all(|i| (0..nv).all(|j| (at(i, j)[c] - at(0, j)[c]).abs() <= tol))
        };
        let layout = |tol: f64| {
            if along_u(0, tol) && along_v(1, tol) {
                Some(true)
            } else if along_v(0, tol) && along_u(1, tol) {
                Some(false)
            } else {
                None
            }
        };
        let (x_along_u, exact) = match (layout(0.0), layout(slack)) {
            (Some(x), _) => (x, true),
            (None, Some(x)) => (x, false),
            (None, None) => return None,
        };
        let (cu, cv) = if x_along_u { (0, 1) } else { (1, 0) };
        let u_values: Vec<f64> = (0..nu)
            .map(|i| (0..nv).map(|j| at(i, j)[cu]).sum::<f64>() / nv as f64)
            .collect();
        let v_values: Vec<f64> = (0..nv)
            .map(|j| (0..nu).map(|i| at(i, j)[cv]).sum::<f64>() / nu as f64)
            .collect();
        if !strictly_monotone(&u_values) || !strictly_monotone(&v_values) {
            return None;
        }
        let axes = [
            Axis1 {
                knots: s.knots(Direction::U).clone(),
                weights: (0..nu).map(|i| w[i * nv]).collect(),
                values: u_values,
            },
            Axis1 {
                knots: s.knots(Direction::V).clone(),
                weights: w[..nv].to_vec(),
                values: v_values,
            },
        ];
        Some(Separable {
            x_along_u,
            exact,
            axes,
        })
    }
}

/// Whether `values` strictly increase or strictly decrease.
fn strictly_monotone(values: &[f64]) -> bool {
    values.windows(2).all(|w| w[0] < w[1]) || values.windows(2).all(|w| w[0] > w[1])
}

/// The tabulated plan map of any surface, for Newton's method.
pub(crate) struct Table<'a> {
    surface: &'a NurbsSurface<3>,
    /// Table parameters along u and v.
    tu: Vec<f64>,
    tv: Vec<f64>,
    /// Per quadrilateral (row-major over `tu × tv` cells), its box widened
    /// by half its size: `[x0, x1, y0, y1]`.
    boxes: Vec<[f64; 4]>,
    /// The plan extent and the bucket grid over it.
    extent: [f64; 4],
    buckets: [usize; 2],
    /// Per bucket, the quadrilaterals whose widened box meets it.
    members: Vec<Vec<u32>>,
    size: f64,
}

/// The parameters of one direction's table: `TABLE_STEPS` per span.
fn table_parameters(knots: &KnotVector) -> Vec<f64> {
    let spans: Vec<[f64; 2]> = knots.spans().map(|(_, r)| r).collect();
    let steps = (MAX_TABLE_NODES / spans.len().max(1)).clamp(1, TABLE_STEPS);
    let mut out = Vec::with_capacity(spans.len() * steps + 1);
    for [a, b] in &spans {
        for k in 0..steps {
            out.push(a + (b - a) * k as f64 / steps as f64);
        }
    }
    out.push(knots.domain().end);
    out
}

impl<'a> Table<'a> {
    /// The table of the plan map of `surface`.
    pub(crate) fn new(surface: &'a NurbsSurface<3>) -> Self {
        let tu = table_parameters(surface.knots(Direction::U));
        let tv = table_parameters(surface.knots(Direction::V));
        let nodes: Vec<[f64; 2]> = tu
            .iter()
            .flat_map(|&u| tv.iter().map(move |&v| (u, v)))
            .map(|(u, v)| {
                let p = surface.eval_unchecked(u, v);
                [p[0], p[1]]
            })
            .collect();
        let nv = tv.len();
        let mut boxes = Vec::with_capacity((tu.len() - 1) * (nv - 1));
        let mut extent = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for i in 0..tu.len() - 1 {
            for j in 0..nv - 1 {
                let mut b = [
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                ];
                for (a, c) in [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)] {
                    let p = nodes[a * nv + c];
                    b = [
                        b[0].min(p[0]),
                        b[1].max(p[0]),
                        b[2].min(p[1]),
                        b[3].max(p[1]),
                    ];
                }
                let (hx, hy) = (0.5 * (b[1] - b[0]), 0.5 * (b[3] - b[2]));
                let h = hx.max(hy);
                let b = [b[0] - h, b[1] + h, b[2] - h, b[3] + h];
                extent = [
                    extent[0].min(b[0]),
                    extent[1].max(b[1]),
                    extent[2].min(b[2]),
                    extent[3].max(b[3]),
                ];
                boxes.push(b);
            }
        }
        let size = (extent[1] - extent[0])
            .max(extent[3] - extent[2])
            .max(f64::MIN_POSITIVE);
        let side = ((boxes.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let buckets = [side, side];
        let mut members = vec![Vec::new(); side * side];
        let table = |lo: f64, hi: f64, e0: f64, e1: f64| {
            let f = |x: f64| (((x - e0) / (e1 - e0).max(f64::MIN_POSITIVE)) * side as f64).floor();
            let a = f(lo).clamp(0.0, (side - 1) as f64) as usize;
            let b = f(hi).clamp(0.0, (side - 1) as f64) as usize;
            a..=b
        };
        for (k, b) in boxes.iter().enumerate() {
            for bx in table(b[0], b[1], extent[0], extent[1]) {
                for by in table(b[2], b[3], extent[2], extent[3]) {
                    members[by * side + bx].push(k as u32);
                }
            }
        }
        Table {
            surface,
            tu,
            tv,
            boxes,
            extent,
            buckets,
            members,
            size,
        }
    }

    /// Every parameter found where the plan map takes `(x0, y0)` (none
    /// outside the plan extent).
    pub(crate) fn preimages(&self, [x0, y0]: [f64; 2]) -> Vec<[f64; 2]> {
        let e = self.extent;
        if !(e[0] <= x0 && x0 <= e[1] && e[2] <= y0 && y0 <= e[3]) {
            return Vec::new();
        }
        let [sx, sy] = self.buckets;
        let cell = |x: f64, a: f64, b: f64, n: usize| {
            (((x - a) / (b - a).max(f64::MIN_POSITIVE)) * n as f64)
                .floor()
                .clamp(0.0, (n - 1) as f64) as usize
        };
        let (bx, by) = (cell(x0, e[0], e[1], sx), cell(y0, e[2], e[3], sy));
        let nv = self.tv.len() - 1;
        let mut found: Vec<[f64; 2]> = Vec::new();
        for &k in &self.members[by * sx + bx] {
            let k = k as usize;
            let b = self.boxes[k];
            if !(b[0] <= x0 && x0 <= b[1] && b[2] <= y0 && y0 <= b[3]) {
                continue;
            }
            let (i, j) = (k / nv, k % nv);
            let start = [
                0.5 * (self.tu[i] + self.tu[i + 1]),
                0.5 * (self.tv[j] + self.tv[j + 1]),
            ];
            if let Some(uv) = self.newton(start, [x0, y0]) {
                // The same preimage found from a neighbouring start.
                let near = |a: &[f64; 2]| (a[0] - uv[0]).abs() + (a[1] - uv[1]).abs() <= 1e-9;
                if !found.iter().any(near) {
                    found.push(uv);
                }
                if found.len() >= MAX_PREIMAGES {
                    break;
                }
            }
        }
        found
    }

    /// Newton's method for `plan(u, v) = target` from `start`, kept in the
    /// domain, with halved steps while the residual does not fall.
    pub(crate) fn newton(&self, start: [f64; 2], target: [f64; 2]) -> Option<[f64; 2]> {
        let s = self.surface;
        let (du, dv) = (s.domain(Direction::U), s.domain(Direction::V));
        let clamp = |[u, v]: [f64; 2]| [u.clamp(du.start, du.end), v.clamp(dv.start, dv.end)];
        let residual = |uv: [f64; 2]| {
            let p = s.eval_unchecked(uv[0], uv[1]);
            [p[0] - target[0], p[1] - target[1]]
        };
        let norm = |r: [f64; 2]| r[0].hypot(r[1]);
        let mut uv = start;
        let mut r = residual(uv);
        for _ in 0..NEWTON_STEPS {
            if norm(r) <= RESIDUAL * self.size {
                return Some(uv);
            }
            let d = s.derivatives_unchecked(uv[0], uv[1], 1);
            let (su, sv) = (d[1][0], d[0][1]);
            let det = su[0] * sv[1] - sv[0] * su[1];
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let step = [
                -(sv[1] * r[0] - sv[0] * r[1]) / det,
                -(-su[1] * r[0] + su[0] * r[1]) / det,
            ];
            let mut lambda = 1.0;
            let mut improved = false;
            for _ in 0..30 {
                let next = clamp([uv[0] + lambda * step[0], uv[1] + lambda * step[1]]);
                let rn = residual(next);
                if norm(rn) < norm(r) {
                    (uv, r, improved) = (next, rn, true);
                    break;
                }
                lambda *= 0.5;
            }
            if !improved {
                break;
            }
        }
        (norm(r) <= RESIDUAL * self.size).then_some(uv)
    }
}
