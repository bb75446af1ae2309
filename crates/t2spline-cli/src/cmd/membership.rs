//! `t2spline membership JOB.json POINTS.csv [-o OUT.csv]`: the membership
//! grades of query points in the fuzzy curve or surface as a set.

use std::path::Path;

use t2spline::job::{Job, ModelVisitor};
use t2spline::set::Grades;
use t2spline::{FuzzyCurve, FuzzySurface};
use t2spline_io::set::{parse_points, write_membership_csv, QueryPoints};

use super::model_kind::ModelKind;
use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::MembershipArgs;
use crate::output::{is_stdio, job_name, read_input, read_job, Outputs};

pub fn membership(args: &MembershipArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path(), args.points.as_path()]).file("--output", out)?;
    }
    if is_stdio(&args.job) && is_stdio(&args.points) {
        return Err(OptionError {
            option: "POINTS",
            message: "standard input (`-`) can hold the job or the points, not both".into(),
        }
        .into());
    }
    let job = read_job(&args.job)?;
    let points = parse_points(&read_input(&args.points)?, &job_name(&args.points))?;
    let bytes = grades_csv(&job, &points, &args.points)?;
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

/// The grades of `points` (read from `points_file`, as messages name it) in
/// `job`'s model, as the CSV bytes of `t2spline membership` (also the
/// `serve` page's).
///
/// # Errors
/// Points of another dimension than the model's.
pub fn grades_csv(job: &Job, points: &QueryPoints, points_file: &Path) -> anyhow::Result<Vec<u8>> {
    let kind = ModelKind::of(&job.model)?;
    let (model_dimension, what) = (kind.dimension(), kind.name());
    if points.dimension() != model_dimension {
        let header = if model_dimension == 2 { "x,y" } else { "x,y,z" };
        return Err(OptionError {
            option: "POINTS",
            message: format!(
                "{}: the job is {what}, so the header must be {header}",
                t2spline_io::printable(&points_file.display().to_string())
            ),
        }
        .into());
    }
    job.model.visit(Grade(points))
}

/// The grades of the query points, as CSV bytes.
struct Grade<'a>(&'a QueryPoints);

impl ModelVisitor for Grade<'_> {
    type Output = anyhow::Result<Vec<u8>>;

    fn curve<const D: usize>(self, curve: &FuzzyCurve<D>) -> Self::Output {
        let points = same_dimension::<D>(self.0);
        let grades = curve.memberships(&points)?;
        csv(&points, &grades)
    }

    fn surface<const D: usize>(self, surface: &FuzzySurface<D>) -> Self::Output {
        let points = same_dimension::<D>(self.0);
        let grades = surface.memberships(&points)?;
        csv(&points, &grades)
    }
}

/// The points as arrays of `D` coordinates (the dimension was checked).
fn same_dimension<const D: usize>(points: &QueryPoints) -> Vec<[f64; D]> {
    let take = |p: &[f64]| std::array::from_fn(|c| p.get(c).copied().unwrap_or(0.0));
    match points {
        QueryPoints::Plane(p) => p.iter().map(|p| take(p)).collect(),
        QueryPoints::Space(p) => p.iter().map(|p| take(p)).collect(),
    }
}

fn csv<const D: usize>(points: &[[f64; D]], grades: &[Grades]) -> anyhow::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    write_membership_csv(&mut bytes, points, grades)?;
    Ok(bytes)
}
