//! The exact curves of a run, named: what CAD files carry.
//!
//! A run samples its curves ([`Job::run`]); a CAD program wants the curves
//! themselves. [`Job::geometry`] gives them as rational B-splines with their
//! knots, weights and control points, exactly those whose samples `run`
//! writes:
//!
//! | name | curve | source |
//! |---|---|---|
//! | `crisp` | the crisp curve | docs/method.md §7 stage 1 |
//! | `defuzzified` | the crisp type-2 solution at the run's alpha, by its type reduction | docs/method.md §7 stage 4, §9 |
//! | `upper_left`, …, `upper_right` | the six other layer curves, before the cut | docs/method.md §7 stage 1 |
//!
//! A surface job (docs/method.md §8) gives the same names to its surfaces: the crisp,
//! the defuzzified and the six layer surfaces. Points are lifted to three
//! coordinates (`z = 0` for planar jobs), as every CAD format stores them. A curve whose knot vector has an interior knot of
//! full multiplicity (order `k`) jumps there (docs/method.md §6); CAD formats allow at
//! most degree `p = k − 1` inside the knot vector (ISO 10303-42's rule for
//! `B_SPLINE_CURVE_WITH_KNOTS`), so such a curve is given as its continuous
//! pieces, cut at the jumps without arithmetic: each piece keeps its control
//! points, weights and knots bit for bit, and its parameters. At a jump the
//! run's value is the right piece's (docs/method.md §6: from the right). A knot of
//! full multiplicity at an end of the domain with knots beyond it is cut the
//! same way: the control points and knots beyond it, which act only outside
//! the domain, are dropped, so every piece is clamped there and the curve
//! on its domain is unchanged (ISO 10303-42 allows no more than `p` equal
//! knots inside a knot vector, and OpenCASCADE refuses or bends such a
//! curve). Surfaces are cut the same way in each direction, into patches.

use crate::error::Error;
use crate::fuzzy::{Alpha, Layer};
use crate::nurbs::{Direction, KnotVector, NurbsCurve, NurbsSurface};
use crate::pipeline::{FuzzyCurve, FuzzySurface};
use crate::reduction::TypeReduction;

use super::model::ModelVisitor;
use super::settings::Settings;
use super::Job;

/// One named curve of a run, as continuous pieces in parameter order.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedCurve {
    /// `crisp`, `defuzzified`, or a layer's name (`upper_left`, …).
    pub name: &'static str,
    /// The curve, cut at interior knots of full multiplicity and without the
    /// control points beyond a knot of full multiplicity at an end of the
    /// domain; one piece when it has none. Each piece keeps the curve's
    /// parameters.
    pub pieces: Vec<NurbsCurve<3>>,
}

/// One named surface of a run, as patches without jumps.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedSurface {
    /// `crisp`, `defuzzified`, or a layer's name (`upper_left`, …).
    pub name: &'static str,
    /// The surface, cut at interior knots of full multiplicity in either
    /// direction, row by row of patches (along u, then v); one patch when it
    /// has none. Each patch keeps the surface's parameters.
    pub patches: Vec<NurbsSurface<3>>,
}

/// The exact geometry of a run: every curve (of a curve job) or surface (of
/// a surface job), named, in 3-D.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Geometry {
    /// The dimension of the job's points (2 or 3); planar jobs have `z = 0`.
    pub dimension: usize,
    /// `crisp`, `defuzzified`, then the six non-crisp layers in docs/method.md §1 order;
    /// empty for a surface job.
    pub curves: Vec<NamedCurve>,
    /// The same names for the surfaces of a surface job; empty for a curve
    /// job.
    pub surfaces: Vec<NamedSurface>,
}

impl Geometry {
    /// The same geometry with every curve piece clamped
    /// ([`NurbsCurve::clamped`]: knot insertion at the ends of the domain,
    /// so each piece starts and ends at its first and last control point);
    /// the curves are unchanged to rounding, surfaces are left as they are.
    #[must_use]
    pub fn clamped(&self) -> Geometry {
        Geometry {
            dimension: self.dimension,
            curves: self
                .curves
                .iter()
                .map(|c| NamedCurve {
                    name: c.name,
                    pieces: c.pieces.iter().map(NurbsCurve::clamped).collect(),
                })
                .collect(),
            surfaces: self.surfaces.clone(),
        }
    }

