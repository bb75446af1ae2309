//! DXF files (AutoCAD R2000, ASCII) of `SPLINE` entities.
//!
//! The structure AutoCAD and other readers expect of an R2000 file: HEADER
//! (`$ACADVER`, `$HANDSEED`, millimetres, the drawing extents), CLASSES,
//! TABLES (viewport, line types, a layer per curve, text and dimension
//! styles, application id, block records), BLOCKS (model and paper space),
//! ENTITIES and OBJECTS (the root dictionary), every object with a handle and
//! its owner.
//!
//! A `SPLINE` (group codes of the DXF reference):
//! ```text
//! 70 flags: 8 planar (2-D jobs, with normal 210/220/230 = 0, 0, 1), 4 rational (a weight ≠ 1)
//! 71 degree, 72 knot count, 73 control point count, 74 fit point count (0)
//! 40 knot (each), 10/20/30 control point (each), 41 its weight (rational only)
//! ```
//! DXF readers draw a spline from its first to its last control point, so
//! the caller clamps curves first ([`super::CadFormat::clamps`]).
//!
//! The `dxf` crate was the first choice and cannot be used: its `Spline`
//! has one `weight` for the whole curve (group 41 written once), so
//! rational splines lose their weights, and it writes floats with 12
//! decimals (`format!("{:.12}")`), which rounds coordinates.

use std::fmt::Write as _;

use t2spline::job::{Geometry, LengthUnit, NamedCurve};

use super::meta::CadMeta;
use super::real::real;

/// The DXF text of `geometry`.
pub(super) fn render(geometry: &Geometry, meta: &CadMeta) -> String {
    let mut w = Writer::default();
    let (lo, hi) = extents(geometry);
    // Handles are fixed for the tables; entities start after them.
    let body = body(geometry, &mut Handles(0x100));
    w.section("HEADER", |w| {
        w.var("$ACADVER", 1, "AC1015");
        w.var("$DWGCODEPAGE", 3, "ANSI_1252");
        w.point_var("$EXTMIN", lo);
        w.point_var("$EXTMAX", hi);
        let (insunits, measurement) = match meta.units() {
            LengthUnit::Inch => ("1", "0"),
            LengthUnit::Foot => ("2", "0"),
            LengthUnit::Millimetre => ("4", "1"),
            LengthUnit::Centimetre => ("5", "1"),
            LengthUnit::Metre => ("6", "1"),
        };
        w.var("$INSUNITS", 70, insunits);
        w.var("$MEASUREMENT", 70, measurement);
        w.var("$HANDSEED", 5, &format!("{:X}", body.next));
    });
    w.section("CLASSES", |_| {});
    w.section("TABLES", |w| tables(w, geometry));
    w.section("BLOCKS", |w| {
        for (block, end, record, name) in [
            ("20", "21", "1A", "*Model_Space"),
            ("22", "23", "1B", "*Paper_Space"),
        ] {
            w.pairs(&[
                (0, "BLOCK"),
                (5, block),
                (330, record),
                (100, "AcDbEntity"),
                (8, "0"),
                (100, "AcDbBlockBegin"),
                (2, name),
                (70, "0"),
            ]);
            w.pairs(&[(10, "0.0"), (20, "0.0"), (30, "0.0"), (3, name), (1, "")]);
            w.pairs(&[
                (0, "ENDBLK"),
                (5, end),
                (330, record),
                (100, "AcDbEntity"),
                (8, "0"),
                (100, "AcDbBlockEnd"),
            ]);
        }
    });
    w.section("ENTITIES", |w| w.text.push_str(&body.text));
    w.section("OBJECTS", |w| {
        w.pairs(&[
            (0, "DICTIONARY"),
            (5, "C"),
            (330, "0"),
            (100, "AcDbDictionary"),
            (281, "1"),
            (3, "ACAD_GROUP"),
            (350, "D"),
        ]);
        w.pairs(&[
            (0, "DICTIONARY"),
            (5, "D"),
            (330, "C"),
            (100, "AcDbDictionary"),
            (281, "1"),
        ]);
    });
    w.pair(0, "EOF");
    w.text
}

