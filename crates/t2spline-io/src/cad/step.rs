//! STEP files (ISO 10303-21 exchange structure, AP214 `automotive_design`
//! schema) of rational B-spline curves.
//!
//! One product (`PRODUCT` … `PRODUCT_DEFINITION_SHAPE`) whose shape is a
//! `GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION` holding a
//! `GEOMETRIC_CURVE_SET` of every curve, in a context of millimetres and
//! radians, as CAD programs expect of a part. Each curve is the complex
//! entity of ISO 10303-42 for a rational B-spline with knots:
//!
//! ```text
//! (BOUNDED_CURVE() B_SPLINE_CURVE(p, (P…), .UNSPECIFIED., .F., .F.)
//!  B_SPLINE_CURVE_WITH_KNOTS((multiplicities), (distinct knots), .UNSPECIFIED.)
//!  CURVE() GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE((weights))
//!  REPRESENTATION_ITEM('name'))
//! ```
//! The name is the representation item's, and each name is also a
//! `PRESENTATION_LAYER_ASSIGNMENT`, which CAD programs show as layers.
//! ISO 10303-42 allows interior multiplicities up to `p` (curves that jump
//! arrive here as continuous pieces) and any end multiplicity up to `p + 1`,
//! so unclamped curves are written as they are; the domain is `[U[p], U[n]]`.
//! Surfaces are the complex entity of `B_SPLINE_SURFACE_WITH_KNOTS` and
//! `RATIONAL_B_SPLINE_SURFACE` in a `GEOMETRIC_SET` of a
//! `GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION`, named the same way.

use std::fmt::Write as _;

use t2spline::job::{Geometry, LengthUnit};
use t2spline::{Direction, KnotVector, NurbsCurve, NurbsSurface};

use super::meta::CadMeta;
use super::real::real;

/// The STEP text of `geometry`.
pub(super) fn render(geometry: &Geometry, meta: &CadMeta) -> String {
    let mut data = Data::default();
    let context =
        data.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
    data.add(&format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,{context})"
    ));
    let product_context = data.add(&format!("PRODUCT_CONTEXT('',{context},'mechanical')"));
    let title = string(meta.name());
    let description = string(meta.description().unwrap_or(""));
    let product = data.add(&format!(
        "PRODUCT({title},{title},{description},({product_context}))"
    ));
    data.add(&format!(
        "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,({product}))"
    ));
    let formation = data.add(&format!("PRODUCT_DEFINITION_FORMATION('','',{product})"));
    let definition_context = data.add(&format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',{context},'design')"
    ));
    let definition = data.add(&format!(
        "PRODUCT_DEFINITION('design','',{formation},{definition_context})"
    ));
    let shape = data.add(&format!("PRODUCT_DEFINITION_SHAPE('','',{definition})"));
    let length = length_unit(&mut data, meta.units());
    let angle = data.add("(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.))");
    let solid = data.add("(NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT())");
    let uncertainty = data.add(&format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.0E-7),{length},'distance_accuracy_value','confusion accuracy')"
    ));
    let units = data.add(&format!(
        "(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT(({uncertainty})) GLOBAL_UNIT_ASSIGNED_CONTEXT(({length},{angle},{solid})) REPRESENTATION_CONTEXT('3D','3D context with units and uncertainty'))"
    ));
    let origin = data.add("CARTESIAN_POINT('',(0.0,0.0,0.0))");
    let z = data.add("DIRECTION('',(0.0,0.0,1.0))");
    let x = data.add("DIRECTION('',(1.0,0.0,0.0))");
    let placement = data.add(&format!("AXIS2_PLACEMENT_3D('',{origin},{z},{x})"));
    let mut all = Vec::new();
    let mut layers = Vec::new();
    for curve in &geometry.curves {
        let items: Vec<String> = curve
            .pieces
            .iter()
            .map(|piece| spline(&mut data, curve.name, piece))
            .collect();
        all.extend(items.iter().cloned());
        layers.push((curve.name, items));
    }
    for surface in &geometry.surfaces {
        let items: Vec<String> = surface
            .patches
            .iter()
            .map(|patch| surface_entity(&mut data, surface.name, patch))
            .collect();
        all.extend(items.iter().cloned());
        layers.push((surface.name, items));
    }
    let representation = if geometry.surfaces.is_empty() {
        let set = data.add(&format!("GEOMETRIC_CURVE_SET('',({}))", all.join(",")));
        data.add(&format!(
            "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION({title},({placement},{set}),{units})"
        ))
    } else {
        let set = data.add(&format!("GEOMETRIC_SET('',({}))", all.join(",")));
        data.add(&format!(
            "GEOMETRICALLY_BOUNDED_SURFACE_SHAPE_REPRESENTATION({title},({placement},{set}),{units})"
        ))
    };
    data.add(&format!(
        "SHAPE_DEFINITION_REPRESENTATION({shape},{representation})"
    ));
    for (name, items) in layers {
        data.add(&format!(
            "PRESENTATION_LAYER_ASSIGNMENT('{name}','{name}',({}))",
            items.join(",")
        ));
    }
    let mut out = String::from("ISO-10303-21;\nHEADER;\n");
    let _ = writeln!(
        out,
        "FILE_DESCRIPTION(({}),'2;1');",
        string("t2spline: a run's curves or surfaces as exact rational B-splines")
    );
    let version = concat!("'t2spline ", env!("CARGO_PKG_VERSION"), "'");
    let _ = writeln!(
        out,
        "FILE_NAME({title},'{}',(''),(''),{version},{version},'');",
        meta.timestamp()
    );
    out.push_str("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n");
    out.push_str(&data.text);
    out.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    out
}

