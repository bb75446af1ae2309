//! The JSON API of `t2spline serve`, for the page and for scripts. Every
//! body is a job file's text (read with the limits and checks of job files)
//! and every answer is what the command of the same name writes:
//!
//! | request | answer |
//! |---|---|
//! | `GET /api/job[?reload=1]` | `{"name", "text", "saveable"}`: the job as read at start (`reload`: as the file holds it now) |
//! | `POST /api/run` | the result, the bytes `t2spline run` writes |
//! | `POST /api/canonical` | the job in canonical form (explicit knots, weights, heights) |
//! | `POST /api/region[?tolerance=T]` | the regions at the job's alpha, as `t2spline region [--tolerance T]` writes them |
//! | `POST /api/membership` | `{"job": TEXT, "points": CSV}`: the grades, as `t2spline membership` writes them |
//! | `POST /api/save[?overwrite=1]` | the job written over the file named on the command line, as `run -o` writes; 409 with `"changed": true` when the file changed since it was read, unless `overwrite` |
//!
//! A job that breaks a rule is answered 422 with `{"problems": [...]}`, one
//! line each as the command line prints them (without `t2spline: `).

use std::path::Path;

use t2spline::job::Overrides;
use t2spline_io::job::MAX_FILE_BYTES;
use t2spline_io::{MissingAlpha, Prepared};

use super::answer::{Answer, Served};
use super::http::Request;
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
/// it with `answer`. A declared length past the limit is refused unread.
pub fn with_body(
    request: &mut Request,
    job: &Served,
    answer: impl FnOnce(&str, &Served) -> anyhow::Result<Answer>,
) -> Answer {
    let body = match request.body(MAX_FILE_BYTES, &job.name) {
        Ok(body) => body,
        Err(failure) => return Answer::problem(failure.status, &failure.message),
    };
    let text = match t2spline_io::job::read_text_from(body.as_slice(), &job.name) {
        Ok(text) => text,
        Err(e) => return failed(&e.into()),
    };
    answer(&text, job).unwrap_or_else(|e| failed(&e))
}

/// The job as read at start, or with `reload` as the file holds it now
/// (the page's answer to a file changed on disk).
pub fn job(job: &Served, reload: bool) -> Answer {
    let text = match (&job.path, reload) {
        (Some(path), true) => match t2spline_io::job::read_text(path) {
            Ok(text) => {
                let mut on_disk = job.on_disk();
                on_disk.clone_from(&text);
                text
            }
            Err(e) => return failed(&e.into()),
        },
        _ => job.text.clone(),
    };
    Answer::json(
        200,
        &serde_json::json!({
            "name": job.name,
            "text": text,
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
    let bytes = crate::cmd::region::geojson(prepared.job(), &[alpha], tolerance)?;
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

/// Saves the job (checked first) over the file named on the command line,
/// unless the file changed on disk since the server read or wrote it (409,
/// `"changed": true`) and `overwrite` was not asked.
pub fn save(text: &str, job: &Served, overwrite: bool) -> anyhow::Result<Answer> {
    let Some(path) = &job.path else {
        return Ok(Answer::problem(
            409,
            "no job file was named on the command line: download the job instead",
        ));
    };
    t2spline_io::parse_job(text, &job.name)?;
    let mut on_disk = job.on_disk();
    let now = std::fs::read(path).ok();
    if !overwrite && now.as_deref() != Some(on_disk.as_bytes()) {
        let message = format!(
            "{}: the file changed on disk since it was read; reload it, or save again to overwrite it",
            job.name
        );
        return Ok(Answer::json(
            409,
            &serde_json::json!({ "problems": [message], "changed": true }),
        ));
    }
    t2spline_io::write_atomic(path, text.as_bytes())?;
    text.clone_into(&mut on_disk);
    Ok(Answer::json(200, &serde_json::json!({ "saved": job.name })))
}
