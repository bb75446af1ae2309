//! Regions as GeoJSON (RFC 7946): a FeatureCollection with one Feature per
//! membership function (and plane), geometry a MultiPolygon.
//!
//! RFC 7946 §3.1.6: exterior rings counter-clockwise, holes clockwise, each
//! ring closed (its first position repeated at the end). The coordinates are
//! the model's own, not longitude and latitude; GeoJSON readers (shapely,
//! GeoPandas, QGIS) take them as they are.

use std::io::{self, Write};

use t2spline::set::{Plane, Region};
use t2spline::Membership;

use crate::number::json as num;

/// One Feature: a region and what it is the region of.
#[derive(Clone, Copy, Debug)]
pub struct RegionFeature<'a> {
    /// The membership function.
    pub membership: Membership,
    /// The level.
    pub alpha: f64,
    /// The plane (`xy` for a plane curve).
    pub plane: Plane,
    /// The region.
    pub region: &'a Region,
}

/// `"upper"`, `"primary"` or `"lower"`.
fn name(m: Membership) -> &'static str {
    match m {
        Membership::Upper => "upper",
        Membership::Primary => "primary",
        Membership::Lower => "lower",
    }
}

/// Writes the FeatureCollection of `features`.
///
/// Each Feature's `properties` are `membership`, `alpha`, `plane`, `area` and
/// `tolerance` (of the outline).
///
/// # Errors
/// The errors of `w`.
pub fn write_region_geojson<W: Write + ?Sized>(
    w: &mut W,
    features: &[RegionFeature<'_>],
) -> io::Result<()> {
    w.write_all(b"{\"type\": \"FeatureCollection\", \"features\": [")?;
    for (k, f) in features.iter().enumerate() {
        if k > 0 {
            w.write_all(b",")?;
        }
        write!(
            w,
            "\n  {{\"type\": \"Feature\", \"properties\": {{\"membership\": \"{}\", \"alpha\": ",
            name(f.membership)
        )?;
        num(w, f.alpha)?;
        write!(w, ", \"plane\": \"{}\", \"area\": ", f.plane.name())?;
        num(w, f.region.area())?;
        w.write_all(b", \"tolerance\": ")?;
        num(w, f.region.tolerance())?;
        w.write_all(b"},\n   \"geometry\": {\"type\": \"MultiPolygon\", \"coordinates\": [")?;
        for (i, g) in f.region.polygons().iter().enumerate() {
            if i > 0 {
                w.write_all(b",")?;
            }
            w.write_all(b"\n    [")?;
            for (j, ring) in std::iter::once(&g.exterior).chain(&g.holes).enumerate() {
                if j > 0 {
                    w.write_all(b", ")?;
                }
                w.write_all(b"[")?;
                for (n, v) in ring.iter().chain(ring.first()).enumerate() {
                    if n > 0 {
                        w.write_all(b", ")?;
                    }
                    w.write_all(b"[")?;
                    num(w, v[0])?;
                    w.write_all(b", ")?;
                    num(w, v[1])?;
                    w.write_all(b"]")?;
                }
                w.write_all(b"]")?;
            }
            w.write_all(b"]")?;
        }
        w.write_all(b"]}}")?;
    }
    w.write_all(b"\n]}\n")
}
