//! The crisp surface as every stage draws it: its grey and its legend.

use crate::chart::paint::{Color, Fill};
use crate::chart::scene::LegendEntry;
use crate::figures::style::{crisp_marker, polygon_stroke};

/// The colour of an opaque surface before shading: a light grey.
pub const SURFACE: Color = Color(0xdc, 0xdc, 0xdc);

/// The legend entries of the shaded crisp surface and the crisp control net.
#[must_use]
pub fn crisp_legend() -> Vec<LegendEntry> {
    vec![
        LegendEntry::area(
            "crisp surface (shaded), isoparametric lines",
            Fill {
                color: SURFACE,
                opacity: 1.0,
            },
        ),
        LegendEntry::line_marker(
            "crisp control net and points",
            polygon_stroke(),
            crisp_marker(),
        ),
    ]
}
