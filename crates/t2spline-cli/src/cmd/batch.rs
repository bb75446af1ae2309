//! `t2spline run a.json b.json … -o DIR [--jobs DIR] [--csv DIR]
//! [--parquet DIR|FILE.parquet] [--jsonl FILE]`: many jobs in one process, in parallel across jobs
//! (rayon), one result per job, past failing jobs, and a summary table;
//! with a one-table output (`--parquet FILE.parquet`, `--jsonl FILE`) and
//! no `-o`, no file per job, the summary beside the table.
//!
//! Each job is all or nothing on its own: its files are complete in
//! temporary files before any is renamed. They are renamed without a flush
//! to disk each; one flush of the file systems at the end covers them all
//! (a flush per file costs a disk round trip, more than a small job).

use std::io::Write;
use std::path::{Path, PathBuf};

use rayon::prelude::*;
use t2spline::job::ALPHA_IGNORED;
use t2spline::job::{Overrides, Parameter, RunOutput};
use t2spline_io::{
    printable, sync_file_systems, write_jobs_jsonl, write_jobs_parquet, write_summary_csv,
    write_summary_parquet, JobSummary, JobsParquet, Staged, CSV_FILES, DERIVATIVES_CSV,
};

use super::prepare::{about_run, alpha_notes, prepare, OptionError};
use super::results::{overrides, Destinations};
use crate::clash::Claims;
use crate::cli::RunArgs;
use crate::exit::{Exit, JobsFailed};
use crate::output::{is_stdio, job_name, shown, NewFolders};

/// The summary's file names.
const SUMMARY_CSV: &str = "summary.csv";
const SUMMARY_PARQUET: &str = "summary.parquet";

/// Jobs run at once while the one Parquet table is written group by
/// group: enough to keep both cores busy, few enough that their results
/// take a few megabytes.
const GROUP: usize = 128;

/// A job of the run: its file and the name of its outputs.
#[derive(Debug)]
struct Entry {
    path: PathBuf,
    name: String,
}

/// A run of many jobs with its options checked.
#[derive(Debug)]
struct Batch {
    jobs: Vec<Entry>,
    overrides: Overrides,
    /// The folder of one result file per job (`-o DIR`); none when only
    /// the one table of every job is asked for.
    output: Option<PathBuf>,
    /// The folder of the summary: `-o DIR`, else the one table's.
    summary_dir: PathBuf,
    csv: Option<PathBuf>,
    /// The folder of one Parquet file per job (`--parquet DIR`).
    parquet: Option<PathBuf>,
    /// The one Parquet file of every job's samples (`--parquet FILE.parquet`).
    one_parquet: Option<PathBuf>,
    /// The one JSON Lines file of every job's samples (`--jsonl FILE`).
    jsonl: Option<PathBuf>,
}

/// What became of one job.
struct Outcome {
    summary: JobSummary,
    error: Option<anyhow::Error>,
    /// Notes for standard error (an alpha its type reduction does not use,
    /// an alpha just above a lower height).
    notes: Vec<String>,
    /// The files written, to be flushed to disk at the end.
    written: Vec<PathBuf>,
    /// The result, kept for the one Parquet or JSON Lines file of every job.
    result: Option<RunOutput>,
}

fn usage(option: &'static str, message: impl Into<String>) -> anyhow::Error {
    OptionError {
        option,
        message: message.into(),
    }
    .into()
}

/// The name of a job's outputs: its file name without `.json`.
pub(super) fn output_name(path: &Path) -> String {
    let file = path
        .file_name()
        .map_or_else(String::new, |f| f.to_string_lossy().into_owned());
    file.strip_suffix(".json").unwrap_or(&file).to_owned()
}

/// The folder of the file `path` (`.` for a bare name).
fn folder_of(path: &Path) -> PathBuf {
    path.parent()
        .filter(|d| !d.as_os_str().is_empty())
        .map_or_else(|| PathBuf::from("."), Path::to_owned)
}

