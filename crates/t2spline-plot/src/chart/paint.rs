//! The drawing vocabulary: colours, line styles, fills and markers, and the
//! palette. Which series of the method gets which is decided in one place,
//! `figures/style.rs`; the chart engine only draws them.
//!
//! Colours are the Okabe–Ito palette (distinguishable with the common colour
//! vision deficiencies); every series also differs in dash pattern, width or
//! marker shape, so a figure printed in grey stays readable. The alpha sweep
//! uses viridis, whose lightness rises monotonically with alpha.

use std::fmt;

/// An sRGB colour, written as `#rrggbb`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Color(pub u8, pub u8, pub u8);

impl fmt::Display for Color {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }
}

/// Black: crisp values and curves.
pub const BLACK: Color = Color(0x00, 0x00, 0x00);
/// Dark grey: axes and text.
pub const INK: Color = Color(0x22, 0x22, 0x22);
/// Mid grey: control polygons and reference lines.
pub const GREY: Color = Color(0x80, 0x80, 0x80);
/// Muted grey: notes.
pub const MUTED: Color = Color(0x55, 0x55, 0x55);
/// Light grey: grid lines.
pub const GRID: Color = Color(0xe4, 0xe4, 0xe4);
/// White: backgrounds, open markers and text halos.
pub const WHITE: Color = Color(0xff, 0xff, 0xff);
/// Okabe–Ito blue: the upper membership function and its layers.
pub const BLUE: Color = Color(0x00, 0x72, 0xb2);
/// Okabe–Ito bluish green: the primary membership function and its layers.
pub const GREEN: Color = Color(0x00, 0x9e, 0x73);
/// Okabe–Ito vermillion: the lower membership function and its layers.
pub const VERMILLION: Color = Color(0xd5, 0x5e, 0x00);
/// Okabe–Ito reddish purple: type-reduced values.
pub const PURPLE: Color = Color(0xcc, 0x79, 0xa7);
/// Okabe–Ito orange: the type-reduced right values.
pub const ORANGE: Color = Color(0xe6, 0x9f, 0x00);
/// Okabe–Ito sky blue.
pub const SKY: Color = Color(0x56, 0xb4, 0xe9);

/// How a line is drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Stroke {
    /// Colour.
    pub color: Color,
    /// Width in pixels (user units).
    pub width: f64,
    /// SVG dash array, `None` for solid.
    pub dash: Option<&'static str>,
}

impl Stroke {
    /// A solid line.
    #[must_use]
    pub const fn solid(color: Color, width: f64) -> Stroke {
        Stroke {
            color,
            width,
            dash: None,
        }
    }

    /// A dashed line with an SVG dash array such as `"6 3"`.
    #[must_use]
    pub const fn dashed(color: Color, width: f64, dash: &'static str) -> Stroke {
        Stroke {
            color,
            width,
            dash: Some(dash),
        }
    }
}

/// How an area is filled.
#[derive(Clone, Debug, PartialEq)]
pub struct Fill {
    /// Colour.
    pub color: Color,
    /// Opacity in `[0, 1]`.
    pub opacity: f64,
}

/// The outline of a marker.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A disc.
    Circle,
    /// An axis-aligned square.
    Square,
    /// A triangle pointing up.
    Triangle,
    /// A square turned by 45°.
    Diamond,
    /// A diagonal cross (drawn with the stroke only).
    Cross,
}

/// A marker drawn at a point.
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    /// Outline.
    pub shape: Shape,
    /// Size: the diameter of the circle the shape fits in, in pixels.
    pub size: f64,
    /// Outline colour.
    pub stroke: Color,
    /// Fill colour; `None` is an open marker (filled white).
    pub fill: Option<Color>,
}

impl Marker {
    /// A filled marker.
    #[must_use]
    pub const fn filled(shape: Shape, size: f64, color: Color) -> Marker {
        Marker {
            shape,
            size,
            stroke: color,
            fill: Some(color),
        }
    }

    /// An open marker (white inside).
    #[must_use]
    pub const fn open(shape: Shape, size: f64, color: Color) -> Marker {
        Marker {
            shape,
            size,
            stroke: color,
            fill: None,
        }
    }
}

/// Font sizes in pixels.
pub mod font_size {
    /// Figure title.
    pub const TITLE: f64 = 15.0;
    /// The line under the title.
    pub const SUBTITLE: f64 = 11.5;
    /// Axis labels and panel titles.
    pub const AXIS: f64 = 12.5;
    /// Tick labels.
    pub const TICK: f64 = 11.0;
    /// Legend entries.
    pub const LEGEND: f64 = 11.0;
    /// Labels placed on the data.
    pub const LABEL: f64 = 10.5;
    /// Notes under the figure.
    pub const NOTE: f64 = 10.0;
}

/// Viridis at `s` in `[0, 1]` (matplotlib's colour map, nine stops, linear in
/// between): dark purple at 0, yellow at 1, lightness rising throughout.
#[must_use]
pub fn viridis(s: f64) -> Color {
    const STOPS: [(u8, u8, u8); 9] = [
        (0x44, 0x01, 0x54),
        (0x47, 0x2d, 0x7b),
        (0x3b, 0x52, 0x8b),
        (0x2c, 0x72, 0x8e),
        (0x21, 0x91, 0x8c),
        (0x28, 0xae, 0x80),
        (0x5e, 0xc9, 0x62),
        (0xad, 0xdc, 0x30),
        (0xfd, 0xe7, 0x25),
    ];
    let s = if s.is_nan() { 0.0 } else { s.clamp(0.0, 1.0) };
    let x = s * (STOPS.len() - 1) as f64;
    // `x` lies in [0, 8], so the index fits.
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    Color(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_are_written_as_hex() {
        assert_eq!(VERMILLION.to_string(), "#d55e00");
    }

    #[test]
    fn viridis_ends_and_lightness_rises() {
        assert_eq!(viridis(0.0), Color(0x44, 0x01, 0x54));
        assert_eq!(viridis(1.0), Color(0xfd, 0xe7, 0x25));
        let luma =
            |c: Color| 0.299 * f64::from(c.0) + 0.587 * f64::from(c.1) + 0.114 * f64::from(c.2);
        let l: Vec<f64> = (0..=10)
            .map(|i| luma(viridis(f64::from(i) / 10.0)))
            .collect();
        assert!(l.windows(2).all(|w| w[0] < w[1]), "{l:?}");
    }
}
