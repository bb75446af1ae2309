//! `t2spline plot JOB.json -o DIR [--format svg|png|both] [--point I --axis x|y|z] [--alpha A]`.

use t2spline::job::Overrides;
use t2spline::Axis;
use t2spline_plot::{all_figures, render_files, Format, NumberChoice};

use super::settings::{settings, OptionError};
use crate::cli::{AxisArg, FormatArg, PlotArgs};
use crate::output::{read_job_text, Outputs};

pub fn plot(args: &PlotArgs) -> anyhow::Result<()> {
    let (job, text) = read_job_text(&args.job)?;
    let overrides = Overrides {
        alpha: args.alpha,
        ..Overrides::default()
    };
    let alpha = settings(&job, &overrides, &args.job, &text)?.alpha;
    let choice = NumberChoice {
        point: args.point,
        axis: match args.axis {
            AxisArg::X => Axis::X,
            AxisArg::Y => Axis::Y,
            AxisArg::Z => Axis::Z,
        },
    };
    let format = match args.format {
        FormatArg::Svg => Format::Svg,
        FormatArg::Png => Format::Png,
        FormatArg::Both => Format::Both,
    };
    // Everything is rendered before anything is written, and written all or
    // nothing; the paths written go to standard output.
    let figures = all_figures(&job, alpha, choice).map_err(|e| match e {
        t2spline_plot::Error::NoSuchPoint { .. } => OptionError {
            option: "--point",
            message: e.to_string(),
        }
        .into(),
        t2spline_plot::Error::NoSuchAxis { .. } => OptionError {
            option: "--axis",
            message: e.to_string(),
        }
        .into(),
        other => anyhow::Error::from(other),
    })?;
    let mut out = Outputs::default();
    let mut listing = String::new();
    for (name, bytes) in render_files(&figures, format)? {
        listing.push_str(&format!("{}\n", args.output.join(&name).display()));
        out.in_dir(&args.output, &name, bytes);
    }
    out.to(None, listing.into_bytes());
    out.commit()
}
