//! The legend, the colour bar and the notes as SVG elements.

use std::fmt::Write as _;

use super::number::coord;
use crate::chart::font::cap_height;
use crate::chart::geometry::Rect;
use crate::chart::layout::{LegendLayout, LEGEND_ROW, LEGEND_SWATCH, NOTE_ROW};
use crate::chart::paint::{font_size, Fill, INK, MUTED, WHITE};
use crate::chart::scene::{ColorBar, LegendEntry};
use crate::chart::ticks::short;

use super::element::{rect_attrs, stroke_attrs, text_el};
use super::marks::markers;

pub(super) fn legend(entries: &[LegendEntry], l: &LegendLayout) -> String {
    let r = l.rect;
    let mut s = format!(
        "<rect{} fill=\"{WHITE}\" fill-opacity=\"0.92\" stroke=\"#b0b0b0\" stroke-width=\"0.8\" rx=\"2\"/>\n",
        rect_attrs(&r)
    );
    for (e, [x, y]) in entries.iter().zip(l.entries(entries.len())) {
        let mid = y + 0.5 * (LEGEND_ROW - 2.0);
        if let Some(Fill { color, opacity }) = &e.fill {
            let _ = writeln!(
                s,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"10\" fill=\"{color}\" fill-opacity=\"{}\"/>",
                coord(x),
                coord(mid - 5.0),
                coord(LEGEND_SWATCH),
                coord(*opacity)
            );
        }
        if let Some(st) = &e.line {
            let _ = writeln!(
                s,
                "<path d=\"M{} {}h{}\" {}/>",
                coord(x),
                coord(mid),
                coord(LEGEND_SWATCH),
                stroke_attrs(st)
            );
        }
        if let Some(m) = &e.marker {
            s.push_str(&markers(&[[x + 0.5 * LEGEND_SWATCH, mid]], m));
        }
        s.push_str(&text_el(
            x + LEGEND_SWATCH + 6.0,
            mid + 0.5 * cap_height(font_size::LEGEND),
            font_size::LEGEND,
            "start",
            "",
            &e.label,
        ));
    }
    s
}

pub(super) fn colorbar(cb: &ColorBar, r: Rect) -> String {
    let n = cb.stops.len().max(1);
    let h = r.h / n as f64;
    // Swatch k (value stops[k]) is centred at this y; low values at the bottom.
    let centre = |k: f64| r.bottom() - (k + 0.5) * h;
    let mut s = String::new();
    for (k, (v, color)) in cb.stops.iter().enumerate() {
        let y = centre(k as f64);
        let _ = writeln!(
            s,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{color}\"/>",
            coord(r.x),
            coord(y - 0.5 * h),
            coord(r.w),
            coord(h)
        );
        let _ = writeln!(
            s,
            "<path d=\"M{} {}h4\" stroke=\"{INK}\" stroke-width=\"1\"/>",
            coord(r.right()),
            coord(y)
        );
        s.push_str(&text_el(
            r.right() + 7.0,
            y + 0.5 * cap_height(font_size::TICK),
            font_size::TICK,
            "start",
            "",
            &short(*v, 3),
        ));
    }
    let _ = writeln!(
        s,
        "<rect{} fill=\"none\" stroke=\"{INK}\" stroke-width=\"0.8\"/>",
        rect_attrs(&r)
    );
    s.push_str(&text_el(
        r.x + 0.5 * r.w,
        r.y - 8.0,
        font_size::AXIS,
        "middle",
        "",
        &cb.label,
    ));
    // Marks sit at their value, interpolated between swatch centres.
    let values: Vec<f64> = cb.stops.iter().map(|(v, _)| *v).collect();
    for (v, text) in &cb.marks {
        let k = match values.iter().position(|&s| s >= *v) {
            Some(0) | None if values.is_empty() => 0.0,
            Some(0) => 0.0,
            None => (values.len() - 1) as f64,
            Some(j) => (j - 1) as f64 + (v - values[j - 1]) / (values[j] - values[j - 1]),
        };
        let y = centre(k);
        let _ = writeln!(
            s,
            "<path d=\"M{} {}l-6 -4v8Z\" fill=\"{INK}\"/>",
            coord(r.x - 1.0),
            coord(y)
        );
        s.push_str(&text_el(
            r.x - 9.0,
            y + 0.5 * cap_height(font_size::TICK),
            font_size::TICK,
            "end",
            "",
            text,
        ));
    }
    s
}

/// Notes in small muted type, one per line, from `top`.
pub(super) fn notes(notes: &[String], top: f64) -> String {
    let mut s = String::new();
    for (k, n) in notes.iter().enumerate() {
        let _ = writeln!(
            s,
            "<text x=\"10\" y=\"{}\" font-size=\"{}\" fill=\"{MUTED}\">{}</text>",
            coord(top + (k as f64 + 1.0) * NOTE_ROW - 3.0),
            font_size::NOTE,
            super::element::escape(n)
        );
    }
    s
}
