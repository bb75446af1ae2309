//! `t2spline plot JOB.json -o DIR [--format svg|png|both] [--point I --axis x|y|z] [--alpha A]`.

use t2spline::Axis;
use t2spline_plot::{all_figures, render_files, Format, NumberChoice};

use super::alpha;
use crate::cli::{AxisArg, FormatArg, PlotArgs};
use crate::output::{read_job_text, Outputs};

pub fn plot(args: &PlotArgs) -> anyhow::Result<()> {
    let option = alpha::parse_option(args.alpha)?;
    let (job, text) = read_job_text(&args.job)?;
    let alpha = alpha::required(option, &job, &args.job, &text)?;
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
    let figures = all_figures(&job, alpha, choice)?;
    let mut out = Outputs::default();
    let mut listing = String::new();
    for (name, bytes) in render_files(&figures, format)? {
        listing.push_str(&format!("{}\n", args.output.join(&name).display()));
        out.in_dir(&args.output, &name, bytes);
    }
    out.to(None, listing.into_bytes());
    out.commit()
}
