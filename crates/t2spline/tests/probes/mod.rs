//! Parameters that probe a surface in one direction, shared by the surface
//! test files.

use t2spline::KnotVector;

/// Both ends of the domain, every knot in it (where spans change, also knots
/// of full multiplicity), and the given fractions of the domain; sorted.
pub fn probes(knots: &KnotVector, fractions: &[f64]) -> Vec<f64> {
    let d = knots.domain();
    let mut t: Vec<f64> = fractions.iter().map(|&s| d.lerp(s)).collect();
    t.extend([d.start, d.end]);
    t.extend(knots.as_slice().iter().filter(|&&u| d.contains(u)));
    t.sort_by(f64::total_cmp);
    t.dedup();
    t
}
