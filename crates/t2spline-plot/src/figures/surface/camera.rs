//! The camera of surface figures: an orthographic view from a direction given
//! by azimuth and elevation, the box the data are scaled into, depth for the
//! painter's algorithm and Lambert shading from a fixed light.
//!
//! ```text
//! toward the viewer  d = (cos e·cos a, cos e·sin a, sin e)
//! screen right       r = (−sin a, cos a, 0)
//! screen up          u = d × r = (−sin e·cos a, −sin e·sin a, cos e)
//! box coordinates    qₖ = (pₖ − cₖ)·sₖ          (c the data's centre, s the scales)
//! screen point       (q·r, q·u),   depth q·d     (larger depth is nearer)
//! ```
//! `a` is the azimuth, the angle from the +x axis toward +y of the direction
//! to the viewer, and `e` the elevation above the x–y plane. The default
//! (−60°, 30°) looks from the front right and above, as matplotlib's 3-D
//! axes do, with z up.

use std::str::FromStr;

use crate::chart::scene::Xy;
use crate::error::Error;
use crate::figures::aspect::Aspect;

/// A point or vector in 3-D.
pub type Xyz = [f64; 3];

/// The direction a 3-D view looks from, in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// The angle from the +x axis toward +y of the direction to the viewer.
    pub azimuth: f64,
    /// The angle of the direction to the viewer above the x–y plane, in
    /// `[−90, 90]`.
    pub elevation: f64,
}

impl View {
    /// The default view: azimuth −60°, elevation 30°.
    pub const DEFAULT: View = View {
        azimuth: -60.0,
        elevation: 30.0,
    };

    /// A view from `azimuth` and `elevation` in degrees.
    ///
    /// # Errors
    /// [`Error::View`] if a value is not finite or the elevation lies
    /// outside `[−90, 90]`.
    ///
    /// # Examples
    /// ```
    /// use t2spline_plot::View;
    /// assert!(View::try_new(-60.0, 30.0).is_ok());
    /// assert!(View::try_new(0.0, 91.0).is_err());
    /// ```
    pub fn try_new(azimuth: f64, elevation: f64) -> Result<View, Error> {
        if !azimuth.is_finite() || !elevation.is_finite() {
            return Err(Error::View(format!(
                "the angles must be finite numbers, not {azimuth},{elevation}"
            )));
        }
        if !(-90.0..=90.0).contains(&elevation) {
            return Err(Error::View(format!(
                "the elevation must lie in [-90, 90] degrees, not {elevation}"
            )));
        }
        Ok(View { azimuth, elevation })
    }
}

impl Default for View {
    fn default() -> View {
        View::DEFAULT
    }
}

impl FromStr for View {
    type Err = Error;

    /// `AZIMUTH,ELEVATION` in degrees, e.g. `-60,30`.
    fn from_str(s: &str) -> Result<View, Error> {
        let parts: Vec<&str> = s.split(',').map(str::trim).collect();
        let [a, e] = parts.as_slice() else {
            return Err(Error::View(format!(
                "expected AZIMUTH,ELEVATION in degrees (e.g. -60,30), not `{s}`"
            )));
        };
        let number = |t: &str| {
            t.parse::<f64>()
                .map_err(|_| Error::View(format!("`{t}` is not a number of degrees (e.g. -60,30)")))
        };
        View::try_new(number(a)?, number(e)?)
    }
}

/// The shortest side of the box, as a fraction of the longest, under
/// [`Aspect::Equal`]: a terrain 500 m wide and 15 m high is drawn with its
/// heights stretched to 0.4 of its width rather than as a flat sheet.
pub const MIN_BOX_SIDE: f64 = 0.4;

/// The light, in screen coordinates (right, up, toward the viewer): from
/// above the viewer's left shoulder.
const LIGHT: Xyz = [-0.4, 0.6, 0.7];

/// The share of a face's colour it keeps facing away from the light.
pub const AMBIENT: f64 = 0.35;

