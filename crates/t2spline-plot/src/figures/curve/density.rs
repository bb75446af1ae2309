//! How much per-point detail a curve figure can show: markers, interval bars
//! and names need room, and a job of hundreds of control points has little.
//!
//! The figure builders work in data coordinates, so the room is estimated
//! from the data: the median distance between consecutive crisp control
//! points, in pixels of a panel of typical size. Thresholds are in pixels.

use t2spline::job::Points;

use super::projection::Projection;
use crate::figures::aspect::Aspect;

/// Plot width of a panel of a one-panel figure, in pixels (about what the
/// layout gives it).
const PANEL_PX: f64 = 560.0;
/// Plot width of each panel of a three-panel figure.
const PANEL_PX_3: f64 = 340.0;
/// The fewest pixels between neighbouring control points for markers at the
/// derived control points (cut ends, type-reduced, defuzzified), for the
/// stage-1 interval bars and for full-size crisp markers.
const MARKERS_PX: f64 = 18.0;
/// The fewest pixels for (small) markers at the crisp control points.
const CRISP_PX: f64 = 3.0;
/// Names need about this many pixels between labelled points.
const NAME_PX: f64 = 30.0;
/// The most names a panel tries to place.
const MAX_NAMES: usize = 60;

/// What per-point detail fits a figure, and notes on what was left out.
#[derive(Clone, Debug, PartialEq)]
pub struct Density {
    /// Name every `name_stride`-th control point (and the last); 0 for none.
    pub name_stride: usize,
    /// Markers at the crisp control points.
    pub crisp_markers: bool,
    /// Markers at the derived control points, and the bars of the fuzzy
    /// intervals (stage 1).
    pub markers: bool,
    /// Median distance between neighbouring control points, in pixels.
    pub spacing_px: f64,
    /// The number of control points.
    pub count: usize,
}

impl Density {
    /// The detail that fits the control points `crisp` drawn in the first of
    /// `projections` with `aspect`.
    #[must_use]
    pub fn of(crisp: &Points, projections: &[Projection], aspect: Aspect) -> Density {
        let count = crisp.len();
        let ij = projections.first().map_or((0, 1), |p| p.axes);
        let panel = if projections.len() > 1 {
            PANEL_PX_3
        } else {
            PANEL_PX
        };
        let spacing_px = spacing(crisp, ij, panel, aspect);
        let name_stride = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000]
            .into_iter()
            .find(|&k| k as f64 * spacing_px >= NAME_PX && count.div_ceil(k) <= MAX_NAMES)
            .unwrap_or(0);
        Density {
            name_stride,
            crisp_markers: spacing_px >= CRISP_PX,
            markers: spacing_px >= MARKERS_PX,
            spacing_px,
            count,
        }
    }

    /// Whether control point `k` gets a name.
    #[must_use]
    pub fn named(&self, k: usize) -> bool {
        self.name_stride > 0 && (k % self.name_stride == 0 || k + 1 == self.count)
    }

    /// A note on what the figure leaves out: thinned names, crisp markers,
    /// and `left_out` (what the builder dropped for want of room, e.g.
    /// "cut ends not marked"); `None` when nothing is.
    #[must_use]
    pub fn note(&self, left_out: Option<&str>) -> Option<String> {
        let mut parts = Vec::new();
        match self.name_stride {
            0 => parts.push("no names".to_owned()),
            1 => {}
            2 => parts.push("names on every other point where there is room".to_owned()),
            k => parts.push(format!("names on every {k}th point where there is room")),
        }
        if let Some(what) = left_out {
            parts.push(what.to_owned());
        }
        if !self.crisp_markers {
            parts.push("control points not marked".to_owned());
        }
        (!parts.is_empty()).then(|| {
            format!(
                "{} control points about {:.0} px apart: {}.",
                self.count,
                self.spacing_px,
                parts.join("; ")
            )
        })
    }
}

/// The median distance between consecutive points of projection `ij`, in
/// pixels of a panel `panel` pixels wide showing their bounding box.
fn spacing(points: &Points, (i, j): (usize, usize), panel: f64, aspect: Aspect) -> f64 {
    let (x, y) = (points.coord(i), points.coord(j));
    let range = |v: &[f64]| {
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &c| {
                (a.min(c), b.max(c))
            });
        (hi - lo).max(f64::MIN_POSITIVE)
    };
    let (wx, wy) = (range(x), range(y));
    // Pixels per data unit on each axis; the plot is about 0.6 as tall as wide
    // unless the data are taller.
    let (sx, sy) = match aspect {
        Aspect::Equal => {
            let s = (panel / wx).min(panel / wy);
            (s, s)
        }
        Aspect::Auto => (panel / wx, 0.6 * panel / wy),
    };
    let mut gaps: Vec<f64> = x
        .windows(2)
        .zip(y.windows(2))
        .map(|(a, b)| ((a[1] - a[0]) * sx).hypot((b[1] - b[0]) * sy))
        .collect();
    if gaps.is_empty() {
        return f64::INFINITY;
    }
    let mid = gaps.len() / 2;
    *gaps.select_nth_unstable_by(mid, f64::total_cmp).1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(n: usize) -> Points {
        let p: Vec<[f64; 2]> = (0..n).map(|i| [i as f64, (i % 2) as f64]).collect();
        Points::from_points(&p)
    }

    fn xy() -> Vec<Projection> {
        vec![Projection::new((0, 1), false)]
    }

    #[test]
    fn few_points_show_everything_and_many_are_thinned() {
        let few = Density::of(&line(5), &xy(), Aspect::Equal);
        assert_eq!(few.name_stride, 1);
        assert!(few.markers && few.crisp_markers);
        assert_eq!(few.note(None), None);
        let many = Density::of(&line(1000), &xy(), Aspect::Equal);
        assert!(many.name_stride >= 20, "{many:?}");
        assert!(!many.markers);
        let note = many.note(Some("cut ends not marked")).unwrap();
        assert!(
            note.contains("1000 control points") && note.contains("cut ends not marked"),
            "{note}"
        );
        assert!(many.named(0) && many.named(999) && !many.named(1));
    }
}