    /// The smallest degree of the curves or of the surfaces in either
    /// direction (all curves, and all surfaces, share their degrees).
    #[must_use]
    pub fn degree(&self) -> usize {
        let curve = self
            .curves
            .first()
            .and_then(|c| c.pieces.first())
            .map(NurbsCurve::degree);
        let surface = self
            .surfaces
            .first()
            .and_then(|s| s.patches.first())
            .map(|s| s.degree().into_iter().min().unwrap_or(0));
        curve.or(surface).unwrap_or(0)
    }
}

impl Job {
    /// The exact curves of a run at `settings.alpha()` with
    /// `settings.type_reduction()`: the crisp, the defuzzified and the six
    /// other layer curves, named (see the module docs). Their samples are the curves of [`Job::run`] with the same
    /// settings.
    ///
    /// # Errors
    /// None for a valid job (the pieces are cut from valid knot vectors);
    /// the `Result` guards the construction of each piece.
    ///
    /// # Examples
    /// ```
    /// # use t2spline::job::{Job, Model, Overrides};
    /// # use t2spline::{FuzzyCurve, Nt2Number, Nt2Point};
    /// let n = |c: f64| Nt2Number::try_new(c, [c - 1.0, c + 2.0], [c - 0.5, c + 1.0], [c - 0.2, c + 0.3], 0.5);
    /// let points = vec![Nt2Point::new([n(0.0)?, n(0.0)?]), Nt2Point::new([n(3.0)?, n(4.0)?])];
    /// let job = Job::new(Model::Planar(FuzzyCurve::try_new(1, points, vec![1.0, 1.0], None)?));
    /// let settings = job.settings(&Overrides { alpha: Some(0.5), ..Overrides::default() })?;
    /// let g = job.geometry(&settings)?;
    /// let names: Vec<_> = g.curves.iter().map(|c| c.name).collect();
    /// assert_eq!(names, ["crisp", "defuzzified", "upper_left", "primary_left", "lower_left",
    ///                    "lower_right", "primary_right", "upper_right"]);
    /// assert_eq!(g.curves[0].pieces[0].eval(0.5)?, [1.5, 2.0, 0.0]);
    /// # Ok::<(), t2spline::Error>(())
    /// ```
    pub fn geometry(&self, settings: &Settings) -> Result<Geometry, Error> {
        self.model
            .visit(Exact(settings.alpha(), settings.type_reduction()))
    }
}

/// [`Job::geometry`] for one kind of model.
struct Exact(Alpha, TypeReduction);

impl ModelVisitor for Exact {
    type Output = Result<Geometry, Error>;

    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> Self::Output {
        let defuzzified = curve.solve_with(self.0, self.1).defuzzified_curve();
        let curves = named(curve.crisp_curve(), defuzzified, |l| curve.layer_curve(l))
            .into_iter()
            .map(|(name, c)| {
                Ok(NamedCurve {
                    name,
                    pieces: continuous_pieces(&lift(&c)?)?,
                })
            })
            .collect::<Result<_, Error>>()?;
        Ok(Geometry {
            dimension: D,
            curves,
            surfaces: Vec::new(),
        })
    }

    fn surface<const D: usize>(self, surface: &FuzzySurface<D>) -> Self::Output {
        let defuzzified = surface.solve_with(self.0, self.1).defuzzified_surface();
        let surfaces = named(surface.crisp_surface(), defuzzified, |l| {
            surface.layer_surface(l)
        })
        .into_iter()
        .map(|(name, s)| {
            Ok(NamedSurface {
                name,
                patches: continuous_patches(&lift_surface(&s)?)?,
            })
        })
        .collect::<Result<_, Error>>()?;
        Ok(Geometry {
            dimension: D,
            curves: Vec::new(),
            surfaces,
        })
    }
}

/// The eight shapes of a run with their names: `crisp`, `defuzzified`, then
/// the six other layers in docs/method.md §1 order.
fn named<T>(crisp: T, defuzzified: T, layer: impl Fn(Layer) -> T) -> Vec<(&'static str, T)> {
    let mut out = vec![("crisp", crisp), ("defuzzified", defuzzified)];
    out.extend(
        Layer::ALL
            .into_iter()
            .filter(|&l| l != Layer::Crisp)
            .map(|l| (l.name(), layer(l))),
    );
    out
}

/// A point with three coordinates: its own, then zeros.
fn lift_point<const D: usize>(p: &[f64; D]) -> [f64; 3] {
    std::array::from_fn(|i| p.get(i).copied().unwrap_or(0.0))
}

