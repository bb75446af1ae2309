//! The `envelope-width` figure of a terrain: how far apart the least and
//! the greatest height of the fuzzy surface lie above each plan point at
//! the job's alpha (docs/method.md §12), per membership function, as maps
//! over the plan with one colour bar.

use super::bins::Bins;
use super::plan_tiles::tiles;
use crate::chart::paint::Fill;
use crate::chart::scene::{Figure, LegendEntry, Mark, Panel};
use crate::chart::ticks::short;
use crate::terrain_view::WidthMap;

/// The functions' names in the panels' titles.
const NAMES: [&str; 3] = ["upper (UMF)", "primary", "lower (LMF)"];

/// The `envelope-width` figure of `map`: a panel per membership function
/// with a cut at the map's alpha (with `every_panel`, as the report needs
/// at every slider stop, all three, a function without a cut shown empty
/// with a line saying so), each cell coloured by `greatest − least` in
/// [`Bins::COUNT`] steps from 0 to the largest width of the upper function,
/// NODATA cells (no admissible surface above them) left blank.
#[must_use]
pub fn width_figure(map: &WidthMap, heights: &[f64], every_panel: bool) -> Figure {
    let bins = Bins { max: map.max() };
    let [x0, y0, x1, y1] = map.grid.extent();
    let alpha = short(map.alpha, 4);
    let mut panels = Vec::new();
    for (name, widths) in NAMES.iter().zip(&map.widths) {
        if widths.is_none() && !every_panel {
            continue;
        }
        let mut p = Panel::curves("x", "y");
        p.title = Some(format!("{name} width"));
        p.x_range = Some([x0, x1]);
        p.y_range = Some([y0, y1]);
        let t = widths.as_deref().map_or_else(Vec::new, |w| {
            tiles(map.grid.extent(), map.grid.shape(), w, |v| {
                v.is_finite().then(|| bins.colour(v))
            })
        });
        p.push("cells", Mark::Tiles { tiles: t });
        let label = match widths {
            Some(_) => Mark::Empty,
            // A fixed text, not a placed label: a placed one has a part
            // of its own, and the report's frames must keep their parts.
            None => Mark::Text {
                at: [0.5 * (x0 + x1), 0.5 * (y0 + y1)],
                text: format!("no cut at α = {alpha}"),
            },
        };
        p.push("absent", label);
        panels.push(p);
    }
    let [nx, ny] = map.grid.shape();
    let mut notes = vec![format!(
        "The envelope on {nx} × {ny} cells of the plan extent, each coloured by the width at its centre, rounded to one of {} steps; blank cells: NODATA (no admissible surface above them). t2spline envelope --grid {nx},{ny} --alpha {alpha} gives the numbers.",
        Bins::COUNT
    )];
    if map.widths[2].is_none() {
        let h = heights
            .iter()
            .map(|h| short(*h, 4))
            .collect::<Vec<_>>()
            .join(", ");
        notes.push(format!(
            "The lower function has no cut at α = {alpha}, above its height h = {h}."
        ));
    }
    let legend = vec![LegendEntry::area(
        "cell coloured by the width greatest − least height",
        Fill {
            color: bins.colour(0.5 * bins.max),
            opacity: 1.0,
        },
    )];
    Figure {
        colorbar: Some(bins.colorbar(
            "width (units of z)",
            vec![(bins.max, format!("max {}", short(bins.max, 4)))],
        )),
        notes,
        ..Figure::new(
            "envelope-width",
            "Envelope width: how far the fuzzy surface's height can move",
            format!(
                "greatest − least height at α = {alpha}, per membership function; largest width {}",
                short(bins.max, 4)
            ),
            panels,
            legend,
        )
    }
}
