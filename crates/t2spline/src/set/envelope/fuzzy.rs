//! The envelope where x or y is fuzzy: per plan point the section of the
//! set ([`FuzzySurface::sections`]), its intervals hulled into the least and
//! the greatest height.

use super::bounds::{EnvelopeLevel, Gathered};
use crate::fuzzy::Alpha;
use crate::pipeline::FuzzySurface;
use crate::set::surface::SurfaceGrader;

/// The envelope at `points`, one section per point.
pub(crate) fn at_points(
    s: &FuzzySurface<3>,
    points: &[[f64; 2]],
    levels: &[Alpha],
) -> Vec<EnvelopeLevel> {
    let grader = SurfaceGrader::new(s);
    let present: [bool; 3] = [0, 1, 2].map(|k| grader.top(k) >= 0.0);
    let tops = [0, 1, 2].map(|k| grader.top(k));
    let mut g = Gathered::new(points.len(), levels, |k, alpha| {
        present[k] && alpha <= tops[k]
    });
    for (cell, &p) in points.iter().enumerate() {
        let sections = s.sections_with(&grader, p, levels);
        for ((_, bounds), section) in g.levels.iter_mut().zip(&sections) {
            let functions = [&section.upper, &section.primary, &section.lower];
            for (b, intervals) in bounds.iter_mut().zip(functions) {
                let (Some(b), Some(intervals)) = (b, intervals) else {
                    continue;
                };
                if let (Some(first), Some(last)) = (intervals.first(), intervals.last()) {
                    b.least[cell] = first[0];
                    b.greatest[cell] = last[1];
                }
            }
        }
    }
    g.finish()
}