/// The `*.json` files of `dir` (following links), by name; a link that
/// leads nowhere is a job too, which then fails as unreadable rather than
/// vanish without a word.
fn folder_jobs(dir: &Path) -> Result<Vec<PathBuf>, t2spline_io::Error> {
    let failed = |source| t2spline_io::Error::Read {
        path: dir.to_owned(),
        source,
    };
    let mut jobs = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(failed)? {
        let entry = entry.map_err(failed)?;
        let path = entry.path();
        if path
            .extension()
            .is_none_or(|e| !e.eq_ignore_ascii_case("json"))
        {
            continue;
        }
        // The folder's listing tells a plain file without a further look;
        // a link (or a file system that does not say) is followed.
        let file = match entry.file_type() {
            Ok(kind) if kind.is_file() => true,
            Ok(kind) if kind.is_dir() => false,
            _ => match std::fs::metadata(&path) {
                Ok(meta) => meta.is_file(),
                // Dangling, or a loop of links.
                Err(_) => std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_symlink()),
            },
        };
        if file {
            jobs.push(path);
        }
    }
    jobs.sort_by(|a, b| natural_order(&a.to_string_lossy(), &b.to_string_lossy()));
    Ok(jobs)
}

/// Names in natural order: runs of digits compared as numbers (`a2` before
/// `a10`, `a02` beside `a2`), other characters one by one, a number placed
/// among characters as its first digit is; equal so far, by their text.
fn natural_order(a: &str, b: &str) -> std::cmp::Ordering {
    use std::cmp::Ordering;
    /// A character, or a run of digits (leading zeros dropped).
    enum Token<'a> {
        Char(char),
        Number(&'a str),
    }
    fn tokens(s: &str) -> impl Iterator<Item = Token<'_>> {
        let mut rest = s;
        std::iter::from_fn(move || {
            let first = rest.chars().next()?;
            if first.is_ascii_digit() {
                let end = rest
                    .find(|c: char| !c.is_ascii_digit())
                    .unwrap_or(rest.len());
                let (run, tail) = rest.split_at(end);
                rest = tail;
                Some(Token::Number(run.trim_start_matches('0')))
            } else {
                rest = &rest[first.len_utf8()..];
                Some(Token::Char(first))
            }
        })
    }
    let compare = |x: &Token<'_>, y: &Token<'_>| match (x, y) {
        (Token::Char(p), Token::Char(q)) => p.cmp(q),
        (Token::Number(p), Token::Number(q)) => p.len().cmp(&q.len()).then(p.cmp(q)),
        (Token::Char(p), Token::Number(_)) => p.cmp(&'0').then(Ordering::Greater),
        (Token::Number(_), Token::Char(q)) => '0'.cmp(q).then(Ordering::Less),
    };
    let (mut x, mut y) = (tokens(a), tokens(b));
    loop {
        match (x.next(), y.next()) {
            (None, None) => return a.cmp(b),
            (None, Some(_)) => return Ordering::Less,
            (Some(_), None) => return Ordering::Greater,
            (Some(p), Some(q)) => {
                let order = compare(&p, &q);
                if order.is_ne() {
                    return order;
                }
            }
        }
    }
}

