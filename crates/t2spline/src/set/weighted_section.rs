//! The section at `x = x0` of a plane curve whose weights are fuzzy too
//! (docs/method.md §16): the values of y over every parameter and every
//! choice of points and weights inside their cuts,
//!
//! ```text
//! ∪ over t of  sec(t) = { y : (x0, y) ∈ S(t) }
//! ```
//! each `sec(t)` exact by the Charnes–Cooper program of docs/method.md §15.
//!
//! The knot spans are cut into pieces. On a piece the terms with the bounds
//! of the basis (`weighted_terms.rs`) give a set that holds every `S(t)`
//! there, so its section holds every `sec(t)` of the piece; the section at
//! the piece's middle is attained. A piece whose bound lies within the
//! tolerance of the attained values is done; any other is halved. The
//! answer joins the bounds of the pieces that are done: never narrower than
//! the truth, and (up to the depth limit, reached only where the line
//! touches the set) no end more than the tolerance beyond a value some
//! choice attains.

use std::collections::VecDeque;

use crate::fuzzy::{Alpha, Axis, Membership};
use crate::set::intervals::join;
use crate::set::weighted_terms::{PieceSet, Weighted};

/// Pieces each knot span starts as.
const FIRST_PIECES: usize = 4;

/// Halvings of a piece at the most (`4·2⁴⁰` pieces a span).
const MAX_DEPTH: u32 = 40;

/// Pieces examined at the most; the rest are taken with their bounds.
const MAX_PIECES: usize = 20_000;

/// One piece `[s₀, s₁]` of a knot span, and how often it was halved.
struct Piece {
    span: usize,
    s: [f64; 2],
    depth: u32,
}

/// The section `{ y : (x0, y) in the set }` under `m` at `alpha` of a plane
/// curve with fuzzy weights, as intervals in increasing order joined within
/// half of `tolerance`; `None` where no number that counts has a cut at
/// `alpha` (the lower function above the heights).
pub(crate) fn weighted_section(
    on: &Weighted<'_, 2>,
    x0: f64,
    m: Membership,
    alpha: Alpha,
    tolerance: f64,
) -> Option<Vec<[f64; 2]>> {
    let a = alpha.get();
    let mut queue: VecDeque<Piece> = on
        .curve
        .knots()
        .spans()
        .flat_map(|(span, _)| {
            (0..FIRST_PIECES).map(move |k| Piece {
                span,
                s: [k as f64, (k + 1) as f64].map(|x| x / FIRST_PIECES as f64),
                depth: 0,
            })
        })
        .collect();
    let (mut attained, mut done) = (Vec::new(), Vec::new());
    let mut any_cut = false;
    let mut seen = 0;
    while let Some(piece) = queue.pop_front() {
        seen += 1;
        let bound = match on.set(m, piece.span, &on.on(piece.span, piece.s), a) {
            PieceSet::Empty => continue,
            PieceSet::Unbounded => {
                any_cut = true;
                if piece.depth < MAX_DEPTH && seen < MAX_PIECES {
                    halve(&mut queue, &piece);
                } else {
                    // The curve's box, which holds every choice.
                    let b = on.curve.bounding_box();
                    done.push([b.min[1], b.max[1]]);
                }
                continue;
            }
            PieceSet::Terms(terms) => {
                any_cut = true;
                match terms.section(Axis::X, x0, Axis::Y) {
                    Ok(Some(iv)) => [iv.left(), iv.right()],
                    _ => continue,
                }
            }
        };
        let [s0, s1] = piece.s;
        let mid = s0 + (s1 - s0) / 2.0;
        if let PieceSet::Terms(terms) = on.set(m, piece.span, &on.at(piece.span, mid), a) {
            if let Ok(Some(iv)) = terms.section(Axis::X, x0, Axis::Y) {
                attained.push([iv.left(), iv.right()]);
            }
        }
        let covered = join(attained.clone(), tolerance)
            .iter()
            .any(|iv| iv[0] - tolerance <= bound[0] && bound[1] <= iv[1] + tolerance);
        if covered || piece.depth >= MAX_DEPTH || seen >= MAX_PIECES {
            done.push(bound);
        } else {
            halve(&mut queue, &piece);
        }
    }
    any_cut.then(|| join(done, 0.5 * tolerance))
}

/// Puts the two halves of `piece` at the back of `queue`.
fn halve(queue: &mut VecDeque<Piece>, piece: &Piece) {
    let [s0, s1] = piece.s;
    let mid = s0 + (s1 - s0) / 2.0;
    for s in [[s0, mid], [mid, s1]] {
        if s[0] < s[1] {
            queue.push_back(Piece {
                span: piece.span,
                s,
                depth: piece.depth + 1,
            });
        }
    }
}