/// The colour of each curve's layer (AutoCAD colour index): the crisp curve
/// white/black, the solution red, upper layers blue, primary green, lower
/// orange.
fn colour(name: &str) -> &'static str {
    match name {
        "crisp" => "7",
        "defuzzified" => "1",
        n if n.starts_with("upper") => "5",
        n if n.starts_with("primary") => "3",
        _ => "30",
    }
}

/// The symbol tables: fixed handles below 0x100.
fn tables(w: &mut Writer, geometry: &Geometry) {
    w.table("VPORT", "8", 1, |w| {
        w.pairs(&[
            (0, "VPORT"),
            (5, "30"),
            (330, "8"),
            (100, "AcDbSymbolTableRecord"),
            (100, "AcDbViewportTableRecord"),
            (2, "*ACTIVE"),
            (70, "0"),
        ]);
        w.pairs(&[
            (10, "0.0"),
            (20, "0.0"),
            (11, "1.0"),
            (21, "1.0"),
            (12, "0.0"),
            (22, "0.0"),
            (40, "1.0"),
            (41, "1.0"),
        ]);
    });
    w.table("LTYPE", "5", 3, |w| {
        for (handle, name, text) in [
            ("14", "ByBlock", ""),
            ("15", "ByLayer", ""),
            ("16", "Continuous", "Solid line"),
        ] {
            w.pairs(&[
                (0, "LTYPE"),
                (5, handle),
                (330, "5"),
                (100, "AcDbSymbolTableRecord"),
                (100, "AcDbLinetypeTableRecord"),
                (2, name),
                (70, "0"),
                (3, text),
                (72, "65"),
                (73, "0"),
                (40, "0.0"),
            ]);
        }
    });
    w.table("LAYER", "2", geometry.curves.len() + 1, |w| {
        let mut layer = |handle: String, name: &str, colour: &str| {
            w.pairs(&[
                (0, "LAYER"),
                (5, &handle),
                (330, "2"),
                (100, "AcDbSymbolTableRecord"),
                (100, "AcDbLayerTableRecord"),
                (2, name),
                (70, "0"),
                (62, colour),
                (6, "Continuous"),
                (370, "-3"),
            ]);
        };
        layer("10".into(), "0", "7");
        for (i, c) in geometry.curves.iter().enumerate() {
            layer(format!("{:X}", 0x40 + i), c.name, colour(c.name));
        }
    });
    w.table("STYLE", "3", 1, |w| {
        w.pairs(&[
            (0, "STYLE"),
            (5, "11"),
            (330, "3"),
            (100, "AcDbSymbolTableRecord"),
            (100, "AcDbTextStyleTableRecord"),
            (2, "Standard"),
            (70, "0"),
        ]);
        w.pairs(&[
            (40, "0.0"),
            (41, "1.0"),
            (50, "0.0"),
            (71, "0"),
            (42, "2.5"),
            (3, "txt"),
            (4, ""),
        ]);
    });
    w.table("VIEW", "6", 0, |_| {});
    w.table("UCS", "7", 0, |_| {});
    w.table("APPID", "9", 1, |w| {
        w.pairs(&[
            (0, "APPID"),
            (5, "12"),
            (330, "9"),
            (100, "AcDbSymbolTableRecord"),
            (100, "AcDbRegAppTableRecord"),
            (2, "ACAD"),
            (70, "0"),
        ]);
    });
    w.table("DIMSTYLE", "A", 1, |w| {
        w.pair(100, "AcDbDimStyleTable");
        w.pairs(&[
            (0, "DIMSTYLE"),
            (105, "27"),
            (330, "A"),
            (100, "AcDbSymbolTableRecord"),
            (100, "AcDbDimStyleTableRecord"),
            (2, "Standard"),
            (70, "0"),
        ]);
    });
    w.table("BLOCK_RECORD", "1", 2, |w| {
        for (handle, name) in [("1A", "*Model_Space"), ("1B", "*Paper_Space")] {
            w.pairs(&[
                (0, "BLOCK_RECORD"),
                (5, handle),
                (330, "1"),
                (100, "AcDbSymbolTableRecord"),
                (100, "AcDbBlockTableRecord"),
                (2, name),
            ]);
        }
    });
}