impl Batch {
    fn new(args: RunArgs) -> anyhow::Result<Batch> {
        let mut paths = args.job.clone();
        if let Some(dir) = &args.jobs {
            let found = folder_jobs(dir)?;
            if found.is_empty() && paths.is_empty() {
                return Err(usage(
                    "--jobs",
                    format!("{} holds no *.json file", shown(dir)),
                ));
            }
            paths.extend(found);
        }
        if paths.iter().any(|p| is_stdio(p)) {
            return Err(usage(
                "JOB",
                "standard input (`-`) can only be read when it is the one job",
            ));
        }
        let one_table = args
            .parquet
            .as_ref()
            .filter(|p| {
                p.extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("parquet"))
            })
            .or(args.jsonl.as_ref());
        let output = match (args.output.as_deref(), one_table) {
            (Some(dir), _) if !is_stdio(dir) => Some(dir.to_owned()),
            // Only the one table: no file per job.
            (None, Some(_)) => None,
            _ => {
                return Err(usage(
                    "--output",
                    format!(
                        "{} jobs write one result each: give a folder for them, -o DIR (or only one table of every job's samples: --parquet FILE.parquet, --jsonl FILE)",
                        paths.len()
                    ),
                ))
            }
        };
        let summary_dir = match (&output, one_table) {
            (Some(dir), _) => dir.clone(),
            (None, Some(file)) => folder_of(file),
            (None, None) => PathBuf::from("."),
        };
        let mut jobs: Vec<Entry> = Vec::with_capacity(paths.len());
        let mut seen = std::collections::HashMap::new();
        for path in paths {
            let name = output_name(&path);
            if name.is_empty() || (name == "summary" && args.parquet.is_some()) {
                return Err(usage(
                    "JOB",
                    format!("{}: no output can be named after this file", shown(&path)),
                ));
            }
            if let Some(other) = seen.insert(name.clone(), path.clone()) {
                return Err(usage(
                    "JOB",
                    format!(
                        "{} and {} would both write {}.json: rename one",
                        shown(&other),
                        shown(&path),
                        printable(&name)
                    ),
                ));
            }
            jobs.push(Entry { path, name });
        }
        // `--parquet FILE.parquet`: one file for every job; else a folder.
        let (parquet, one_parquet) = match args.parquet.clone() {
            Some(p)
                if p.extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("parquet")) =>
            {
                (None, Some(p))
            }
            other => (other, None),
        };
        let batch = Batch {
            jobs,
            overrides: overrides(&args),
            output,
            summary_dir,
            csv: args.csv,
            parquet,
            one_parquet,
            jsonl: args.jsonl,
        };
        batch.check_outputs()?;
        Ok(batch)
    }

    /// No output overwrites a job file (`--jobs DIR -o DIR`), and no two
    /// outputs are one file or lie inside a job's CSV folder (the rule of
    /// [`Claims`]), in job order.
    fn check_outputs(&self) -> anyhow::Result<()> {
        let mut claims = Claims::new(self.jobs.iter().map(|j| j.path.as_path()));
        for job in &self.jobs {
            self.destinations(job).claim(&mut claims)?;
        }
        claims.file("--output", &self.summary_dir.join(SUMMARY_CSV))?;
        if let Some(dir) = &self.parquet {
            claims.file("--parquet", &dir.join(SUMMARY_PARQUET))?;
        }
        if let Some(file) = &self.one_parquet {
            claims.file("--parquet", file)?;
            claims.file("--parquet", &self.summary_dir.join(SUMMARY_PARQUET))?;
        }
        if let Some(file) = &self.jsonl {
            claims.file("--jsonl", file)?;
        }
        Ok(())
    }

    /// Where a job's files go.
    fn destinations(&self, job: &Entry) -> Destinations {
        Destinations {
            json: self
                .output
                .as_ref()
                .map(|d| d.join(format!("{}.json", job.name))),
            csv: self.csv.as_ref().map(|d| d.join(&job.name)),
            parquet: self
                .parquet
                .as_ref()
                .map(|d| d.join(format!("{}.parquet", job.name))),
        }
    }

    /// Reads, runs and writes one job.
    fn run_one(&self, job: &Entry) -> Outcome {
        let mut summary = JobSummary {
            name: job.name.clone(),
            file: job_name(&job.path),
            status: Exit::Ok.status().to_owned(),
            type_reduction: None,
            regime: None,
            alpha: None,
            h: None,
            error_max: None,
            error_max_at: None,
            error_max_at_v: None,
            error_rms: None,
            description: None,
            message: None,
        };
        let (mut written, mut notes, mut kept) = (Vec::new(), Vec::new(), None);
        let error = self.compute(job).and_then(|(result, h, said)| {
            notes = said;
            summary.h = Some(h);
            summary.type_reduction = Some(result.type_reduction.name().to_owned());
            // Alpha and the regime are the paper's reduction's (docs/method.md §9).
            summary.regime = result.regime.map(|r| r.as_str().to_owned());
            summary.alpha = result.alpha_used.then_some(result.alpha);
            summary.error_max = Some(result.error.max);
            (summary.error_max_at, summary.error_max_at_v) = match result.error.max_at {
                Parameter::T(t) => (Some(t), None),
                Parameter::Uv([u, v]) => (Some(u), Some(v)),
            };
            summary.error_rms = Some(result.error.rms);
            summary.description.clone_from(&result.description);
            let out = self.destinations(job);
            out.write(Staged::deferring_sync(), &result)?;
            written = files(&out, &result);
            kept = (self.one_parquet.is_some() || self.jsonl.is_some()).then_some(result);
            Ok(())
        });
        let error = error.err();
        if let Some(e) = &error {
            summary.status = Exit::of(e).status().to_owned();
            summary.message = Some(message(&job.path, e).join("; "));
        }
        Outcome {
            summary,
            error,
            notes,
            written,
            result: kept,
        }
    }

    /// Runs every job, in parallel, in order.
    fn run_all(&self) -> Vec<Outcome> {
        self.jobs.par_iter().map(|j| self.run_one(j)).collect()
    }

    /// Whether the jobs' rows go into the one Parquet table as they are
    /// computed: when it is the only output of every job's samples (the
    /// JSON Lines file would need the results again).
    fn streams_table(&self) -> bool {
        self.one_parquet.is_some() && self.jsonl.is_none()
    }

    /// Runs every job, in order, into the one Parquet table `out`: the jobs
    /// run [`GROUP`] at a time, in parallel, and while one group runs the
    /// rows of the one before are written (two threads' work at once), so
    /// that the table is written beside the work rather than after it and
    /// the results are not all held until the end. The outcomes keep no
    /// result. The table's derivative columns are those the option asks
    /// for (every job runs with it), whether or not a job succeeds.
    ///
    /// # Errors
    /// The errors of `out`.
    fn run_into_table(&self, out: &mut (dyn Write + Send)) -> std::io::Result<Vec<Outcome>> {
        let order = self
            .overrides
            .derivatives
            .and_then(|k| usize::try_from(k).ok())
            .unwrap_or(0);
        let mut table = JobsParquet::new(out, order)?;
        let mut outcomes = Vec::with_capacity(self.jobs.len());
        let mut last: Option<(&[Entry], Vec<Outcome>)> = None;
        for group in self.jobs.chunks(GROUP) {
            let (written, done) = rayon::join(
                || last.take().map(|(g, d)| add_rows(&mut table, g, d)),
                || group.par_iter().map(|j| self.run_one(j)).collect(),
            );
            if let Some(written) = written {
                outcomes.extend(written?);
            }
            last = Some((group, done));
        }
        if let Some((group, done)) = last {
            outcomes.extend(add_rows(&mut table, group, done)?);
        }
        table.finish()?;
        Ok(outcomes)
    }

    /// The job's result (each job with its own type reduction unless
    /// `--type-reduction` overrides it), the smallest lower height of its
    /// numbers, and the notes on its alpha.
    fn compute(&self, job: &Entry) -> anyhow::Result<(RunOutput, f64, Vec<String>)> {
        let prepared = prepare(&job.path, &self.overrides)?;
        let notes = alpha_notes(
            prepared.settings(),
            self.overrides.alpha.is_some(),
            ALPHA_IGNORED,
        );
        let h = prepared.job().model.least_height();
        Ok((prepared.run().map_err(about_run)?, h, notes))
    }
}

