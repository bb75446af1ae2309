//! `t2spline region JOB.json --alpha A [-o OUT.geojson] [--tolerance T]`: the
//! region a fuzzy curve can occupy at a level, as GeoJSON.

use t2spline::job::{Job, Model};
use t2spline::set::{Plane, Region, MEMBERSHIPS};
use t2spline::{Alpha, FuzzyCurve, Membership};
use t2spline_io::set::{write_region_geojson, RegionFeature};

use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::RegionArgs;
use crate::output::{read_job, Outputs};

pub fn region(args: &RegionArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path()]).file("--output", out)?;
    }
    let alpha = Alpha::try_new(args.alpha).map_err(|e| OptionError {
        option: "--alpha",
        message: e.to_string(),
    })?;
    let job = read_job(&args.job)?;
    let bytes = geojson(&job, alpha, args.tolerance)?;
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

/// The regions of `job`'s curve at `alpha` as GeoJSON bytes (also the
/// `serve` page's): one Feature per membership function with a cut there,
/// on the `xy` plane of a plane curve and on every plane of a space curve.
///
/// # Errors
/// A surface (regions are drawn for curves), a `tolerance` out of its range.
pub fn geojson(job: &Job, alpha: Alpha, tolerance: Option<f64>) -> anyhow::Result<Vec<u8>> {
    let regions: Vec<(Membership, Plane, Region)> = match &job.model {
        Model::Planar(c) => regions(c, &[Plane::Xy], alpha, tolerance)?,
        Model::Spatial(c) => regions(c, &Plane::ALL, alpha, tolerance)?,
        _ => {
            return Err(OptionError {
                option: "JOB",
                message: "regions are drawn for curves; for a surface, ask `t2spline membership` of points or `t2spline section --at X0,Y0`".into(),
            }
            .into())
        }
    };
    let features: Vec<RegionFeature<'_>> = regions
        .iter()
        .map(|(membership, plane, region)| RegionFeature {
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
                    t2spline::Error::Tolerance { .. } => anyhow::Error::from(OptionError {
                        option: "--tolerance",
                        message: e.to_string(),
                    }),
                    other => other.into(),
                })?;
            if let Some(r) = region {
                out.push((m, plane, r));
            }
        }
    }
    Ok(out)
}
