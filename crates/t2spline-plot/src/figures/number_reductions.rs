//! The type-2 literature's reductions of one number (docs/method.md §9) drawn into
//! the `number` figure, beside the paper's: the centroid interval
//! `[c_l, c_r]`, the type-reduced set of the alpha-planes
//! `z ↦ [c_l(z), c_r(z)]` (its membership grade is `z`, so it shares the
//! figure's vertical axis), and the defuzzified values of the other three
//! reductions, each on a row of its own below the axis.

use std::f64::consts::PI;

use t2spline::{Alpha, Nt2Number, TypeReduction};

use super::style::{reduction_label, reduction_marker, reduction_stroke};
use crate::chart::paint::Stroke;
use crate::chart::scene::{LegendEntry, Mark, Panel, Xy};
use crate::chart::ticks::short;

/// Levels `z` at which the alpha-planes' type-reduced set is drawn,
/// clustered at both ends (`z = (1 − cos πk/64)/2`), where `c_l(z)` and
/// `c_r(z)` change fastest.
const LEVELS: usize = 65;

/// The rows below the axis where the reductions are drawn, one each, so that
/// close values do not hide each other: the centroid interval with its
/// midpoint, the alpha-plane value, the Nie–Tan value.
const ROWS: [(TypeReduction, f64); 3] = [
    (TypeReduction::Centroid, -0.05),
    (TypeReduction::AlphaPlanes, -0.1),
    (TypeReduction::NieTan, -0.15),
];

/// The lowest value of the vertical axis, below the rows.
const BOTTOM: f64 = -0.19;

/// Half the height of the interval's end ticks.
const TICK: f64 = 0.018;

/// Adds the reductions of `x` to the number figure's `panel` (keys
/// `alpha-planes-set`, `centroid-interval` and `defuzzified-<name>` for the
/// three) below and above its axis, and returns their legend entries. None
/// of these reductions depends on alpha.
pub(super) fn add_reductions(panel: &mut Panel, x: &Nt2Number) -> Vec<LegendEntry> {
    let planes: Vec<(f64, t2spline::Interval)> = (0..LEVELS)
        .map(|k| 0.5 * (1.0 - (PI * k as f64 / (LEVELS - 1) as f64).cos()))
        // Values in [0, 1] (clamped against rounding) are valid levels.
        .filter_map(|z| Alpha::try_new(z.clamp(0.0, 1.0)).ok())
        .map(|z| (z.get(), x.alpha_plane_centroid(z)))
        .collect();
    let mut set: Vec<Xy> = planes.iter().map(|(z, c)| [c.left(), *z]).collect();
    set.extend(planes.iter().rev().map(|(z, c)| [c.right(), *z]));
    let set_stroke = Stroke {
        width: 1.4,
        ..reduction_stroke(TypeReduction::AlphaPlanes)
    };
    panel.push(
        "alpha-planes-set",
        Mark::Line {
            points: set,
            stroke: set_stroke.clone(),
        },
    );
    let c = x.centroid();
    let bar = ROWS[0].1;
    let bar_stroke = Stroke {
        width: 2.4,
        ..reduction_stroke(TypeReduction::Centroid)
    };
    panel.push(
        "centroid-interval",
        Mark::Segments {
            segments: vec![
                [[c.left(), bar], [c.right(), bar]],
                [[c.left(), bar - TICK], [c.left(), bar + TICK]],
                [[c.right(), bar - TICK], [c.right(), bar + TICK]],
            ],
            stroke: bar_stroke.clone(),
        },
    );
    panel.y_range = panel.y_range.map(|[_, top]| [BOTTOM, top]);
    let mut legend = Vec::new();
    for (method, row) in ROWS {
        // The three do not depend on alpha; any level gives the same value.
        let d = x.reduce(method, Alpha::ZERO).defuzzified();
        panel.push(
            format!("defuzzified-{}", method.name()),
            Mark::Markers {
                points: vec![[d, row]],
                marker: reduction_marker(method),
            },
        );
        let value = short(d, 4);
        legend.push(match method {
            TypeReduction::Centroid => LegendEntry::line_marker(
                &format!(
                    "centroid [c_l, c_r] = [{}, {}], midpoint {value}",
                    short(c.left(), 4),
                    short(c.right(), 4)
                ),
                bar_stroke.clone(),
                reduction_marker(method),
            ),
            TypeReduction::AlphaPlanes => LegendEntry::line_marker(
                &format!("alpha-planes z ↦ [c_l(z), c_r(z)], defuzzified {value}"),
                set_stroke.clone(),
                reduction_marker(method),
            ),
            _ => LegendEntry::marker(
                &format!("{}: {value}", reduction_label(method)),
                reduction_marker(method),
            ),
        });
    }
    legend
}

/// The number figure's subtitle when the run's reduction is not the
/// paper's: that reduction's left, right and defuzzified value.
pub(super) fn reduction_subtitle(x: &Nt2Number, method: TypeReduction) -> String {
    let r = x.reduce(method, Alpha::ZERO);
    let ends = if method == TypeReduction::NieTan {
        String::new()
    } else {
        format!("[{}, {}], ", short(r.left(), 4), short(r.right(), 4))
    };
    format!(
        "{}: {ends}defuzzified {} (α is used by the paper's reduction only)",
        reduction_label(method),
        short(r.defuzzified(), 4)
    )
}
