//! The `shoreline` figure of a terrain: the fuzzy contour at the datum
//! `z = 0` (docs/method.md §13), the plan region where a surface whose
//! heights lie inside their cuts can cross the datum, per membership
//! function, filled over the crisp surface's contour map.

use t2spline::set::{Contour, Region};

use crate::chart::paint::Fill;
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel, Xy};
use crate::chart::ticks::short;
use crate::figures::style::{crisp_stroke, level_stroke, lower_band, primary_band, upper_band};

/// The rings of a region (exteriors and holes), for [`Mark::Region`].
fn rings(region: Option<&Region>) -> Vec<Vec<Xy>> {
    region
        .map(|r| {
            r.polygons()
                .iter()
                .flat_map(|g| std::iter::once(&g.exterior).chain(&g.holes))
                .cloned()
                .collect()
        })
        .unwrap_or_default()
}

/// Polylines as one line with gaps.
fn joined(lines: &[Vec<Xy>]) -> Vec<Xy> {
    let mut points = Vec::new();
    for l in lines {
        if !points.is_empty() {
            points.push([f64::NAN, f64::NAN]);
        }
        points.extend_from_slice(l);
    }
    points
}

/// A line, or nothing where it has no points.
fn line_or_empty(points: Vec<Xy>, stroke: crate::chart::paint::Stroke) -> Mark {
    if points.is_empty() {
        Mark::Empty
    } else {
        Mark::Line { points, stroke }
    }
}

/// The band fills: upper, primary, lower.
fn fills() -> [Fill; 3] {
    [upper_band(), primary_band(), lower_band()]
}

/// The `shoreline` figure: the bands of `contour`'s level `k` (upper,
/// primary, lower: nested, each drawn over the one it lies in; a function
/// without a cut there draws nothing), over the crisp surface's contour
/// lines `map` (height, polylines), and the crisp surface's shoreline.
/// The extent is the contour grid's, so the figure is the same size at
/// every level.
#[must_use]
pub fn shoreline_figure(contour: &Contour, k: usize, map: &[(f64, Vec<Vec<Xy>>)]) -> Figure {
    let [x0, y0, x1, y1] = contour.grid.extent();
    let mut p = Panel::curves("x", "y");
    p.x_range = Some([x0, x1]);
    p.y_range = Some([y0, y1]);
    p.title = Some("plan".to_owned());
    let levels: Vec<Vec<Xy>> = map
        .iter()
        .filter(|(z, _)| *z != contour.z)
        .flat_map(|(_, lines)| lines.iter().cloned())
        .collect();
    p.push("levels", line_or_empty(joined(&levels), level_stroke()));
    let level = contour.levels.get(k);
    let names = ["upper", "primary", "lower"];
    let mut areas = Vec::new();
    for (f, (name, fill)) in names.iter().zip(fills()).enumerate() {
        let region = level.and_then(|l| match f {
            0 => l.upper.as_ref(),
            1 => l.primary.as_ref(),
            _ => l.lower.as_ref(),
        });
        areas.push(region.map(Region::area));
        let rings = rings(region);
        let mark = if rings.is_empty() {
            Mark::Empty
        } else {
            Mark::Region { rings, fill }
        };
        p.push(format!("band-{name}"), mark);
    }
    p.push(
        "crisp",
        line_or_empty(joined(&contour.crisp), crisp_stroke()),
    );
    let alpha = level.map_or(f64::NAN, |l| l.alpha);
    let heights: Vec<String> = map.iter().map(|(z, _)| short(*z, 4)).collect();
    let step = match map {
        [(a, _), (b, _), ..] => format!("every {}", short(b - a, 4)),
        _ => String::new(),
    };
    let legend = vec![
        LegendEntry::area("upper (UMF) band", upper_band()),
        LegendEntry::area("primary band", primary_band()),
        LegendEntry::area("lower (LMF) band, up to h", lower_band()),
        LegendEntry::line("crisp surface's shoreline z = 0", crisp_stroke()),
        LegendEntry::line(
            format!("crisp surface's contours {step}").trim_end(),
            level_stroke(),
        ),
    ];
    let area_text = |a: Option<f64>| a.map_or_else(|| "no cut".to_owned(), |a| short(a, 4));
    let [nx, ny] = contour.grid.shape();
    let notes = vec![
        format!(
            "Band areas (plan units²): upper {}, primary {}, lower {}.",
            area_text(areas[0]),
            area_text(areas[1]),
            area_text(areas[2])
        ),
        format!(
            "Bands traced on {nx} × {ny} cells: within {} in the plan (a cell's diagonal) and {} in height of where a surface can cross z = 0; contours at z = {}.",
            short(contour.tolerance, 3),
            short(contour.height_tolerance, 3),
            heights.join(", ")
        ),
    ];
    Figure {
        notes,
        ..Figure::new(
            "shoreline",
            "Fuzzy shoreline: where the surface can cross the datum z = 0",
            format!(
                "the bands at α = {} of every surface whose heights lie inside their cuts; t2spline contour --z 0 --alpha {} gives the polygons",
                short(alpha, 4),
                short(alpha, 4)
            ),
            vec![p],
            legend,
        )
    }
}