/// The DATA section, built entity by entity.
#[derive(Default)]
struct Data {
    text: String,
    count: usize,
}

impl Data {
    /// Adds `#n=entity;` and returns `#n`.
    fn add(&mut self, entity: &str) -> String {
        self.count += 1;
        let _ = writeln!(self.text, "#{}={entity};", self.count);
        format!("#{}", self.count)
    }
}

/// The length unit of the representation context: an SI unit (milli-,
/// centi- or plain metres), or an inch or a foot as a conversion-based unit
/// of the millimetre (ISO 10303-41).
fn length_unit(data: &mut Data, units: LengthUnit) -> String {
    let si = |prefix: &str| format!("(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT({prefix},.METRE.))");
    match units {
        LengthUnit::Millimetre => data.add(&si(".MILLI.")),
        LengthUnit::Centimetre => data.add(&si(".CENTI.")),
        LengthUnit::Metre => data.add(&si("$")),
        LengthUnit::Inch | LengthUnit::Foot => {
            let mm = data.add(&si(".MILLI."));
            let factor = data.add(&format!(
                "LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE({}),{mm})",
                r(units.millimetres())
            ));
            let exponents = data.add("DIMENSIONAL_EXPONENTS(1.0,0.0,0.0,0.0,0.0,0.0,0.0)");
            let name = if units == LengthUnit::Inch {
                "INCH"
            } else {
                "FOOT"
            };
            data.add(&format!(
                "(CONVERSION_BASED_UNIT('{name}',{factor}) LENGTH_UNIT() NAMED_UNIT({exponents}))"
            ))
        }
    }
}

/// A real in STEP's form.
fn r(x: f64) -> String {
    real(x, 'E')
}

/// Adds a `CARTESIAN_POINT`; returns its reference.
fn point(data: &mut Data, p: [f64; 3]) -> String {
    data.add(&format!(
        "CARTESIAN_POINT('',({},{},{}))",
        r(p[0]),
        r(p[1]),
        r(p[2])
    ))
}

