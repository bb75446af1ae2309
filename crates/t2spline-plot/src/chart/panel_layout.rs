//! A placed panel: its plot area in pixels, the range and ticks of each axis,
//! and the transform from data coordinates to pixels. What the layout
//! computes and what everything drawn on a panel (obstacles, labels, SVG)
//! reads.

use crate::chart::geometry::{Px, Rect};
use crate::chart::scene::Xy;
use crate::chart::ticks::tick_label;

/// One axis of a panel: its range and ticks.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisLayout {
    /// The data range shown.
    pub range: [f64; 2],
    /// Tick values.
    pub ticks: Vec<f64>,
    /// Decimals of the tick labels.
    pub decimals: usize,
}

impl AxisLayout {
    /// The tick labels.
    #[must_use]
    pub fn labels(&self) -> Vec<String> {
        self.ticks
            .iter()
            .map(|&t| tick_label(t, self.decimals))
            .collect()
    }
}

/// A placed panel.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelLayout {
    /// The plot area in pixels.
    pub plot: Rect,
    /// Horizontal axis.
    pub x: AxisLayout,
    /// Vertical axis.
    pub y: AxisLayout,
}

impl PanelLayout {
    /// Data coordinates to pixels.
    #[must_use]
    pub fn to_px(&self, p: Xy) -> Px {
        let [x0, x1] = self.x.range;
        let [y0, y1] = self.y.range;
        [
            self.plot.x + (p[0] - x0) / (x1 - x0) * self.plot.w,
            self.plot.bottom() - (p[1] - y0) / (y1 - y0) * self.plot.h,
        ]
    }

    /// The pixels of the marker centres that lie in the plot area (to within
    /// 0.01 px): markers are not clipped, so that one at the edge shows whole,
    /// but one whose centre lies outside a zoomed panel is left out.
    #[must_use]
    pub fn marker_px(&self, points: &[Xy]) -> Vec<Px> {
        let r = &self.plot;
        let shows = |px: &Px| {
            (r.x - 0.01..=r.right() + 0.01).contains(&px[0])
                && (r.y - 0.01..=r.bottom() + 0.01).contains(&px[1])
        };
        points
            .iter()
            .map(|&p| self.to_px(p))
            .filter(shows)
            .collect()
    }
}
