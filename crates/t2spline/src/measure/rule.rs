//! A fixed quadrature rule over the curve's domain for the integrals of
//! docs/method.md §11 (arc length, area): Gauss–Legendre nodes on equal parts
//! of each tame piece of the knot spans, with the rational basis and its
//! first derivative stored at every node, so that a length or an area of
//! any control points in the box costs one pass over the nodes.
//!
//! Each piece is halved until the rule on `m` parts and on `2m` parts agree
//! to `10⁻¹³` on the piece's test integrals: `∫ Rⱼ'·Rₖ` for every pair of
//! its control points (the area's coefficients) and the crisp curve's
//! length. The rule on `m` parts is kept as `coarse`: the difference
//! between the two rules is the error estimate of every integral reported.

use crate::cubature::gauss_legendre;
use crate::measure::coefficients::rational_derivatives;
use crate::nurbs::pieces::tame_pieces;
use crate::nurbs::KnotVector;

/// Gauss–Legendre points per part: exact for polynomials of degree 31.
const POINTS: usize = 16;
/// Halvings of a piece at most (`2⁷` parts).
const MAX_HALVINGS: u32 = 7;
/// Agreement of two rules on the test integrals, relative to their size.
const AGREEMENT: f64 = 1e-13;

/// Nodes in increasing order of `t`, with their weights and the `p + 1`
/// values of `R` and `R'` of the control points `first .. first + p`.
#[derive(Clone, Debug, Default)]
pub(crate) struct Rule {
    /// `p + 1`.
    pub(crate) width: usize,
    pub(crate) t: Vec<f64>,
    pub(crate) weight: Vec<f64>,
    pub(crate) first: Vec<usize>,
    /// `r[q·width + j]`: `R_{first+j}(t_q)`.
    pub(crate) r: Vec<f64>,
    /// `r1[q·width + j]`: `R'_{first+j}(t_q)`.
    pub(crate) r1: Vec<f64>,
}

impl Rule {
    /// The number of nodes.
    pub(crate) fn len(&self) -> usize {
        self.t.len()
    }

    /// The nodes where control point `i` counts: a contiguous range.
    pub(crate) fn nodes_of(&self, i: usize) -> std::ops::Range<usize> {
        let p = self.width - 1;
        let lo = self.first.partition_point(|&f| f + p < i);
        let hi = self.first.partition_point(|&f| f <= i);
        lo..hi.max(lo)
    }

    fn push_part(
        &mut self,
        knots: &KnotVector,
        weights: &[f64],
        span: usize,
        [lo, hi]: [f64; 2],
        gauss: &(Vec<f64>, Vec<f64>),
    ) {
        let (half, mid) = ((hi - lo) / 2.0, lo + (hi - lo) / 2.0);
        let p = knots.degree();
        for (x, w) in gauss.0.iter().zip(&gauss.1).rev() {
            let t = (mid + half * x).clamp(lo, hi);
            let d = rational_derivatives(knots, weights, span, t, 1);
            self.t.push(t);
            self.weight.push(w * half);
            self.first.push(span - p);
            self.r.extend_from_slice(&d[0]);
            self.r1.extend_from_slice(&d[1]);
        }
    }
}

/// A rule and the coarser one it was checked against.
#[derive(Clone, Debug, Default)]
pub(crate) struct Rules {
    pub(crate) fine: Rule,
    pub(crate) coarse: Rule,
}