/// A knot vector as STEP writes it: the multiplicities and the distinct
/// knots, each a list `(…)`.
fn knots_with_multiplicities(knots: &KnotVector) -> (String, String) {
    let mut values: Vec<f64> = Vec::new();
    let mut multiplicities: Vec<usize> = Vec::new();
    for &u in knots.as_slice() {
        if values.last() == Some(&u) {
            if let Some(m) = multiplicities.last_mut() {
                *m += 1;
            }
        } else {
            values.push(u);
            multiplicities.push(1);
        }
    }
    let m: Vec<String> = multiplicities.iter().map(ToString::to_string).collect();
    let v: Vec<String> = values.iter().map(|&u| r(u)).collect();
    (format!("({})", m.join(",")), format!("({})", v.join(",")))
}

/// Adds a curve's control points and its complex entity; returns its
/// reference.
fn spline(data: &mut Data, name: &str, c: &NurbsCurve<3>) -> String {
    let points: Vec<String> = c.control_points().iter().map(|&p| point(data, p)).collect();
    let weights: Vec<String> = c.weights().iter().map(|&w| r(w)).collect();
    let (m, u) = knots_with_multiplicities(c.knots());
    data.add(&format!(
        "(BOUNDED_CURVE() B_SPLINE_CURVE({},({}),.UNSPECIFIED.,.F.,.F.) B_SPLINE_CURVE_WITH_KNOTS({m},{u},.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE(({})) REPRESENTATION_ITEM('{name}'))",
        c.degree(),
        points.join(","),
        weights.join(","),
    ))
}

/// Adds a surface's control points and its complex entity (ISO 10303-42
/// `B_SPLINE_SURFACE_WITH_KNOTS` and `RATIONAL_B_SPLINE_SURFACE`: lists of
/// rows along u, each row along v); returns its reference.
fn surface_entity(data: &mut Data, name: &str, s: &NurbsSurface<3>) -> String {
    let [nu, nv] = s.shape();
    let [p, q] = s.degree();
    let mut rows = Vec::with_capacity(nu);
    let mut weight_rows = Vec::with_capacity(nu);
    for (points, weights) in s.control_points().chunks(nv).zip(s.weights().chunks(nv)) {
        let row: Vec<String> = points.iter().map(|&p| point(data, p)).collect();
        rows.push(format!("({})", row.join(",")));
        let w: Vec<String> = weights.iter().map(|&w| r(w)).collect();
        weight_rows.push(format!("({})", w.join(",")));
    }
    let (mu, ku) = knots_with_multiplicities(s.knots(Direction::U));
    let (mv, kv) = knots_with_multiplicities(s.knots(Direction::V));
    data.add(&format!(
        "(BOUNDED_SURFACE() B_SPLINE_SURFACE({p},{q},({}),.UNSPECIFIED.,.F.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS({mu},{mv},{ku},{kv},.UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(({})) REPRESENTATION_ITEM('{name}') SURFACE())",
        rows.join(","),
        weight_rows.join(","),
    ))
}

/// A STEP string literal: apostrophes and backslashes doubled, characters
/// outside printable ASCII as `\X2\hhhh\X0\` (UTF-16, ISO 10303-21 §6.4.3).
fn string(text: &str) -> String {
    let mut out = String::from("'");
    for c in text.chars() {
        match c {
            '\'' => out.push_str("''"),
            '\\' => out.push_str("\\\\"),
            ' '..='~' => out.push(c),
            _ => {
                out.push_str("\\X2\\");
                let mut units = [0u16; 2];
                for u in c.encode_utf16(&mut units) {
                    let _ = write!(out, "{u:04X}");
                }
                out.push_str("\\X0\\");
            }
        }
    }
    out.push('\'');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strings_are_escaped_as_part_21_says() {
        assert_eq!(string("it's"), "'it''s'");
        assert_eq!(string("a\\b"), "'a\\\\b'");
        assert_eq!(string("Düne"), "'D\\X2\\00FC\\X0\\ne'");
        assert_eq!(string("\n"), "'\\X2\\000A\\X0\\'");
    }
}
