//! `t2spline plot JOB.json -o DIR [--format svg|png|both] [--point I --axis x|y|z]
//! [--aspect equal|auto] [--view AZ,EL] [--alpha A] [--type-reduction NAME]`.

use t2spline::job::Job;
use t2spline::Axis;
use t2spline_plot::{
    all_figures, render_files, terrain_left_out, Aspect, FigureOptions, Format, NumberChoice,
};

use super::model_kind::ModelKind;
use super::prepare::{note_alpha, prepare, reduction_overrides, OptionError};
use crate::clash::Claims;
use crate::cli::{AspectArg, AxisArg, FigureArgs, FormatArg, PlotArgs, PointArg};
use crate::output::Outputs;

/// The figure options of `--point`, `--axis`, `--aspect`, `--view` and
/// `--station` for `job`.
///
/// # Errors
/// An [`OptionError`] of `--point` if `I,J` is given for a curve or lies
/// outside the net; of `--station` if it is not finite or the job is not a
/// plane curve.
pub fn figure_options(args: &FigureArgs, job: &Job) -> Result<FigureOptions, OptionError> {
    Ok(FigureOptions {
        number: NumberChoice {
            point: point_index(args.point, job)?,
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
        station: station(args.station, job)?,
    })
}

/// `--station`: a finite x, for a plane curve only.
fn station(x0: Option<f64>, job: &Job) -> Result<Option<f64>, OptionError> {
    let Some(x0) = x0 else {
        return Ok(None);
    };
    let message = if !x0.is_finite() {
        format!("the station must be a finite x, got {x0}")
    } else if !ModelKind::of(&job.model)?.is_plane_curve() {
        "the section at a station is drawn for plane curves (x, y) only".to_owned()
    } else {
        return Ok(Some(x0));
    };
    Err(OptionError {
        option: "--station",
        message,
    })
}

/// The row-major index of `--point` in `job` (range checked later, with the
/// axis, by the figure).
fn point_index(point: PointArg, job: &Job) -> Result<usize, OptionError> {
    let (i, j) = match point {
        PointArg::Index(k) => return Ok(k),
        PointArg::Net(i, j) => (i, j),
    };
    let message = match job.model.net_shape() {
        None => format!(
            "{i},{j} names a point of a surface's net, but this job is a curve: give --point I"
        ),
        Some([nu, nv]) if i < nu && j < nv => return Ok(i * nv + j),
        Some([nu, nv]) => format!(
            "{i},{j} lies outside the {nu} × {nv} control net (I from 0 to {}, J from 0 to {})",
            nu - 1,
            nv - 1
        ),
    };
    Err(OptionError {
        option: "--point",
        message,
    })
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
    let prepared = prepare(&args.job, &reduction_overrides(args.alpha, &args.reduction))?;
    let settings = prepared.settings();
    note_alpha(
        "plot",
        settings,
        args.alpha.is_some(),
        "is used only by the paper's reduction in the figures number, distance-alpha and reductions (stage 2 is cut at alpha = 0)",
    );
    // Stages 2–4 as `run` gives them; the paper's level where it is drawn.
    let (alpha, job) = (settings.paper_alpha(), prepared.job());
    let format = match args.format {
        Some(FormatArg::Svg) => Format::Svg,
        Some(FormatArg::Png) => Format::Png,
        Some(FormatArg::Both) => Format::Both,
        None if t2spline_plot::PNG => Format::Both,
        None => Format::Svg,
    };
    // Everything is rendered before anything is written, and written all or
    // nothing; the paths written go to standard output.
    let figures =
        all_figures(job, alpha, &figure_options(&args.figures, job)?).map_err(about_number)?;
    if let Some(reason) = t2spline_plot::set_figures_left_out(job) {
        crate::output::note(
            "plot",
            format!("note: the figures membership, section and measures are left out, and stages 1–2 shade no regions: {reason}"),
        );
    }
    if job.model.is_surface() {
        if let Some(reason) = terrain_left_out(job)? {
            crate::output::note(
                "plot",
                format!("note: the terrain figures (envelope-width, shoreline, terrain-measures) are left out: {reason}"),
            );
        }
    }
    let files = render_files(&figures, format)?;
    crate::output::refuse_extension(
        "--output",
        &args.output,
        &["svg", "png", "pdf", "html", "jpg", "jpeg"],
        "plot writes a folder of figures (SVG and PNG files, as --format says), not one file: name a folder, e.g. `figures`",
    )?;
    Claims::new([args.job.as_path()]).folder(
        "--output",
        &args.output,
        files.iter().map(|(name, _)| name.as_str()),
    )?;
    let mut out = Outputs::default();
    let mut listing = String::new();
    for (name, bytes) in files {
        listing.push_str(&format!("{}\n", args.output.join(&name).display()));
        out.in_dir(&args.output, &name, bytes);
    }
    out.to(None, listing.into_bytes());
    out.commit()
}
