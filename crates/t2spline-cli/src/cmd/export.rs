//! `t2spline export JOB.json -o FILE [--format dxf|step|iges|obj] [--alpha A]
//! [--type-reduction NAME]`: the exact curves of the run, the defuzzified one
//! by the chosen type reduction.

use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use t2spline_io::{render_cad, CadFormat, CadMeta, Prepared};

use super::prepare::{about_option, note_alpha, prepare, reduction_overrides, OptionError};
use crate::clash::Claims;
use crate::cli::{CadFormatArg, ExportArgs};
use crate::output::{is_stdio, job_name, shown, Outputs};

/// An export with every input validated.
struct Plan {
    prepared: Prepared,
    source: String,
    format: CadFormat,
    output: PathBuf,
}

impl Plan {
    fn new(args: &ExportArgs) -> anyhow::Result<Plan> {
        let format = match args.format {
            Some(f) => from_arg(f),
            None => from_extension(&args.output)?,
        };
        Claims::new([args.job.as_path()]).file("--output", &args.output)?;
        let prepared = prepare(&args.job, &reduction_overrides(args.alpha, &args.reduction))?;
        note_alpha(
            "export",
            prepared.settings(),
            args.alpha.is_some(),
            "is ignored (the defuzzified curve does not depend on it)",
        );
        Ok(Plan {
            prepared,
            source: job_name(&args.job),
            format,
            output: args.output.clone(),
        })
    }
}

pub fn export(args: &ExportArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let (job, settings) = (plan.prepared.job(), plan.prepared.settings());
    let geometry = job.geometry(settings).map_err(about_option)?;
    let geometry = if plan.format.clamps() {
        geometry.clamped()
    } else {
        geometry
    };
    let name = if is_stdio(&plan.output) {
        "t2spline".to_owned()
    } else {
        plan.output
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
    };
    let meta = CadMeta {
        name,
        description: job.description.clone(),
        timestamp: timestamp(),
    };
    let text = render_cad(plan.format, &geometry, &meta, &plan.source)?;
    let mut out = Outputs::default();
    out.to(Some(&plan.output), text.into_bytes());
    out.commit()
}

fn from_arg(f: CadFormatArg) -> CadFormat {
    match f {
        CadFormatArg::Dxf => CadFormat::Dxf,
        CadFormatArg::Step => CadFormat::Step,
        CadFormatArg::Iges => CadFormat::Iges,
        CadFormatArg::Obj => CadFormat::Obj,
    }
}

/// The format named by the output's extension.
fn from_extension(path: &Path) -> anyhow::Result<CadFormat> {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("dxf") => Ok(CadFormat::Dxf),
        Some("step" | "stp") => Ok(CadFormat::Step),
        Some("iges" | "igs") => Ok(CadFormat::Iges),
        Some("obj") => Ok(CadFormat::Obj),
        _ => Err(OptionError {
            option: "--format",
            message: format!(
                "missing: the extension of {} names no format (.dxf, .step, .stp, .iges, .igs, .obj); give --format dxf|step|iges|obj",
                if is_stdio(path) { "<stdout>".to_owned() } else { shown(path) }
            ),
        }
        .into()),
    }
}

/// The time of writing as `YYYY-MM-DDThh:mm:ss` (UTC); `SOURCE_DATE_EPOCH`
/// (seconds since 1970), when set, replaces the clock, so that files can be
/// made reproducibly.
fn timestamp() -> String {
    let seconds = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.trim().parse::<u64>().ok())
        .unwrap_or_else(|| {
            SystemTime::now()
                .duration_since(UNIX_EPOCH)
                .map_or(0, |d| d.as_secs())
        });
    let (days, rest) = (seconds / 86_400, seconds % 86_400);
    let (year, month, day) = civil_from_days(days);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}

/// The proleptic Gregorian date of a day count since 1970-01-01 (Howard
/// Hinnant's `civil_from_days`, in 400-year eras of 146 097 days).
fn civil_from_days(days: u64) -> (u64, u64, u64) {
    let z = days + 719_468;
    let era = z / 146_097;
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + u64::from(month <= 2);
    (year, month, day)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_from_day_counts() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(59), (1970, 3, 1));
        // 2000-02-29 (a leap day of a year divisible by 400) is day 11 016.
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        assert_eq!(civil_from_days(20_819), (2027, 1, 1));
    }
}
