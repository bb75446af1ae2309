//! What the curve figures of one result share: the scene they are drawn in.

use t2spline::job::RunOutput;

use super::density::Density;
use super::projection::{projections, Projection};
use crate::chart::scene::Panel;
use crate::figures::aspect::Aspect;

/// What the curve figures of one result share: the result, the lower heights,
/// the projections, the aspect and the detail that fits.
#[derive(Debug)]
pub struct CurveScene<'a> {
    /// The result drawn.
    pub r: &'a RunOutput,
    /// The distinct lower heights of the job, ascending.
    pub heights: &'a [f64],
    /// The projections drawn.
    pub projections: Vec<Projection>,
    /// Equal or free aspect.
    pub aspect: Aspect,
    /// The per-point detail that fits.
    pub density: Density,
}

impl<'a> CurveScene<'a> {
    /// The scene of result `r` of a job with lower heights `heights`.
    #[must_use]
    pub fn new(r: &'a RunOutput, heights: &'a [f64], aspect: Aspect) -> CurveScene<'a> {
        let projections = projections(r.dimension);
        let density = Density::of(&r.control_points.crisp, &projections, aspect);
        CurveScene {
            r,
            heights,
            projections,
            aspect,
            density,
        }
    }

    /// The axes of the projections, in the order of the panels.
    #[must_use]
    pub fn axes(&self) -> Vec<(usize, usize)> {
        self.projections.iter().map(|p| p.axes).collect()
    }

    /// One panel per projection, each filled by `fill`.
    pub fn panels(&self, mut fill: impl FnMut(&mut Panel, (usize, usize))) -> Vec<Panel> {
        self.projections
            .iter()
            .map(|pr| {
                let mut p = pr.panel(self.aspect);
                fill(&mut p, pr.axes);
                p
            })
            .collect()
    }

    /// The notes of a figure: what the density left out (`left_out` says
    /// what, when the derived markers are; `None` for a figure that draws
    /// none), and whether the axes are to scale.
    #[must_use]
    pub fn notes(&self, left_out: Option<&str>) -> Vec<String> {
        let left_out = left_out.filter(|_| !self.density.markers);
        let mut notes: Vec<String> = self.density.note(left_out).into_iter().collect();
        if self.aspect == Aspect::Auto {
            notes.push("Axes not to scale: each is fitted to the data.".to_owned());
        }
        notes
    }
}
