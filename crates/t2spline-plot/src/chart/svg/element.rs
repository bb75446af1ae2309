//! SVG attributes and elements written as text: escaping, a rectangle's
//! position, a stroke, a list of points and a text element.

use std::fmt::Write as _;

use super::number::coord;
use crate::chart::geometry::{Px, Rect};
use crate::chart::paint::{Stroke, INK};

/// Escapes text for SVG/XML.
#[must_use]
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// `<rect>` position attributes of `r`: ` x="…" y="…" width="…" height="…"`.
pub(crate) fn rect_attrs(r: &Rect) -> String {
    format!(
        " x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"",
        coord(r.x),
        coord(r.y),
        coord(r.w),
        coord(r.h)
    )
}

/// The attributes of an unfilled line drawn with `s`: colour, width, round
/// joins and the dash pattern, if any.
pub(crate) fn stroke_attrs(s: &Stroke) -> String {
    let mut a = format!(
        "fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
        s.color,
        coord(s.width)
    );
    if let Some(d) = s.dash {
        let _ = write!(a, " stroke-dasharray=\"{d}\"");
    }
    a
}

/// The value of a `points` attribute: `x,y` pairs separated by spaces.
pub(crate) fn points_attr(pts: &[Px]) -> String {
    let mut s = String::with_capacity(pts.len() * 14);
    for (k, p) in pts.iter().enumerate() {
        if k > 0 {
            s.push(' ');
        }
        let _ = write!(s, "{},{}", coord(p[0]), coord(p[1]));
    }
    s
}

/// A `<text>` element at `(x, y)` in ink, anchored by `anchor`, with `extra`
/// attributes and `text` escaped.
pub(crate) fn text_el(x: f64, y: f64, size: f64, anchor: &str, extra: &str, text: &str) -> String {
    format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"{size}\" text-anchor=\"{anchor}\" fill=\"{INK}\"{extra}>{}</text>\n",
        coord(x),
        coord(y),
        escape(text)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a < b & \"c\""), "a &lt; b &amp; &quot;c&quot;");
    }
}