/// The surface with three coordinates.
fn lift_surface<const D: usize>(s: &NurbsSurface<D>) -> Result<NurbsSurface<3>, Error> {
    let nv = s.shape()[1];
    let points = s
        .control_points()
        .chunks(nv)
        .map(|row| row.iter().map(lift_point).collect())
        .collect();
    let weights = s.weights().chunks(nv).map(<[f64]>::to_vec).collect();
    NurbsSurface::try_new(
        points,
        weights,
        [s.knots(Direction::U).clone(), s.knots(Direction::V).clone()],
    )
}

/// The index ranges of control points of the continuous pieces of a knot
/// vector: cut at every interior knot of full multiplicity (see
/// [`continuous_pieces`]), and without the control points that act only
/// outside the domain.
///
/// A run of `k` equal knots that holds an end of the domain, `U[p]` or
/// `U[n]`, with knots beyond it, cuts the curve there too: the basis
/// functions of the control points beyond the run vanish on the whole
/// domain, so those points and their knots are dropped, and the curve on
/// its domain is unchanged (no coefficient changes). CAD formats need the
/// cut: ISO 10303-42 allows at most `p` equal knots inside a knot vector,
/// and OpenCASCADE refuses such a STEP curve ("Poles and degree mismatch")
/// and bends such an IGES curve.
///
/// ```text
/// k = 3, U = (0, 0, 0, ½, ½, ½, 1), P₀ … P₃: domain [U[2], U[4]] = [0, ½]
/// → U = (0, 0, 0, ½, ½, ½), P₀ … P₂  (P₃ acts on [½, 1] only)
/// ```
fn piece_ranges(knots: &KnotVector) -> Vec<(usize, usize)> {
    let k = knots.degree() + 1;
    let u = knots.as_slice();
    let domain = knots.domain();
    let mut cuts = Vec::new();
    let (mut first, mut last) = (0, knots.count());
    let mut f = 0;
    for run in u.chunk_by(|a, b| a == b) {
        if let (true, Some(&v)) = (run.len() == k, run.first()) {
            if domain.start < v && v < domain.end {
                cuts.push(f);
            } else if v == domain.start {
                // Points 0 … f − 1 end their support at or before U[p].
                first = f;
            } else if v == domain.end {
                // Points f … n − 1 start their support at or after U[n].
                last = f;
            }
        }
        f += run.len();
    }
    let mut ranges = Vec::with_capacity(cuts.len() + 1);
    let mut start = first;
    for end in cuts.into_iter().chain([last]) {
        ranges.push((start, end));
        start = end;
    }
    ranges
}

/// The knot vector of the piece whose control points are `start..end`.
fn piece_knots(knots: &KnotVector, (start, end): (usize, usize)) -> Result<KnotVector, Error> {
    let k = knots.degree() + 1;
    KnotVector::try_new(
        knots
            .as_slice()
            .get(start..end + k)
            .unwrap_or_default()
            .to_vec(),
        k - 1,
        end - start,
    )
}

/// Rows `u0..u1`, columns `v0..v1` of a net stored row by row, `nv` per row.
/// Piece ranges lie within the net's shape, so every slice exists (an empty
/// row would make `NurbsSurface::try_new` refuse the patch).
fn sub_net<T: Copy>(
    values: &[T],
    nv: usize,
    (u0, u1): (usize, usize),
    (v0, v1): (usize, usize),
) -> Vec<Vec<T>> {
    let rows = values.get(u0 * nv..u1 * nv).unwrap_or_default();
    rows.chunks(nv.max(1))
        .map(|row| row.get(v0..v1).unwrap_or_default().to_vec())
        .collect()
}

/// The surface cut at every interior knot of full multiplicity in u and in
/// v: the patches of the product of both directions' pieces, row by row.
fn continuous_patches(s: &NurbsSurface<3>) -> Result<Vec<NurbsSurface<3>>, Error> {
    let (ku, kv) = (s.knots(Direction::U), s.knots(Direction::V));
    let (ru, rv) = (piece_ranges(ku), piece_ranges(kv));
    if ru == [(0, ku.count())] && rv == [(0, kv.count())] {
        return Ok(vec![s.clone()]);
    }
    let nv = s.shape()[1];
    let mut patches = Vec::with_capacity(ru.len() * rv.len());
    for &(u0, u1) in &ru {
        for &(v0, v1) in &rv {
            let points = sub_net(s.control_points(), nv, (u0, u1), (v0, v1));
            let weights = sub_net(s.weights(), nv, (u0, u1), (v0, v1));
            patches.push(NurbsSurface::try_new(
                points,
                weights,
                [piece_knots(ku, (u0, u1))?, piece_knots(kv, (v0, v1))?],
            )?);
        }
    }
    Ok(patches)
}