/// The rules for a curve with `knots` and `weights` whose crisp control
/// points are `crisp` (flattened, `D` per point).
pub(crate) fn rules(knots: &KnotVector, weights: &[f64], crisp: &[f64], dim: usize) -> Rules {
    let gauss = gauss_legendre(POINTS);
    let width = knots.degree() + 1;
    let mut out = Rules {
        fine: Rule {
            width,
            ..Rule::default()
        },
        coarse: Rule {
            width,
            ..Rule::default()
        },
    };
    let domain = knots.domain();
    let pieces = tame_pieces(
        knots,
        weights,
        |i| vec![weights[i]],
        domain.start,
        domain.end,
    );
    for piece in pieces.into_iter().filter(|p| p.lo < p.hi) {
        let range = [piece.lo, piece.hi];
        let mut coarse = part_rule(knots, weights, piece.span, range, 1, &gauss);
        let mut before = tests(&coarse, crisp, dim);
        let mut parts = 2usize;
        let mut fine = part_rule(knots, weights, piece.span, range, parts, &gauss);
        for _ in 1..MAX_HALVINGS {
            let now = tests(&fine, crisp, dim);
            let agree = before
                .iter()
                .zip(&now)
                .all(|(a, b)| (a - b).abs() <= AGREEMENT * a.abs().max(b.abs()).max(1.0));
            if agree {
                break;
            }
            parts *= 2;
            coarse = std::mem::replace(
                &mut fine,
                part_rule(knots, weights, piece.span, range, parts, &gauss),
            );
            before = now;
        }
        out_extend(&mut out.coarse, &coarse);
        out_extend(&mut out.fine, &fine);
    }
    out
}

fn out_extend(rule: &mut Rule, part: &Rule) {
    rule.t.extend_from_slice(&part.t);
    rule.weight.extend_from_slice(&part.weight);
    rule.first.extend_from_slice(&part.first);
    rule.r.extend_from_slice(&part.r);
    rule.r1.extend_from_slice(&part.r1);
}

/// The rule on `parts` equal parts of `[lo, hi]` in span `span`.
fn part_rule(
    knots: &KnotVector,
    weights: &[f64],
    span: usize,
    [lo, hi]: [f64; 2],
    parts: usize,
    gauss: &(Vec<f64>, Vec<f64>),
) -> Rule {
    let mut rule = Rule {
        width: knots.degree() + 1,
        ..Rule::default()
    };
    let step = (hi - lo) / parts as f64;
    for k in 0..parts {
        let a = lo + step * k as f64;
        let b = if k + 1 == parts {
            hi
        } else {
            lo + step * (k + 1) as f64
        };
        rule.push_part(knots, weights, span, [a, b], gauss);
    }
    rule
}

/// The test integrals of one piece's rule: `∫ Rⱼ'Rₖ` for every pair, then
/// the crisp curve's length on the piece divided by the largest crisp
/// coordinate (a number of the size of the others; `∫ |Rⱼ'|` would do too,
/// but it has corners where `Rⱼ'` changes sign and converges slowly).
fn tests(rule: &Rule, crisp: &[f64], dim: usize) -> Vec<f64> {
    let w = rule.width;
    let mut out = vec![0.0; w * w + 1];
    for q in 0..rule.len() {
        let (r, r1) = (&rule.r[q * w..(q + 1) * w], &rule.r1[q * w..(q + 1) * w]);
        let weight = rule.weight[q];
        for j in 0..w {
            for k in 0..w {
                out[j * w + k] += weight * r1[j] * r[k];
            }
        }
        let first = rule.first[q];
        let mut speed = 0.0;
        for c in 0..dim {
            let d: f64 = (0..w).map(|j| r1[j] * crisp[(first + j) * dim + c]).sum();
            speed += d * d;
        }
        out[w * w] += weight * speed.sqrt();
    }
    let size = crisp
        .iter()
        .fold(0.0_f64, |m, x| m.max(x.abs()))
        .max(f64::MIN_POSITIVE);
    out[w * w] /= size;
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::NurbsCurve;

    #[test]
    fn the_rule_integrates_a_cubic_wave_length() {
        let points: Vec<[f64; 2]> = (0..20)
            .map(|i| [i as f64, 2.0 * (0.7 * i as f64).sin()])
            .collect();
        let c = NurbsCurve::try_clamped(3, points.clone(), vec![1.0; 20]).unwrap();
        let crisp: Vec<f64> = points.iter().flatten().copied().collect();
        let r = rules(c.knots(), c.weights(), &crisp, 2);
        let l = crate::measure::length::length(&r.fine, 2, &crisp);
        let reference = c.arc_length();
        assert!(
            (l - reference).abs() < 1e-12 * reference,
            "{l} vs {reference}, {} nodes",
            r.fine.len()
        );
    }
}
