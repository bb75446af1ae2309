//! The fuzzy contour of a surface as GeoJSON (RFC 7946): a
//! FeatureCollection with one Feature per level and membership function (a
//! MultiPolygon: the band where the surface can cross the height) and one
//! for the crisp surface's contour (a MultiLineString).
//!
//! RFC 7946 §3.1.6: exterior rings counter-clockwise, holes clockwise, each
//! ring closed. The coordinates are the model's own (a projected CRS such as
//! EPSG:3857 for the shipped seabed); GeoJSON readers take them as they are.

use std::io::{self, Write};

use t2spline::set::{Contour, Polygon, MEMBERSHIPS};

use crate::number::json as num;
use crate::set::envelope_table::membership_name;

/// Writes `[x, y]`.
fn position<W: Write + ?Sized>(w: &mut W, v: [f64; 2]) -> io::Result<()> {
    w.write_all(b"[")?;
    num(w, v[0])?;
    w.write_all(b", ")?;
    num(w, v[1])?;
    w.write_all(b"]")
}

/// Writes the positions of a line, as they are.
fn line<W: Write + ?Sized>(w: &mut W, points: &[[f64; 2]]) -> io::Result<()> {
    w.write_all(b"[")?;
    for (n, v) in points.iter().enumerate() {
        if n > 0 {
            w.write_all(b", ")?;
        }
        position(w, *v)?;
    }
    w.write_all(b"]")
}

/// Writes the rings of a polygon, each closed.
fn polygon<W: Write + ?Sized>(w: &mut W, g: &Polygon) -> io::Result<()> {
    w.write_all(b"[")?;
    for (j, ring) in std::iter::once(&g.exterior).chain(&g.holes).enumerate() {
        if j > 0 {
            w.write_all(b", ")?;
        }
        let closed: Vec<[f64; 2]> = ring.iter().chain(ring.first()).copied().collect();
        line(w, &closed)?;
    }
    w.write_all(b"]")
}

/// Writes the FeatureCollection of `contour`.
///
/// Band Features come level by level in the order computed, upper, primary
/// and lower, a function without a cut at a level left out; their
/// `properties` are `alpha`, `membership`, `z`, `area`, `tolerance` (the
/// plan tolerance: a cell diagonal) and `height_tolerance`. A band the
/// surface never reaches has no polygons. The last Feature is the crisp
/// contour, `properties` `crisp: true` and `z`.
///
/// # Errors
/// The errors of `w`.
pub fn write_contour_geojson<W: Write + ?Sized>(w: &mut W, contour: &Contour) -> io::Result<()> {
    w.write_all(b"{\"type\": \"FeatureCollection\", \"features\": [")?;
    for level in &contour.levels {
        for m in MEMBERSHIPS {
            let Some(band) = level.get(m) else { continue };
            w.write_all(b"\n  {\"type\": \"Feature\", \"properties\": {\"alpha\": ")?;
            num(w, level.alpha)?;
            write!(w, ", \"membership\": \"{}\", \"z\": ", membership_name(m))?;
            num(w, contour.z)?;
            w.write_all(b", \"area\": ")?;
            num(w, band.area())?;
            w.write_all(b", \"tolerance\": ")?;
            num(w, contour.tolerance)?;
            w.write_all(b", \"height_tolerance\": ")?;
            num(w, contour.height_tolerance)?;
            w.write_all(b"},\n   \"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": [")?;
            for (i, g) in band.polygons().iter().enumerate() {
                if i > 0 {
                    w.write_all(b",")?;
                }
                w.write_all(b"\n    ")?;
                polygon(w, g)?;
            }
            w.write_all(b"]}},")?;
        }
    }
    w.write_all(b"\n  {\"type\": \"Feature\", \"properties\": {\"crisp\": true, \"z\": ")?;
    num(w, contour.z)?;
    w.write_all(b"},\n   \"geometry\": {\"type\": \"MultiLineString\", \"coordinates\": [")?;
    for (i, l) in contour.crisp.iter().enumerate() {
        if i > 0 {
            w.write_all(b",")?;
        }
        w.write_all(b"\n    ")?;
        line(w, l)?;
    }
    w.write_all(b"]}}\n]}\n")
}

#[cfg(test)]
mod tests {
    use super::*;
    use t2spline::set::PlanGrid;
    use t2spline::{Alpha, FuzzySurface, Nt2Number, Nt2Point};

    #[test]
    fn a_plane_s_contour_is_json_with_closed_counter_clockwise_rings() {
        let c = |x: f64| Nt2Number::try_crisp(x).expect("finite");
        let z = |z: f64| {
            Nt2Number::try_new(z, [z - 0.5, z + 0.5], [z - 0.25, z + 0.25], [z, z], 1.0)
                .expect("valid")
        };
        let p = |x: f64, y: f64| Nt2Point::new([c(x), c(y), z(x)]);
        let net = vec![
            vec![p(0.0, 0.0), p(0.0, 1.0)],
            vec![p(2.0, 0.0), p(2.0, 1.0)],
        ];
        let s =
            FuzzySurface::try_new([1, 1], net, vec![vec![1.0; 2]; 2], [None, None]).expect("valid");
        let grid = PlanGrid::try_new([0.0, 0.0, 2.0, 1.0], [20, 10]).expect("grid");
        let contour = s.contour(&grid, 1.0, &[Alpha::ZERO]).expect("contour");
        let mut bytes = Vec::new();
        write_contour_geojson(&mut bytes, &contour).expect("in memory");
        let v: serde_json::Value = serde_json::from_slice(&bytes).expect("JSON");
        let features = v["features"].as_array().expect("features");
        assert_eq!(features.len(), 4, "three bands and the crisp contour");
        let ring = features[0]["geometry"]["coordinates"][0][0]
            .as_array()
            .expect("ring");
        assert_eq!(ring.first(), ring.last());
        let pts: Vec<[f64; 2]> = ring
            .iter()
            .map(|p| [p[0].as_f64().expect("x"), p[1].as_f64().expect("y")])
            .collect();
        let area: f64 = pts
            .windows(2)
            .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
            .sum();
        assert!(area > 0.0, "counter-clockwise");
        assert_eq!(features[3]["properties"]["crisp"], true);
        assert_eq!(features[3]["geometry"]["type"], "MultiLineString");
    }
}
