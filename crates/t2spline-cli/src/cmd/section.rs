//! `t2spline section JOB.json --x X0 | --at X0,Y0 [--alpha A | --levels N]
//! [-o OUT.json]`:
//! the fuzzy value at a station.

use t2spline_io::set::{write_section_json, Station};

use super::levels::{Levels, MAX_LEVELS};
use super::model_kind::ModelKind;
use super::prepare::OptionError;
use crate::clash::Claims;
use crate::cli::SectionArgs;
use crate::output::{read_job, Outputs};

pub fn section(args: &SectionArgs) -> anyhow::Result<()> {
    if let Some(out) = &args.output {
        Claims::new([args.job.as_path()]).file("--output", out)?;
    }
    let levels = Levels::from_arg(&args.levels, Some(11), MAX_LEVELS)?;
    let at = args.at.as_deref().map(parse_at).transpose()?;
    if let Some(x0) = args.x.filter(|x| !x.is_finite()) {
        return Err(missing("--x", &format!("{x0} is not a finite number")));
    }
    let job = read_job(&args.job)?;
    let levels = levels.resolve(&job)?;
    let tolerance_error = |e: t2spline::Error| match e {
        t2spline::Error::Tolerance { .. } | t2spline::Error::ToleranceTooCoarse { .. } => {
            anyhow::Error::from(OptionError {
                option: "--tolerance",
                message: e.to_string(),
            })
        }
        other => other.into(),
    };
    let (station, sections) = match (ModelKind::of(&job.model)?, args.x, at) {
        (ModelKind::PlaneCurve(c), Some(x0), None) => (
            Station::X(x0),
            c.sections(x0, &levels, args.tolerance).map_err(tolerance_error)?,
        ),
        (ModelKind::Surface(s), None, Some([x0, y0])) => {
            if args.tolerance.is_some() {
                return Err(OptionError {
                    option: "--tolerance",
                    message: "applies to plane curves; a surface's interval ends are refined to about 1e-9 of its height".into(),
                }
                .into());
            }
            (Station::Xy(x0, y0), s.sections([x0, y0], &levels)?)
        }
        (ModelKind::PlaneCurve(_), _, _) => return Err(missing("--x", "the job is a plane curve: give its station as --x X0")),
        (ModelKind::Surface(_), _, _) => return Err(missing("--at", "the job is a surface: give its station as --at X0,Y0")),
        (ModelKind::SpaceCurve(_), _, _) => {
            return Err(crate::output::unsuited(
                &args.job,
                "sections are taken of plane curves (--x) and surfaces (--at); for a space curve, ask `t2spline region` for its projections",
            ))
        }
    };
    let mut bytes = Vec::new();
    write_section_json(&mut bytes, station, &sections)?;
    let mut out = Outputs::default();
    out.to(args.output.as_deref(), bytes);
    out.commit()
}

fn missing(option: &'static str, message: &str) -> anyhow::Error {
    OptionError {
        option,
        message: message.to_owned(),
    }
    .into()
}

/// `X0,Y0` as two finite numbers.
fn parse_at(text: &str) -> anyhow::Result<[f64; 2]> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let numbers: Vec<f64> = parts
        .iter()
        .filter_map(|p| p.parse::<f64>().ok())
        .filter(|x| x.is_finite())
        .collect();
    match (parts.len(), numbers.as_slice()) {
        (2, &[x, y]) => Ok([x, y]),
        _ => Err(missing(
            "--at",
            &format!(
                "`{}` is not two finite numbers X0,Y0",
                t2spline_io::printable(text)
            ),
        )),
    }
}