/// Writes the rows of the jobs of `group` that succeeded into `table`
/// and gives their outcomes back without the results.
fn add_rows<W: Write + Send>(
    table: &mut JobsParquet<W>,
    group: &[Entry],
    mut done: Vec<Outcome>,
) -> std::io::Result<Vec<Outcome>> {
    let rows: Vec<(&str, &RunOutput)> = group
        .iter()
        .zip(&done)
        .filter_map(|(j, o)| o.result.as_ref().map(|r| (j.name.as_str(), r)))
        .collect();
    table.write(&rows)?;
    drop(rows);
    for o in &mut done {
        o.result = None;
    }
    Ok(done)
}

/// The files a result wrote to `out`.
fn files(out: &Destinations, result: &RunOutput) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = out.json.iter().chain(&out.parquet).cloned().collect();
    if let Some(dir) = &out.csv {
        files.extend(CSV_FILES.iter().map(|f| dir.join(f.0)));
        if result.samples.derivatives.is_some() {
            files.push(dir.join(DERIVATIVES_CSV));
        }
    }
    files
}

/// The lines of a job's error, each naming the job file once, as the I/O
/// crate's messages name it (control characters escaped).
fn message(path: &Path, e: &anyhow::Error) -> Vec<String> {
    let file = printable(&job_name(path));
    format!("{e:#}")
        .lines()
        .map(|line| {
            if line.starts_with(&file) {
                line.to_owned()
            } else {
                format!("{file}: {line}")
            }
        })
        .collect()
}