/// Handles for entities, counting up.
struct Handles(u64);

impl Handles {
    fn next(&mut self) -> String {
        self.0 += 1;
        format!("{:X}", self.0)
    }
}

/// The ENTITIES section's content and the next free handle.
struct Body {
    text: String,
    next: u64,
}

fn body(geometry: &Geometry, handles: &mut Handles) -> Body {
    let mut w = Writer::default();
    for curve in &geometry.curves {
        spline(&mut w, curve, geometry.dimension == 2, handles);
    }
    Body {
        text: w.text,
        next: handles.0 + 1,
    }
}

/// Every piece of a curve as a `SPLINE` on the curve's layer.
fn spline(w: &mut Writer, curve: &NamedCurve, planar: bool, handles: &mut Handles) {
    let r = |x: f64| real(x, 'E');
    for c in &curve.pieces {
        let rational = c.weights().iter().any(|&x| x != 1.0);
        let flags = if planar { 8 } else { 0 } + if rational { 4 } else { 0 };
        w.pairs(&[
            (0, "SPLINE"),
            (5, &handles.next()),
            (330, "1A"),
            (100, "AcDbEntity"),
            (8, curve.name),
            (100, "AcDbSpline"),
        ]);
        if planar {
            w.pairs(&[(210, "0.0"), (220, "0.0"), (230, "1.0")]);
        }
        let knots = c.knots().as_slice();
        w.pairs(&[
            (70, &flags.to_string()),
            (71, &c.degree().to_string()),
            (72, &knots.len().to_string()),
            (73, &c.control_points().len().to_string()),
            (74, "0"),
            (42, "1.0E-10"),
            (43, "1.0E-10"),
        ]);
        for &u in knots {
            w.pair(40, &r(u));
        }
        for (p, &weight) in c.control_points().iter().zip(c.weights()) {
            w.pairs(&[(10, &r(p[0])), (20, &r(p[1])), (30, &r(p[2]))]);
            if rational {
                w.pair(41, &r(weight));
            }
        }
    }
}

/// Group codes and values, one per line each (CRLF is not needed: readers
/// take LF).
#[derive(Default)]
struct Writer {
    text: String,
}

impl Writer {
    fn pair(&mut self, code: u16, value: &str) {
        let _ = write!(self.text, "{code:>3}\n{value}\n");
    }

    fn pairs(&mut self, pairs: &[(u16, &str)]) {
        for (code, value) in pairs {
            self.pair(*code, value);
        }
    }

    fn var(&mut self, name: &str, code: u16, value: &str) {
        self.pair(9, name);
        self.pair(code, value);
    }

    fn point_var(&mut self, name: &str, p: [f64; 3]) {
        self.pair(9, name);
        for (code, x) in [10, 20, 30].into_iter().zip(p) {
            self.pair(code, &real(x, 'E'));
        }
    }

    fn section(&mut self, name: &str, content: impl FnOnce(&mut Writer)) {
        self.pairs(&[(0, "SECTION"), (2, name)]);
        content(self);
        self.pair(0, "ENDSEC");
    }

    fn table(&mut self, name: &str, handle: &str, count: usize, entries: impl FnOnce(&mut Writer)) {
        self.pairs(&[
            (0, "TABLE"),
            (2, name),
            (5, handle),
            (330, "0"),
            (100, "AcDbSymbolTable"),
            (70, &count.to_string()),
        ]);
        entries(self);
        self.pair(0, "ENDTAB");
    }
}

/// The smallest box around every control point (the curves lie inside it:
/// the convex hull property), for DXF's drawing extents.
fn extents(geometry: &Geometry) -> ([f64; 3], [f64; 3]) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let curves = geometry.curves.iter().flat_map(|c| &c.pieces);
    let surfaces = geometry.surfaces.iter().flat_map(|s| &s.patches);
    for p in curves
        .flat_map(|p| p.control_points())
        .chain(surfaces.flat_map(|s| s.control_points()))
    {
        for i in 0..3 {
            lo[i] = lo[i].min(p[i]);
            hi[i] = hi[i].max(p[i]);
        }
    }
    (lo, hi)
}