/// The curve with three coordinates: its own, then zeros.
fn lift<const D: usize>(c: &NurbsCurve<D>) -> Result<NurbsCurve<3>, Error> {
    let points = c.control_points().iter().map(lift_point).collect();
    NurbsCurve::try_new(points, c.weights().to_vec(), c.knots().clone())
}

/// The curve cut at every interior knot of full multiplicity `k`.
///
/// ```text
/// U = (u₀ … u_f−1, u, …, u (k times), u_f+k …),  P₀ … Pₙ₋₁
/// left:  U[0 .. f + k],  P₀ … P_f−1      (clamped at its right end u)
/// right: U[f ..],        P_f …           (clamped at its left end u)
/// ```
/// The basis functions of the left piece are those of the curve that vanish
/// right of `u`, and conversely: no coefficient changes.
fn continuous_pieces(c: &NurbsCurve<3>) -> Result<Vec<NurbsCurve<3>>, Error> {
    let ranges = piece_ranges(c.knots());
    if ranges == [(0, c.knots().count())] {
        return Ok(vec![c.clone()]);
    }
    ranges
        .into_iter()
        .map(|(start, end)| {
            NurbsCurve::try_new(
                c.control_points()
                    .get(start..end)
                    .unwrap_or_default()
                    .to_vec(),
                c.weights().get(start..end).unwrap_or_default().to_vec(),
                piece_knots(c.knots(), (start, end))?,
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(knots: Vec<f64>, degree: usize) -> NurbsCurve<3> {
        let n = knots.len() - degree - 1;
        let points = (0..n)
            .map(|i| [i as f64, (i * i) as f64 * 0.5, -(i as f64)])
            .collect();
        let weights = (0..n).map(|i| 1.0 + (i % 3) as f64).collect();
        NurbsCurve::try_new(
            points,
            weights,
            KnotVector::try_new(knots, degree, n).unwrap(),
        )
        .unwrap()
    }

    #[test]
    fn a_curve_without_jumps_is_one_piece_unchanged() {
        let c = curve(vec![0.0, 0.5, 1.0, 2.0, 2.0, 3.0, 4.0, 5.0], 2);
        assert_eq!(continuous_pieces(&c).unwrap(), vec![c]);
    }

    #[test]
    fn jumps_cut_the_curve_into_pieces_that_agree_with_it() {
        // Degree 2, unclamped, full multiplicity (3) at 2 and at 3.
        let c = curve(
            vec![
                0.0, 0.5, 1.0, 2.0, 2.0, 2.0, 2.5, 3.0, 3.0, 3.0, 3.5, 4.0, 4.5,
            ],
            2,
        );
        let pieces = continuous_pieces(&c).unwrap();
        assert_eq!(pieces.len(), 3);
        let domains: Vec<_> = pieces
            .iter()
            .map(|p| (p.domain().start, p.domain().end))
            .collect();
        assert_eq!(domains, [(1.0, 2.0), (2.0, 3.0), (3.0, 3.5)]);
        // Unclamped outer ends stay as they were.
        assert_eq!(pieces[0].knots().as_slice()[..3], [0.0, 0.5, 1.0]);
        for (i, piece) in pieces.iter().enumerate() {
            let d = piece.domain();
            for s in 0..=20 {
                let t = d.lerp(f64::from(s) / 20.0);
                // At a jump the curve takes the right piece's value.
                if t == d.end && i + 1 < pieces.len() {
                    continue;
                }
                assert_eq!(
                    piece.eval(t).unwrap(),
                    c.eval(t).unwrap(),
                    "piece {i}, t = {t}"
                );
            }
        }
    }

    #[test]
    fn full_multiplicity_at_the_domain_ends_is_no_jump() {
        let c = curve(vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0], 2);
        assert_eq!(continuous_pieces(&c).unwrap().len(), 1);
    }
    /// Samples of `piece` and `c` agree on the domain of `c` (which the piece
    /// must keep).
    fn assert_same_curve(piece: &NurbsCurve<3>, c: &NurbsCurve<3>) {
        assert_eq!(piece.domain(), c.domain());
        let d = c.domain();
        for s in 0..=40 {
            let t = d.lerp(f64::from(s) / 40.0);
            let (a, b) = (piece.eval(t).unwrap(), c.eval(t).unwrap());
            for i in 0..3 {
                assert!((a[i] - b[i]).abs() <= 1e-12, "t = {t}: {a:?} against {b:?}");
            }
        }
    }

    #[test]
    fn full_multiplicity_at_the_domain_end_with_knots_beyond_is_cut_off() {
        // Order 3: domain [U[2], U[4]] = [0, 0.5]; P3 acts on [0.5, 1] only.
        let c = curve(vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0], 2);
        let pieces = continuous_pieces(&c).unwrap();
        assert_eq!(pieces.len(), 1);
        let p = &pieces[0];
        assert_eq!(p.knots().as_slice(), [0.0, 0.0, 0.0, 0.5, 0.5, 0.5]);
        assert_eq!(p.control_points(), &c.control_points()[..3]);
        assert_eq!(p.weights(), &c.weights()[..3]);
        assert!(p.knots().is_clamped());
        assert_same_curve(p, &c);
    }

    #[test]
    fn full_multiplicity_at_the_domain_start_with_knots_before_is_cut_off() {
        // Order 3: domain [U[2], U[4]] = [0.5, 1]; P0 acts on [0, 0.5] only.
        let c = curve(vec![0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0], 2);
        let pieces = continuous_pieces(&c).unwrap();
        assert_eq!(pieces.len(), 1);
        assert_eq!(pieces[0].knots().as_slice(), [0.5, 0.5, 0.5, 1.0, 1.0, 1.0]);
        assert_eq!(pieces[0].control_points(), &c.control_points()[1..]);
        assert_same_curve(&pieces[0], &c);
    }

    #[test]
    fn both_ends_and_a_jump_cut_together() {
        // Degree 2, 8 points: runs of 3 at the domain start 1, the jump 2
        // and the domain end 3, with knots before and after.
        let c = curve(
            vec![0.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 3.0, 3.0, 3.0],
            2,
        );
        assert_eq!((c.domain().start, c.domain().end), (1.0, 3.0));
        let pieces = continuous_pieces(&c).unwrap();
        let domains: Vec<_> = pieces
            .iter()
            .map(|p| (p.domain().start, p.domain().end))
            .collect();
        assert_eq!(domains, [(1.0, 2.0), (2.0, 3.0)]);
        assert!(pieces.iter().all(|p| p.knots().is_clamped()));
        assert_eq!(pieces[0].control_points(), &c.control_points()[1..5]);
        assert_eq!(pieces[1].control_points(), &c.control_points()[5..8]);
        // Degree 2 with an unclamped end run of 3 beyond the last knot.
        let c = curve(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 3.0], 2);
        let pieces = continuous_pieces(&c).unwrap();
        assert_eq!(pieces.len(), 1);
        assert_eq!(pieces[0].control_points().len(), 3);
        assert_same_curve(&pieces[0], &c);
    }

    #[test]
    fn surfaces_drop_the_rows_and_columns_outside_the_domain() {
        // u: order 3 with a run of 3 at the domain end 0.5 and the knot 1
        // beyond; v: order 2, clamped.
        let points: Vec<Vec<[f64; 3]>> = (0..4)
            .map(|i| {
                (0..3)
                    .map(|j| [i as f64, j as f64, (i * j) as f64 * 0.25 + (i * i) as f64])
                    .collect()
            })
            .collect();
        let weights = vec![vec![1.0, 2.0, 1.0]; 4];
        let ku = KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0], 2, 4).unwrap();
        let kv = KnotVector::try_new(vec![0.0, 0.0, 0.5, 1.0, 1.0], 1, 3).unwrap();
        let s = NurbsSurface::try_new(points, weights, [ku, kv]).unwrap();
        let patches = continuous_patches(&s).unwrap();
        assert_eq!(patches.len(), 1);
        let p = &patches[0];
        assert_eq!(p.shape(), [3, 3]);
        assert_eq!(
            p.knots(Direction::U).as_slice(),
            [0.0, 0.0, 0.0, 0.5, 0.5, 0.5]
        );
        for a in 0..=10 {
            for b in 0..=10 {
                let (u, v) = (0.05 * f64::from(a), 0.1 * f64::from(b));
                let (x, y) = (p.eval(u, v).unwrap(), s.eval(u, v).unwrap());
                for i in 0..3 {
                    assert!(
                        (x[i] - y[i]).abs() <= 1e-12,
                        "({u}, {v}): {x:?} against {y:?}"
                    );
                }
            }
        }
    }
}
