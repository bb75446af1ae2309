//! The `membership` figure: the footprint of uncertainty of a plane curve in
//! the plane (docs/method.md §10). `mu_upper` and `mu_lower` of every point
//! as colour maps (the core's `membership_grid`), the outlines of their
//! regions at a few levels as contours (the core's regions: `mu ≥ α` is
//! the region at α), and the crisp curve on top.

use t2spline::job::Job;
use t2spline::set::Region;
use t2spline::Membership;

use super::projection::Projection;
use super::scene::CurveScene;
use super::series::crisp_curve;
use crate::chart::paint::{viridis, Color};
use crate::chart::scene::{ColorBar, Figure, LegendEntry, Mark, Panel, Xy};
use crate::chart::ticks::short;
use crate::error::Error;
use crate::figures::aspect::Aspect;
use crate::figures::style::{contour_stroke, crisp_stroke, halo_stroke};
use crate::set_view::{self, Map};

/// The levels whose regions are drawn as contours.
pub const CONTOUR_LEVELS: [f64; 4] = [0.2, 0.4, 0.6, 0.8];

/// Colour steps of the map above 0: a cell takes the colour of its grade
/// rounded to a tenth.
const STEPS: usize = 10;

/// The colour step of a grade; `None` outside the footprint (grade 0).
fn step(v: f64) -> Option<usize> {
    (v > 0.0).then(|| ((v * STEPS as f64).round().max(0.0) as usize).min(STEPS))
}

/// The colour of step `k`.
fn colour(k: usize) -> Color {
    viridis(k as f64 / STEPS as f64)
}

/// The map's cells as tiles, one list per colour step: in each row a run
/// of cells of one step is one rectangle, and a rectangle that repeats the
/// one below it (same columns, same step) extends it; cells of grade 0 are
/// left out (the page shows through).
fn cells(map: &Map, values: &[f64]) -> Vec<(Color, Vec<[Xy; 2]>)> {
    let (columns, [dx, dy]) = (map.grid.xs.len().max(1), map.cell());
    let mut tiles: Vec<Vec<[Xy; 2]>> = vec![Vec::new(); STEPS + 1];
    // The rectangles ending at the row below: (first, end column, step) → index.
    let mut open: Vec<((usize, usize, usize), usize)> = Vec::new();
    for (j, row) in values.chunks(columns).enumerate() {
        let y1 = map.y[0] + (j + 1) as f64 * dy;
        let mut next = Vec::new();
        let mut i = 0;
        while i < row.len() {
            let s = step(row[i]);
            let mut e = i + 1;
            while e < row.len() && step(row[e]) == s {
                e += 1;
            }
            if let Some(k) = s {
                let key = (i, e, k);
                match open.iter().find(|(o, _)| *o == key) {
                    Some(&(_, at)) => {
                        tiles[k][at][1][1] = y1;
                        next.push((key, at));
                    }
                    None => {
                        let y0 = map.y[0] + j as f64 * dy;
                        let (x0, x1) = (map.x[0] + i as f64 * dx, map.x[0] + e as f64 * dx);
                        tiles[k].push([[x0, y0], [x1, y1]]);
                        next.push((key, tiles[k].len() - 1));
                    }
                }
            }
            i = e;
        }
        open = next;
    }
    tiles
        .into_iter()
        .enumerate()
        .map(|(k, t)| (colour(k), t))
        .collect()
}

/// The rings of a region as one line with gaps, each ring closed.
fn outline(region: &Region) -> Vec<Xy> {
    let mut points = Vec::new();
    for g in region.polygons() {
        for ring in std::iter::once(&g.exterior).chain(&g.holes) {
            if let Some(&first) = ring.first() {
                if !points.is_empty() {
                    points.push([f64::NAN, f64::NAN]);
                }
                points.extend_from_slice(ring);
                points.push(first);
            }
        }
    }
    points
}

