//! CAD files of a run's exact curves: DXF, STEP, IGES and Wavefront OBJ.
//!
//! Every format gets the curves of [`Geometry`] (the core's
//! [`Job::geometry`](t2spline::job::Job::geometry)) as rational B-splines
//! with their knots, weights and control points, never as polylines, each
//! named `crisp`, `defuzzified`, `upper_left`, …:
//!
//! | format | entity | name in | unclamped curves | units |
//! |---|---|---|---|---|
//! | DXF (R2000, ASCII) | `SPLINE` (rational flag and a weight per control point when a weight is not 1) | layer | clamped exactly (knot insertion) | `$INSUNITS` (millimetres unless the job's `units` or `--units` say otherwise) |
//! | STEP (AP214, ISO 10303-21) | `B_SPLINE_CURVE_WITH_KNOTS` and `RATIONAL_B_SPLINE_CURVE` (complex entity) in a wireframe shape of one product | entity name and presentation layer | as they are (knot multiplicities, domain `[U[p], U[n]]`) | the context's length unit (SI, or a conversion-based inch or foot) |
//! | IGES 5.3 | entity 126 (rational B-spline curve) with a name property (406 form 15) | name property, label | as they are (`V(0)`, `V(1)` give the domain) | the global section's unit flag and name |
//! | OBJ | `cstype rat bspline`, `deg`, `curv`, `parm u` | group | as they are (`curv u0 u1`) | none |
//!
//! Surface jobs (docs/method.md §8) export their eight surfaces, named the same way:
//! STEP `B_SPLINE_SURFACE_WITH_KNOTS` + `RATIONAL_B_SPLINE_SURFACE`, IGES
//! entity 128, OBJ `surf` with `parm u` and `parm v`; DXF has no NURBS
//! surface entity and refuses them.
//!
//! Numbers are written in the shortest form that reads back to the same
//! 64-bit float, so nothing is rounded. A curve that jumps at a knot of full
//! multiplicity is written as its continuous pieces, all with the curve's
//! name (see [`Geometry`]). Curves of degree 0 (piecewise constant) are sets
//! of points, which no CAD format stores as a curve: they are refused.
//!
//! The writers only write; cutting and clamping curves is the core's
//! ([`Geometry::clamped`]), which the caller applies when
//! [`CadFormat::clamps`] says so.

mod clock;
mod dxf;
mod iges;
mod meta;
mod obj;
mod real;
mod step;

use std::fmt;
use std::path::Path;

use t2spline::job::Geometry;

use crate::error::{Error, Problem};

pub use meta::CadMeta;

/// A CAD file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CadFormat {
    /// AutoCAD's Drawing Exchange Format (ASCII, R2000).
    Dxf,
    /// STEP (ISO 10303-21, AP214 `automotive_design`).
    Step,
    /// IGES 5.3.
    Iges,
    /// Wavefront OBJ free-form curves.
    Obj,
}

impl CadFormat {
    /// Every format.
    pub const ALL: [CadFormat; 4] = [
        CadFormat::Dxf,
        CadFormat::Step,
        CadFormat::Iges,
        CadFormat::Obj,
    ];

    /// The name on the command line and in messages (`dxf`, `step`, …).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            CadFormat::Dxf => "dxf",
            CadFormat::Step => "step",
            CadFormat::Iges => "iges",
            CadFormat::Obj => "obj",
        }
    }

    /// Whether curves must be clamped before this format is written: DXF
    /// readers draw a `SPLINE` from its first to its last control point, so an
    /// unclamped curve is written as the same curve with a clamped knot
    /// vector ([`Geometry::clamped`]); the other formats carry the domain.
    #[must_use]
    pub fn clamps(self) -> bool {
        self == CadFormat::Dxf
    }

    /// The format of a name (`dxf`, `step`, `iges`, `obj`).
    #[must_use]
    pub fn named(name: &str) -> Option<CadFormat> {
        CadFormat::ALL.into_iter().find(|f| f.name() == name)
    }

    /// The format that a file's extension names, in any case: `.dxf`,
    /// `.step` or `.stp`, `.iges` or `.igs`, `.obj`.
    ///
    /// # Examples
    /// ```
    /// # use std::path::Path;
    /// # use t2spline_io::CadFormat;
    /// assert_eq!(CadFormat::from_extension(Path::new("part.STP")), Some(CadFormat::Step));
    /// assert_eq!(CadFormat::from_extension(Path::new("part.txt")), None);
    /// ```
    #[must_use]
    pub fn from_extension(path: &Path) -> Option<CadFormat> {
        let extension = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match extension.as_deref() {
            Some("dxf") => Some(CadFormat::Dxf),
            Some("step" | "stp") => Some(CadFormat::Step),
            Some("iges" | "igs") => Some(CadFormat::Iges),
            Some("obj") => Some(CadFormat::Obj),
            _ => None,
        }
    }
}

