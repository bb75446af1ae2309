//! `t2spline region JOB.json [--alpha A | --levels N] [-o OUT.geojson]
//! [--tolerance T]`: the region a fuzzy curve can occupy at a level (the
//! job's alpha when neither is given), as GeoJSON.

use t2spline::job::Job;
use t2spline::set::{Plane, Region, MEMBERSHIPS};
use t2spline::{Alpha, FuzzyCurve, Membership};
use t2spline_io::set::{write_region_geojson, RegionFeature};

use super::levels::{Levels, MAX_LEVELS};
use super::model_kind::ModelKind;
use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::RegionArgs;
use crate::output::{read_job, Outputs};

/// Why a surface has no region.
const NOT_A_CURVE: &str = "regions are drawn for curves; for a surface, ask `t2spline membership` of points or `t2spline section --at X0,Y0`";

pub fn region(args: &RegionArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path()]).file("--output", out)?;
    }
    let levels = Levels::from_arg(&args.levels, None, MAX_LEVELS)?;
    let job = read_job(&args.job)?;
    if ModelKind::of(&job.model)?.surface().is_some() {
        return Err(crate::output::unsuited(&args.job, NOT_A_CURVE));
    }
    let levels = levels.resolve(&job)?;
    let bytes = geojson(&job, &levels, args.tolerance)?;
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

/// The regions of `job`'s curve at each of `levels` as GeoJSON bytes (also
/// the `serve` page's, at one level): one Feature per level and membership
/// function with a cut there, on the `xy` plane of a plane curve and on
/// every plane of a space curve.
///
/// # Errors
/// A surface (regions are drawn for curves), a `tolerance` out of its range.
pub fn geojson(job: &Job, levels: &[Alpha], tolerance: Option<f64>) -> anyhow::Result<Vec<u8>> {
    let kind = ModelKind::of(&job.model)?;
    let mut regions: Vec<(Alpha, Membership, Plane, Region)> = Vec::new();
    for &alpha in levels {
        let at_level = match kind {
            ModelKind::PlaneCurve(c) => self::regions(c, &[Plane::Xy], alpha, tolerance)?,
            ModelKind::SpaceCurve(c) => self::regions(c, &Plane::ALL, alpha, tolerance)?,
            ModelKind::Surface(_) => {
                return Err(OptionError {
                    option: "JOB",
                    message: NOT_A_CURVE.into(),
                }
                .into())
            }
        };
        regions.extend(at_level.into_iter().map(|(m, p, r)| (alpha, m, p, r)));
    }
    let features: Vec<RegionFeature<'_>> = regions
        .iter()
        .map(|(alpha, membership, plane, region)| RegionFeature {
            membership: *membership,
            alpha: alpha.get(),
            plane: *plane,
            region,
        })
        .collect();
    let mut bytes = Vec::new();
    write_region_geojson(&mut bytes, &features)?;
    Ok(bytes)
}

/// The regions of every function that has a cut at `alpha`, on each plane.
fn regions<const D: usize>(
    curve: &FuzzyCurve<D>,
    planes: &[Plane],
    alpha: Alpha,
    tolerance: Option<f64>,
) -> anyhow::Result<Vec<(Membership, Plane, Region)>> {
    let mut out = Vec::new();
    for m in MEMBERSHIPS {
        for &plane in planes {
            let region = curve
                .region_in(plane, m, alpha, tolerance)
                .map_err(|e| match e {
                    t2spline::Error::Tolerance { .. }
                    | t2spline::Error::ToleranceTooCoarse { .. } => {
                        anyhow::Error::from(OptionError {
                            option: "--tolerance",
                            message: e.to_string(),
                        })
                    }
                    other => other.into(),
                })?;
            if let Some(r) = region {
                out.push((m, plane, r));
            }
        }
    }
    Ok(out)
}