/// One panel: the map of one function, its contours and the crisp curve.
fn panel(
    title: &str,
    map: &Map,
    values: &[f64],
    contours: &[(f64, Region)],
    crisp: &t2spline::job::Points,
    aspect: Aspect,
) -> Panel {
    let mut p = Projection::new((0, 1), false).panel(aspect);
    p.title = Some(title.to_owned());
    p.push(
        "map",
        Mark::Tiles {
            tiles: cells(map, values),
        },
    );
    // All levels as one line with gaps: one element each for the halo and
    // the contour.
    let mut line: Vec<Xy> = Vec::new();
    for (_, r) in contours {
        if !line.is_empty() {
            line.push([f64::NAN, f64::NAN]);
        }
        line.extend(outline(r));
    }
    for (key, stroke) in [("halo", halo_stroke()), ("contour", contour_stroke())] {
        let mark = if line.is_empty() {
            Mark::Empty
        } else {
            Mark::Line {
                points: line.clone(),
                stroke,
            }
        };
        p.push(key, mark);
    }
    crisp_curve(&mut p, crisp, (0, 1));
    p
}

/// The colour bar of the grades.
fn colorbar() -> ColorBar {
    ColorBar {
        label: "grade".to_owned(),
        stops: (0..=STEPS)
            .map(|k| (k as f64 / STEPS as f64, colour(k)))
            .collect(),
        marks: Vec::new(),
    }
}

/// The subtitle: what a grade is, and how high the lower grades reach.
fn subtitle(heights: &[f64]) -> String {
    let reach = match heights {
        [h] if *h < 1.0 => format!("; lower grades reach h = {}", short(*h, 4)),
        [lo, .., hi] => format!(
            "; lower grades reach the heights h, {} to {}",
            short(*lo, 4),
            short(*hi, 4)
        ),
        _ => String::new(),
    };
    format!("the grade of a point is the largest α whose region holds it{reach}")
}

/// The `membership` figure of a plane curve job: the maps of `mu_upper`
/// and `mu_lower` side by side (one colour bar, grades rounded to a tenth),
/// the regions at [`CONTOUR_LEVELS`] outlined, the crisp curve on top.
///
/// # Errors
/// [`Error::Planar`] for a space curve or a surface; [`Error::Core`] if a
/// computation fails (never for a validated job).
pub fn membership_figure(job: &Job, scene: &CurveScene<'_>) -> Result<Figure, Error> {
    let curve = set_view::planar(&job.model)?;
    let map = set_view::membership_map(curve)?;
    let (crisp, aspect) = (&scene.r.samples.crisp, scene.aspect);
    let (upper, lower) = rayon::join(
        || set_view::contours(curve, Membership::Upper, &CONTOUR_LEVELS),
        || set_view::contours(curve, Membership::Lower, &CONTOUR_LEVELS),
    );
    let (upper, lower) = (upper?, lower?);
    let panels = vec![
        panel(
            "upper grade μ_upper",
            &map,
            &map.grid.upper,
            &upper,
            crisp,
            aspect,
        ),
        panel(
            "lower grade μ_lower",
            &map,
            &map.grid.lower,
            &lower,
            crisp,
            aspect,
        ),
    ];
    let levels: Vec<String> = CONTOUR_LEVELS.iter().map(|a| short(*a, 2)).collect();
    let legend = vec![
        LegendEntry::line("crisp curve", crisp_stroke()),
        LegendEntry::line(
            &format!("region outlines at α = {}", levels.join(", ")),
            contour_stroke(),
        ),
    ];
    let heights = job.model.heights();
    let [columns, rows] = [map.grid.xs.len(), map.grid.ys.len()];
    Ok(Figure {
        colorbar: Some(colorbar()),
        notes: vec![format!(
            "Grades of the centres of {columns} × {rows} cells, each coloured by its grade rounded to 0.1; the outlines are the regions themselves."
        )],
        ..Figure::new(
            "membership",
            "The fuzzy curve as a set: its footprint of uncertainty in the plane",
            subtitle(&heights),
            panels,
            legend,
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grades_round_to_tenths_and_zero_is_left_out() {
        assert_eq!(step(0.0), None);
        assert_eq!(step(0.04), Some(0));
        assert_eq!(step(0.26), Some(3));
        assert_eq!(step(1.0), Some(10));
    }
}
