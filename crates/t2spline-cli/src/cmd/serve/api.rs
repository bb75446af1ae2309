//! The JSON API of `t2spline serve`, for the page and for scripts. Every
//! body is a job file's text (read with the limits and checks of job files)
//! and every answer is what the command of the same name writes:
//!
//! | request | answer |
//! |---|---|
//! | `GET /api/job` | `{"name", "text", "saveable"}`: the job as read at start |
//! | `POST /api/run` | the result, the bytes `t2spline run` writes |
//! | `POST /api/canonical` | the job in canonical form (explicit knots, weights, heights) |
//! | `POST /api/region[?tolerance=T]` | the regions at the job's alpha, as `t2spline region [--tolerance T]` writes them |
//! | `POST /api/membership` | `{"job": TEXT, "points": CSV}`: the grades, as `t2spline membership` writes them |
//! | `POST /api/save` | the job written over the file named on the command line, as `run -o` writes |
//!
//! A job that breaks a rule is answered 422 with `{"problems": [...]}`, one
//! line each as the command line prints them (without `t2spline: `).

use std::path::Path;

use t2spline::job::Overrides;
use t2spline_io::job::MAX_FILE_BYTES;
use t2spline_io::{MissingAlpha, Prepared};
use tiny_http::Request;

use super::answer::{Answer, Served};
use super::security::header;
use crate::cmd::prepare::{about_run, OptionError};
use crate::exit::Exit;

/// As `run` refuses a missing alpha.
const GIVE_ALPHA: MissingAlpha<'static> = MissingAlpha::Refuse {
    advice: "give it in the job file or with --alpha",
};

/// The answer to an error of a command: 422 for bad input with the
/// command's lines, 500 for a bug.
fn failed(e: &anyhow::Error) -> Answer {
    let status = match Exit::of(e) {
        Exit::Invalid => 422,
        Exit::Read => 400,
        _ => 500,
    };
    let problems: Vec<String> = format!("{e:#}").lines().map(str::to_owned).collect();
    Answer::json(status, &serde_json::json!({ "problems": problems }))
}

/// Reads the body as a job file's text (at most 64 MiB, UTF-8) and answers
/// it with `answer`.
pub fn with_body(
    request: &mut Request,
    job: &Served,
    answer: impl FnOnce(&str, &Served) -> anyhow::Result<Answer>,
) -> Answer {
    // A declared length past the limit is refused unread.
    let declared = header(request, "Content-Length").and_then(|l| l.trim().parse::<u64>().ok());
    if declared.is_some_and(|n| n > MAX_FILE_BYTES) {
        return Answer::problem(
            413,
            &format!(
                "{}: the request body is larger than a job file may be ({} MiB)",
                job.name,
                MAX_FILE_BYTES >> 20
            ),
        );
    }
    let text = match t2spline_io::job::read_text_from(request.as_reader(), &job.name) {
        Ok(text) => text,
        Err(e) => return failed(&e.into()),
    };
    answer(&text, job).unwrap_or_else(|e| failed(&e))
}

/// The job as read at start.
pub fn job(job: &Served) -> Answer {
    Answer::json(
        200,
        &serde_json::json!({
            "name": job.name,
            "text": job.text,
            "saveable": job.path.is_some(),
        }),
    )
}

/// The job prepared as `run` prepares it (no overrides: the page edits the
/// job itself).
fn prepare(text: &str, job: &Served) -> anyhow::Result<Prepared> {
    Prepared::from_text(text, &job.name, &Overrides::default(), GIVE_ALPHA).map_err(about_run)
}

/// `t2spline run`'s result.
pub fn run(text: &str, job: &Served) -> anyhow::Result<Answer> {
    let result = prepare(text, job)?.run().map_err(about_run)?;
    let mut bytes = Vec::new();
    t2spline_io::write_json_pretty(&mut bytes, &result)?;
    Ok(Answer::new(200, "application/json", bytes))
}

/// The job in canonical form.
pub fn canonical(text: &str, job: &Served) -> anyhow::Result<Answer> {
    let parsed = t2spline_io::parse_job(text, &job.name)?;
    Ok(Answer::json(200, &t2spline_io::job_json(&parsed)))
}

/// `t2spline region`'s GeoJSON at the job's alpha, with the query's
/// `tolerance` as `--tolerance` (the page asks for a fraction of a pixel:
/// the default, 1e-6 of the diagonal, costs tens of milliseconds).
pub fn region(text: &str, job: &Served, query: Option<&str>) -> anyhow::Result<Answer> {
    let tolerance = match query {
        None => None,
        Some(t) => Some(t.parse::<f64>().map_err(|_| OptionError {
            option: "--tolerance",
            message: format!("{}: not a number", t2spline_io::printable(t)),
        })?),
    };
    let prepared = prepare(text, job)?;
    let alpha = prepared.settings().alpha();
    let bytes = crate::cmd::region::geojson(prepared.job(), alpha, tolerance)?;
    Ok(Answer::new(200, "application/geo+json", bytes))
}

/// `t2spline membership`'s CSV of `{"job": TEXT, "points": CSV}`.
pub fn membership(text: &str, job: &Served) -> anyhow::Result<Answer> {
    let request: serde_json::Value = serde_json::from_str(text)
        .map_err(|e| anyhow::anyhow!("request: not {{\"job\": TEXT, \"points\": CSV}}: {e}"))?;
    let (Some(job_text), Some(points)) = (request["job"].as_str(), request["points"].as_str())
    else {
        anyhow::bail!("request: not {{\"job\": TEXT, \"points\": CSV}}");
    };
    let parsed = t2spline_io::parse_job(job_text, &job.name)?;
    let points = t2spline_io::set::parse_points(points, "points.csv")?;
    let bytes = crate::cmd::membership::grades_csv(&parsed, &points, Path::new("points.csv"))?;
    Ok(Answer::new(200, "text/csv", bytes))
}

/// Saves the job (checked first) over the file named on the command line.
pub fn save(text: &str, job: &Served) -> anyhow::Result<Answer> {
    let Some(path) = &job.path else {
        return Ok(Answer::problem(
            409,
            "no job file was named on the command line: download the job instead",
        ));
    };
    t2spline_io::parse_job(text, &job.name)?;
    t2spline_io::write_atomic(path, text.as_bytes())?;
    Ok(Answer::json(200, &serde_json::json!({ "saved": job.name })))
}
