//! Stage 2 (paper Fig. 5.2): the alpha-cut control points and their curves.

use t2spline::job::{Points, RunOutput};
use t2spline::Layer;

use super::phrases::{alpha_phrase, point_name};
use super::projection::project;
use super::scene::CurveScene;
use super::series::{
    crisp_legend, crisp_points, line, markers, names, polygon, regions, regions_legend,
};
use crate::chart::scene::{Figure, LegendEntry};
use crate::chart::ticks::short;
use crate::figures::style::{layer_marker, layer_stroke, FUNCTIONS};
use crate::set_view::Regions;

/// The alpha-cut curve of a layer (the crisp curve for the crisp layer);
/// `None` when the layer has no cut at this alpha.
fn cut_curve(r: &RunOutput, l: Layer) -> Option<&Points> {
    match r.samples.alpha_cut.get(l) {
        None => Some(&r.samples.crisp),
        Some(v) => v.as_ref(),
    }
}

/// The alpha-cut control points of a layer that exist (every coordinate cut).
fn cut_points(r: &RunOutput, l: Layer, (i, j): (usize, usize)) -> Vec<[f64; 2]> {
    r.control_points
        .alpha_cut
        .get(l)
        .map(|cut| {
            cut.coord(i)
                .iter()
                .zip(cut.coord(j))
                .filter_map(|(x, y)| Some([(*x)?, (*y)?]))
                .collect()
        })
        .unwrap_or_default()
}

/// Whether the lower cut curves exist at this alpha.
fn has_lower(r: &RunOutput) -> bool {
    cut_curve(r, Layer::LowerLeft).is_some()
}

/// Stage 2 (paper Fig. 5.2): the alpha-cut control points and their curves,
/// over the regions the curve can occupy at the cut's level (`at`, from the
/// core's set view at the result's alpha): the upper function's and, where
/// it has a cut, the lower's. Lower cut curves are drawn (and listed in the
/// legend) only where every number has one; the lower region wherever some
/// part of the curve has one.
#[must_use]
pub fn stage2_figure(scene: &CurveScene<'_>, at: &Regions) -> Figure {
    let r = scene.r;
    let cp = &r.control_points;
    let d = &scene.density;
    let mut k = 0;
    let panels = scene.panels(|p, ij| {
        regions(p, at, k);
        k += 1;
        polygon(p, &cp.crisp, ij);
        for l in Layer::ALL {
            line(
                p,
                format!("curve-{}", l.name()),
                cut_curve(r, l).map(|c| project(c, ij)),
                layer_stroke(l),
            );
        }
        for l in Layer::ALL.into_iter().filter(|&l| l != Layer::Crisp) {
            markers(
                p,
                format!("points-{}", l.name()),
                cut_points(r, l, ij),
                layer_marker(l),
                d.markers,
            );
        }
        crisp_points(p, &cp.crisp, ij, d);
        names(p, &cp.crisp, ij, d, point_name);
    });
    Figure {
        notes: scene.notes(Some("cut ends not marked")),
        ..Figure::new(
            "stage2-alpha-cut",
            "Stage 2: alpha-cut of the fuzzy control points (α-NT2FRBsC)",
            alpha_phrase(r, scene.heights),
            panels,
            legend(r, at, d.markers),
        )
    }
}

/// The legend of what is drawn at this alpha.
fn legend(r: &RunOutput, at: &Regions, with_markers: bool) -> Vec<LegendEntry> {
    let mut legend = crisp_legend();
    for (l, _, name) in FUNCTIONS {
        if l == Layer::LowerLeft && !has_lower(r) {
            continue;
        }
        let label = format!("{name} cuts (left, right)");
        legend.push(if with_markers {
            LegendEntry::line_marker(&label, layer_stroke(l), layer_marker(l))
        } else {
            LegendEntry::line(&label, layer_stroke(l))
        });
    }
    legend.extend(regions_legend(at, &format!("α = {}", short(at.alpha, 4))));
    legend
}
