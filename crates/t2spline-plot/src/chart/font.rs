//! The bundled font, DejaVu Sans (Bitstream Vera licence, `fonts/`), and text
//! measurement with its advance widths.
//!
//! Figures are laid out with this font's metrics and the PNG renderer uses only
//! this font, so text renders the same on a machine without any fonts. The SVG
//! names it first in its font list and falls back to common sans-serif fonts.

use std::sync::OnceLock;

/// The font file, DejaVu Sans 2.37 from Debian's `fonts-dejavu-core`.
pub const FONT_BYTES: &[u8] = include_bytes!("../../fonts/DejaVuSans.ttf");

/// The family name inside [`FONT_BYTES`].
#[cfg(any(feature = "png", test))]
pub const FONT_FAMILY: &str = "DejaVu Sans";

/// The `font-family` list written into SVG files.
pub const SVG_FONT_STACK: &str = "'DejaVu Sans', Verdana, 'Bitstream Vera Sans', sans-serif";

struct Metrics {
    units_per_em: f64,
    /// Advance widths of U+0000..U+0400 (Latin, Greek, Cyrillic), font units.
    table: Vec<u16>,
    /// Advance width used for characters the table lacks.
    fallback: u16,
    face: ttf_parser::Face<'static>,
}

fn metrics() -> Option<&'static Metrics> {
    static METRICS: OnceLock<Option<Metrics>> = OnceLock::new();
    METRICS
        .get_or_init(|| {
            let face = ttf_parser::Face::parse(FONT_BYTES, 0).ok()?;
            let advance = |c: char| {
                face.glyph_index(c)
                    .and_then(|g| face.glyph_hor_advance(g))
                    .unwrap_or(0)
            };
            let table = (0u32..0x400)
                .map(|u| char::from_u32(u).map_or(0, advance))
                .collect();
            let fallback = advance('0');
            Some(Metrics {
                units_per_em: f64::from(face.units_per_em()),
                table,
                fallback,
                face,
            })
        })
        .as_ref()
}

/// The width in pixels of `text` set in the bundled font at `size` pixels
/// (sum of advance widths; kerning ignored, which DejaVu Sans barely uses).
#[must_use]
pub fn text_width(text: &str, size: f64) -> f64 {
    // The bundled font always parses (a test checks it); if it did not, an
    // average width keeps layout usable.
    let Some(m) = metrics() else {
        return 0.6 * size * text.chars().count() as f64;
    };
    let units: f64 = text
        .chars()
        .map(|c| {
            let u = c as usize;
            let w = if u < m.table.len() {
                m.table[u]
            } else {
                m.face
                    .glyph_index(c)
                    .and_then(|g| m.face.glyph_hor_advance(g))
                    .unwrap_or(m.fallback)
            };
            f64::from(w)
        })
        .sum();
    units / m.units_per_em * size
}

/// Height of a line of text at `size` pixels: ascent to descent, about 1.16 em
/// for DejaVu Sans.
#[must_use]
pub fn line_height(size: f64) -> f64 {
    1.17 * size
}

/// Height above the baseline of capital letters and digits, for centring text
/// vertically: about 0.73 em for DejaVu Sans.
#[must_use]
pub fn cap_height(size: f64) -> f64 {
    0.73 * size
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bundled_font_parses_and_has_the_glyphs_we_use() {
        let m = metrics().expect("bundled font parses");
        for c in "αβ–−≤>₀₁₂₃₄₅₆₇₈₉·×".chars() {
            assert!(m.face.glyph_index(c).is_some(), "no glyph for {c}");
        }
        assert_eq!(
            m.face
                .names()
                .into_iter()
                .find(|n| n.name_id == ttf_parser::name_id::FAMILY && n.is_unicode())
                .and_then(|n| n.to_string()),
            Some(FONT_FAMILY.to_owned())
        );
    }

    #[test]
    fn widths_add_up_and_scale() {
        let a = text_width("ab", 10.0);
        assert!((a - text_width("a", 10.0) - text_width("b", 10.0)).abs() < 1e-12);
        assert!((text_width("ab", 20.0) - 2.0 * a).abs() < 1e-12);
        let w = text_width("alpha", 10.0);
        assert!(w > 20.0 && w < 35.0, "{w}");
        // DejaVu Sans digits are 0.636 em wide.
        assert!((text_width("0", 100.0) - 63.6).abs() < 0.1);
    }
}