pub fn run(args: RunArgs) -> anyhow::Result<()> {
    let batch = Batch::new(args)?;
    let mut folders = NewFolders::default();
    for dir in [
        batch.output.as_ref(),
        batch.csv.as_ref(),
        batch.parquet.as_ref(),
    ]
    .into_iter()
    .flatten()
    {
        folders.create(dir)?;
    }
    let summary = batch.summary_dir.join(SUMMARY_CSV);
    // Declared before the staged outputs, which borrow them until the commit.
    let rows: Vec<JobSummary>;
    let kept: Vec<Option<RunOutput>>;
    // Not late for nothing: a stream staged for a device borrows it.
    #[allow(clippy::needless_late_init)]
    let one: Vec<(&str, &RunOutput)>;
    let mut staged = Staged::default();
    let outcomes = match &batch.one_parquet {
        Some(file) if batch.streams_table() => staged.add_now(file, |w| batch.run_into_table(w))?,
        _ => batch.run_all(),
    };
    let mut worst = Exit::Ok;
    let mut stderr = std::io::stderr().lock();
    for (job, outcome) in batch.jobs.iter().zip(&outcomes) {
        for note in &outcome.notes {
            let _ = writeln!(stderr, "t2spline run: {}: {note}", shown(&job.path));
        }
        if let Some(e) = &outcome.error {
            worst = worst.worst(Exit::of(e));
            for line in message(&job.path, e) {
                // A closed standard error loses the messages, not the run.
                let _ = writeln!(stderr, "t2spline: {line}");
            }
        }
    }
    drop(stderr);
    let written: Vec<PathBuf> = outcomes.iter().flat_map(|o| o.written.clone()).collect();
    sync_file_systems(&written)?;
    (rows, kept) = outcomes.into_iter().map(|o| (o.summary, o.result)).unzip();
    one = batch
        .jobs
        .iter()
        .zip(&kept)
        .filter_map(|(job, r)| r.as_ref().map(|r| (job.name.as_str(), r)))
        .collect();
    if let Some(file) = batch
        .one_parquet
        .as_ref()
        .filter(|_| !batch.streams_table())
    {
        staged.add(file, |w| write_jobs_parquet(w, &one))?;
    }
    if let Some(file) = &batch.jsonl {
        staged.add(file, |w| write_jobs_jsonl(w, &one))?;
    }
    staged.add(&summary, |w| write_summary_csv(w, &rows))?;
    let summary_parquet = match (&batch.parquet, &batch.one_parquet) {
        (Some(dir), _) => Some(dir.join(SUMMARY_PARQUET)),
        (None, Some(_)) => Some(batch.summary_dir.join(SUMMARY_PARQUET)),
        (None, None) => None,
    };
    if let Some(path) = &summary_parquet {
        staged.add(path, |w| write_summary_parquet(w, &rows))?;
    }
    staged.commit()?;
    let failed = rows
        .iter()
        .filter(|r| r.status != Exit::Ok.status())
        .count();
    if failed > 0 {
        return Err(JobsFailed {
            failed,
            total: rows.len(),
            exit: worst,
            summary,
        }
        .into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::natural_order;

    #[test]
    fn numbers_in_names_go_in_their_order() {
        let mut names = vec![
            "a10.json", "a2.json", "a1.json", "b.json", "a02.json", "a.json", "a1b.json",
            "a1a.json",
        ];
        names.sort_by(|a, b| natural_order(a, b));
        assert_eq!(
            names,
            [
                "a.json", "a1.json", "a1a.json", "a1b.json", "a02.json", "a2.json", "a10.json",
                "b.json"
            ]
        );
        // Long runs of digits beyond any integer type.
        assert!(natural_order("x99999999999999999999999", "x100000000000000000000000").is_lt());
    }
}
