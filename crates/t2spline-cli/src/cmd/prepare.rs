//! The one prelude of every subcommand that runs a job: the job read (a file
//! or standard input), the settings of its run made from the options by the
//! shared path ([`t2spline_io::Prepared`]: checked once, in the core), errors
//! naming the option (`--alpha`, `--samples`, `--derivatives`), and the notes
//! on alpha: one that the type reduction does not use, one that lies a few
//! ulps above a number's lower height (the other side of the paper's jump).

use std::path::Path;

use t2spline::job::{Overrides, Setting, Settings};
use t2spline_io::{MissingAlpha, Prepared, RunError};

use crate::cli::ReductionArg;
use crate::output::{job_name, read_input};

pub use crate::exit::OptionError;

/// How a user of the command line gives a missing alpha.
const GIVE_ALPHA: MissingAlpha<'static> = MissingAlpha::Refuse {
    advice: "give it in the job file or with --alpha",
};

/// The option that sets `setting`.
pub fn option_name(setting: Setting) -> &'static str {
    match setting {
        Setting::Alpha => "--alpha",
        Setting::Samples => "--samples",
        Setting::Derivatives => "--derivatives",
        Setting::Points => "--points",
        Setting::Threads => "--threads",
        Setting::Levels => "--levels",
        Setting::At => "--at",
        Setting::Order => "--order",
        Setting::Datum => "--datum",
        Setting::Degree => "--degree",
        Setting::ControlPoints => "--control-points",
    }
}

/// An error of preparing or running a job, a setting's named by its option.
pub fn about_run(e: RunError) -> anyhow::Error {
    match e {
        RunError::File(e) => e.into(),
        RunError::Setting { setting, message } => OptionError {
            option: option_name(setting),
            message,
        }
        .into(),
        RunError::Core(e) => e.into(),
    }
}

/// A core error, one about a setting named by its option.
pub fn about_option(e: t2spline::Error) -> anyhow::Error {
    about_run(e.into())
}

/// The overrides of the commands that draw or export a job: `--alpha` and
/// `--type-reduction`.
pub fn reduction_overrides(alpha: Option<f64>, reduction: &ReductionArg) -> Overrides {
    Overrides {
        alpha,
        type_reduction: reduction.type_reduction,
        ..Overrides::default()
    }
}

/// The job at `path` (`-`: standard input) prepared for a run with the
/// options' `overrides`; a missing alpha is refused.
///
/// # Errors
/// The job file's problems, and an [`OptionError`] for an option whose value
/// breaks its rule.
pub fn prepare(path: &Path, overrides: &Overrides) -> anyhow::Result<Prepared> {
    Ok(prepare_with(path, overrides, GIVE_ALPHA)?.0)
}

/// [`prepare`], with `missing_alpha` saying what a missing alpha does; with
/// the job's text, as read.
///
/// # Errors
/// As [`prepare`].
pub fn prepare_with(
    path: &Path,
    overrides: &Overrides,
    missing_alpha: MissingAlpha<'_>,
) -> anyhow::Result<(Prepared, String)> {
    let text = read_input(path)?;
    let prepared =
        Prepared::from_text(&text, &job_name(path), overrides, missing_alpha).map_err(about_run)?;
    Ok((prepared, text))
}

/// The notes on a run's alpha ([`Settings::alpha_notes`]), each a line
/// `note: …`: the alpha given by `--alpha` if `from_option`, else by the job
/// file, and what it still does in the command (`effect`).
pub fn alpha_notes(settings: &Settings, from_option: bool, effect: &str) -> Vec<String> {
    let source = if from_option {
        "--alpha "
    } else {
        "the job's alpha "
    };
    settings
        .alpha_notes()
        .iter()
        .map(|note| format!("note: {}", note.sentence(source, effect)))
        .collect()
}

/// Says [`alpha_notes`] on standard error, one line each, for `command`.
pub fn note_alpha(command: &str, settings: &Settings, from_option: bool, effect: &str) {
    for note in alpha_notes(settings, from_option, effect) {
        crate::output::note(command, note);
    }
}