impl fmt::Display for CadFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The text of a CAD file of `geometry`; for a format that needs clamped
/// curves ([`CadFormat::clamps`]), of the same curves clamped to their domains.
///
/// # Errors
/// [`Error::Invalid`] (naming `source`, the job) for curves of degree 0,
/// which no format stores as curves.
///
/// # Examples
/// ```
/// # use t2spline::job::Overrides;
/// # use t2spline_io::{render_cad, CadFormat, CadMeta};
/// let text = std::fs::read_to_string("../../examples/paper-alg-1-1.json")?;
/// let job = t2spline_io::parse_job(&text, "paper-alg-1-1.json")?;
/// let geometry = job.geometry(&job.settings(&Overrides::default())?)?;
/// let meta = CadMeta::new("out.obj".into(), None, "2026-01-01T00:00:00", Default::default())?;
/// let obj = render_cad(CadFormat::Obj, &geometry, &meta, "paper-alg-1-1.json")?;
/// assert!(obj.contains("g defuzzified\n") && obj.contains("cstype rat bspline\n"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn render_cad(
    format: CadFormat,
    geometry: &Geometry,
    meta: &CadMeta,
    source: &str,
) -> Result<String, Error> {
    if format == CadFormat::Dxf && !geometry.surfaces.is_empty() {
        return Err(Error::Invalid {
            file: source.to_owned(),
            problems: vec![Problem::new(
                "DXF holds NURBS curves (SPLINE) but no NURBS surfaces (only ACIS solids); export surfaces as STEP, IGES or OBJ",
            )],
        });
    }
    if geometry.degree() == 0 {
        let surface_degrees = geometry
            .surfaces
            .first()
            .and_then(|s| s.patches.first())
            .map(t2spline::NurbsSurface::degree);
        let what = match surface_degrees {
            None => "the curves have degree 0 (piecewise constant: a set of points)".to_owned(),
            Some([0, 0]) => {
                "the surfaces have degree 0 in u and in v (piecewise constant: a set of points)"
                    .to_owned()
            }
            Some([0, _]) => {
                "the surfaces have degree 0 in u (piecewise constant in u: a set of curves along v)"
                    .to_owned()
            }
            Some(_) => {
                "the surfaces have degree 0 in v (piecewise constant in v: a set of curves along u)"
                    .to_owned()
            }
        };
        return Err(Error::Invalid {
            file: source.to_owned(),
            problems: vec![Problem::new(format!(
                "{what}, which {} cannot hold; export needs degree 1 or more{}",
                format.name().to_uppercase(),
                if surface_degrees.is_some() {
                    " in both directions"
                } else {
                    ""
                }
            ))],
        });
    }
    // A format that needs clamped curves gets them here, whatever the
    // caller passed: the same curves, each clamped to its domain.
    let unclamped = geometry
        .curves
        .iter()
        .flat_map(|c| &c.pieces)
        .any(|p| !p.knots().is_clamped());
    let clamped;
    let geometry = if format.clamps() && unclamped {
        clamped = geometry.clamped();
        &clamped
    } else {
        geometry
    };
    Ok(match format {
        CadFormat::Dxf => dxf::render(geometry, meta),
        CadFormat::Step => step::render(geometry, meta),
        CadFormat::Iges => iges::render(geometry, meta),
        CadFormat::Obj => obj::render(geometry, meta),
    })
}
