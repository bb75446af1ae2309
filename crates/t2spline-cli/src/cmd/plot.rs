//! `t2spline plot JOB.json -o DIR [--format svg|png|both] [--point I --axis x|y|z]
//! [--aspect equal|auto] [--view AZ,EL] [--alpha A]`.

use t2spline::job::Overrides;
use t2spline::Axis;
use t2spline_plot::{all_figures, render_files, Aspect, FigureOptions, Format, NumberChoice};

use super::settings::{settings, OptionError};
use crate::cli::{AspectArg, AxisArg, FigureArgs, FormatArg, PlotArgs};
use crate::output::{read_job_text, Outputs};

/// The figure options of `--point`, `--axis` and `--aspect`.
pub fn figure_options(args: &FigureArgs) -> FigureOptions {
    FigureOptions {
        number: NumberChoice {
            point: args.point,
            axis: match args.axis {
                AxisArg::X => Axis::X,
                AxisArg::Y => Axis::Y,
                AxisArg::Z => Axis::Z,
            },
        },
        aspect: match args.aspect {
            AspectArg::Equal => Aspect::Equal,
            AspectArg::Auto => Aspect::Auto,
        },
        view: args.view,
    }
}

/// A plotting error, naming the option that chose a point or axis the job lacks.
pub fn about_number(e: t2spline_plot::Error) -> anyhow::Error {
    match e {
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
    }
}

pub fn plot(args: &PlotArgs) -> anyhow::Result<()> {
    let (job, text) = read_job_text(&args.job)?;
    let overrides = Overrides {
        alpha: args.alpha,
        ..Overrides::default()
    };
    let alpha = settings(&job, &overrides, &args.job, &text)?.alpha;
    let format = match args.format {
        FormatArg::Svg => Format::Svg,
        FormatArg::Png => Format::Png,
        FormatArg::Both => Format::Both,
    };
    // Everything is rendered before anything is written, and written all or
    // nothing; the paths written go to standard output.
    let figures = all_figures(&job, alpha, &figure_options(&args.figures)).map_err(about_number)?;
    let mut out = Outputs::default();
    let mut listing = String::new();
    for (name, bytes) in render_files(&figures, format)? {
        listing.push_str(&format!("{}\n", args.output.join(&name).display()));
        out.in_dir(&args.output, &name, bytes);
    }
    out.to(None, listing.into_bytes());
    out.commit()
}
