//! The `terrain-measures` figure: the volumes below and above the datum
//! `z = 0`, the plan area below it and the surface area of a terrain
//! (docs/method.md §14) as type-2 fuzzy numbers, drawn as the `measures`
//! figure draws a curve's length and area: per quantity the upper, primary
//! and lower membership functions traced by their cuts, the footprint, the
//! height h and the crisp surface's value.

use super::measures::{legend_of, quantity_panel, widest_gap_of};
use crate::chart::scene::Figure;
use crate::chart::ticks::short;
use crate::terrain_view::{TerrainMeasures, SURFACE_AREA_MAX_POINTS};

/// The `terrain-measures` figure of `m`, a panel per quantity (in rows of
/// two).
#[must_use]
pub fn terrain_measures_figure(m: &TerrainMeasures) -> Figure {
    let panels = m
        .quantities
        .iter()
        .map(|q| quantity_panel(q.name, &q.levels, q.crisp))
        .collect();
    let mut notes = Vec::new();
    for q in &m.quantities {
        if let Some(gap) = widest_gap_of(&q.levels) {
            notes.push(format!(
                "{}: some cuts are certified brackets, not exact; their outer bounds are drawn, at most {} outside the values attained (bracket width).",
                q.name,
                short(gap, 3)
            ));
        }
    }
    notes.push(format!(
        "Volumes and plan area traced by their cuts at {} levels (0, 0.1, …, 1 and every h), joined by straight lines; t2spline measure prints the intervals.",
        m.levels
    ));
    notes.push(match m.area_levels {
        Some(n) => format!("Surface area traced at {n} levels (0, 0.5, 1 and every h): each costs a convex minimisation per function."),
        None => format!("Surface area left out: the net has more than {SURFACE_AREA_MAX_POINTS} control points, where each level takes seconds; t2spline measure gives it."),
    });
    let crisp: Vec<String> = m
        .quantities
        .iter()
        .map(|q| format!("{} {}", q.name, short(q.crisp, 4)))
        .collect();
    let mut fig = Figure::new(
        "terrain-measures",
        "Fuzzy measures of the terrain: volumes and areas about z = 0",
        format!(
            "crisp surface: {}; plan area {}",
            crisp.join(", "),
            short(m.plan_area, 4)
        ),
        panels,
        legend_of("crisp surface's value"),
    );
    fig.notes = notes;
    fig
}