/// An orthographic camera over the data's bounding box.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    right: Xyz,
    up: Xyz,
    toward: Xyz,
    light: Xyz,
    centre: Xyz,
    scale: Xyz,
    /// Half the box's sides, in box coordinates (the longest side is 1).
    pub half: Xyz,
    /// The data's bounds per coordinate.
    pub bounds: [[f64; 2]; 3],
}

fn dot(a: Xyz, b: Xyz) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
#[must_use]
pub fn cross(a: Xyz, b: Xyz) -> Xyz {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn normalised(a: Xyz) -> Xyz {
    let n = dot(a, a).sqrt();
    if n > 0.0 {
        a.map(|v| v / n)
    } else {
        a
    }
}

impl Camera {
    /// A camera looking from `view` at the box around `bounds` (per
    /// coordinate `[lo, hi]`): each side as long as its data range, but at
    /// least [`MIN_BOX_SIDE`] of the longest, under [`Aspect::Equal`]; a
    /// cube under [`Aspect::Auto`].
    #[must_use]
    pub fn new(view: View, bounds: [[f64; 2]; 3], aspect: Aspect) -> Camera {
        let (a, e) = (view.azimuth.to_radians(), view.elevation.to_radians());
        let toward = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
        let right = [-a.sin(), a.cos(), 0.0];
        let up = cross(toward, right);
        let range = bounds.map(|[lo, hi]| (hi - lo).max(0.0));
        let longest = range.iter().copied().fold(0.0, f64::max);
        let longest = if longest > 0.0 { longest } else { 1.0 };
        let side = range.map(|r| match aspect {
            Aspect::Equal => r.max(MIN_BOX_SIDE * longest) / longest,
            Aspect::Auto => 1.0,
        });
        let scale = std::array::from_fn(|k| {
            if range[k] > 0.0 {
                side[k] / range[k]
            } else {
                1.0 / longest
            }
        });
        let light = normalised(std::array::from_fn(|k| {
            LIGHT[0] * right[k] + LIGHT[1] * up[k] + LIGHT[2] * toward[k]
        }));
        Camera {
            right,
            up,
            toward,
            light,
            centre: bounds.map(|[lo, hi]| 0.5 * (lo + hi)),
            scale,
            half: side.map(|s| 0.5 * s),
            bounds,
        }
    }

    /// A data point in box coordinates.
    #[must_use]
    pub fn to_box(&self, p: Xyz) -> Xyz {
        std::array::from_fn(|k| (p[k] - self.centre[k]) * self.scale[k])
    }

    /// A point in box coordinates on the screen.
    #[must_use]
    pub fn screen(&self, q: Xyz) -> Xy {
        [dot(q, self.right), dot(q, self.up)]
    }

    /// A data point on the screen.
    #[must_use]
    pub fn project(&self, p: Xyz) -> Xy {
        self.screen(self.to_box(p))
    }

    /// How near a data point is to the viewer (larger is nearer).
    #[must_use]
    pub fn depth(&self, p: Xyz) -> f64 {
        dot(self.to_box(p), self.toward)
    }

    /// How near a point in box coordinates is to the viewer.
    #[must_use]
    pub fn box_depth(&self, q: Xyz) -> f64 {
        dot(q, self.toward)
    }

    /// The brightness of a face with normal `n` (box coordinates, any
    /// length, either side): `AMBIENT + (1 − AMBIENT)·|n̂·l|` (Lambert, lit
    /// on both sides); 1 for a degenerate face.
    #[must_use]
    pub fn brightness(&self, n: Xyz) -> f64 {
        let len = dot(n, n).sqrt();
        if len.is_nan() || len <= 0.0 {
            return 1.0;
        }
        AMBIENT + (1.0 - AMBIENT) * (dot(n, self.light) / len).abs()
    }

    /// The factor by which coordinate `k` is stretched against the others
    /// (1 when the box is to scale).
    #[must_use]
    pub fn stretch(&self, k: usize) -> f64 {
        let least = self.scale.iter().copied().fold(f64::INFINITY, f64::min);
        self.scale[k] / least
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: [[f64; 2]; 3] = [[-1.0, 1.0], [-1.0, 1.0], [-1.0, 1.0]];

    fn near(a: Xy, b: Xy) -> bool {
        (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12
    }

    #[test]
    fn looking_along_minus_x_shows_y_right_and_z_up() {
        let c = Camera::new(View::try_new(0.0, 0.0).unwrap(), UNIT, Aspect::Equal);
        // The cube [-1, 1]³ has sides 1 in box coordinates.
        assert!(near(c.project([0.3, 0.8, -0.4]), [0.4, -0.2]));
        assert!(c.depth([1.0, 0.0, 0.0]) > c.depth([-1.0, 0.0, 0.0]));
    }

    #[test]
    fn looking_down_shows_the_x_y_plane() {
        // From above at azimuth 90°: x points left, y down on the screen.
        let c = Camera::new(View::try_new(90.0, 90.0).unwrap(), UNIT, Aspect::Equal);
        assert!(near(c.project([1.0, 0.0, 0.7]), [-0.5, 0.0]));
        assert!(near(c.project([0.0, 1.0, 0.7]), [0.0, -0.5]));
        assert!(c.depth([0.0, 0.0, 1.0]) > c.depth([0.0, 0.0, 0.0]));
    }

    #[test]
    fn the_projection_is_orthonormal() {
        // Lengths perpendicular to the view direction are kept; along it, lost.
        let v = View::DEFAULT;
        let c = Camera::new(v, UNIT, Aspect::Equal);
        let (a, e) = (v.azimuth.to_radians(), v.elevation.to_radians());
        let toward = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
        let s = c.project(toward);
        assert!(s[0].abs() < 1e-12 && s[1].abs() < 1e-12);
        assert!((c.depth(toward) - 0.5).abs() < 1e-12);
        let r = c.project([-a.sin(), a.cos(), 0.0]);
        assert!(near(r, [0.5, 0.0]));
    }

    #[test]
    fn flat_data_get_a_box_of_at_least_the_minimum_side() {
        let c = Camera::new(
            View::DEFAULT,
            [[0.0, 500.0], [0.0, 400.0], [100.0, 115.0]],
            Aspect::Equal,
        );
        assert!((c.half[0] - 0.5).abs() < 1e-12);
        assert!((c.half[1] - 0.4).abs() < 1e-12);
        assert!((c.half[2] - 0.5 * MIN_BOX_SIDE).abs() < 1e-12);
        assert!((c.stretch(2) - 200.0 / 15.0).abs() < 1e-9);
        assert!((c.stretch(0) - 1.0).abs() < 1e-12);
        let cube = Camera::new(View::DEFAULT, c.bounds, Aspect::Auto);
        assert_eq!(cube.half, [0.5; 3]);
    }

    #[test]
    fn a_face_toward_the_light_is_brightest() {
        let c = Camera::new(View::DEFAULT, UNIT, Aspect::Equal);
        assert!((c.brightness(c.light) - 1.0).abs() < 1e-12);
        assert!((c.brightness(c.light.map(|v| -3.0 * v)) - 1.0).abs() < 1e-12);
        let across = cross(c.light, [0.0, 0.0, 1.0]);
        assert!((c.brightness(across) - AMBIENT).abs() < 1e-12);
    }

    #[test]
    fn views_parse_with_clear_errors() {
        let v: View = "-60, 30".parse().unwrap();
        assert_eq!(v, View::DEFAULT);
        for bad in ["", "30", "a,30", "1,2,3", "0,120", "nan,0"] {
            let e = bad.parse::<View>().unwrap_err().to_string();
            assert!(!e.is_empty(), "{bad}");
        }
        assert!("0,120"
            .parse::<View>()
            .unwrap_err()
            .to_string()
            .contains("[-90, 90]"));
    }
}
