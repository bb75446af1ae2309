//! `t2spline export JOB.json -o FILE [--format dxf|step|iges|obj] [--alpha A]
//! [--type-reduction NAME]`: the exact curves of the run, the defuzzified one
//! by the chosen type reduction.

use std::path::{Path, PathBuf};

use t2spline::job::LengthUnit;
use t2spline_io::{CadFormat, Prepared};

use super::prepare::{about_run, note_alpha, prepare, reduction_overrides, OptionError};
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
        let format = match (args.format.map(from_arg), CadFormat::from_extension(&args.output)) {
            (Some(given), Some(named)) if given != named => {
                return Err(OptionError {
                    option: "--format",
                    message: format!(
                        "{given} contradicts the name {}, whose extension says {named}: leave --format out, or name the file for {given}",
                        shown(&args.output)
                    ),
                }
                .into())
            }
            (Some(given), _) => given,
            (None, _) => from_extension(&args.output)?,
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
    let name = if is_stdio(&plan.output) {
        "t2spline".to_owned()
    } else {
        plan.output
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
    };
    // clap allows only the units' names.
    let units = args.units.as_deref().and_then(LengthUnit::named);
    let text = plan
        .prepared
        .cad(plan.format, name, &plan.source, units)
        .map_err(about_run)?;
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
    CadFormat::from_extension(path).ok_or_else(|| {
        OptionError {
            option: "--format",
            message: format!(
                "missing: the extension of {} names no format (.dxf, .step, .stp, .iges, .igs, .obj); give --format dxf|step|iges|obj",
                if is_stdio(path) { "<stdout>".to_owned() } else { shown(path) }
            ),
        }
        .into()
    })
}
