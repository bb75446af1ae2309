//! What `run` does alike for one job (`run.rs`) and for many (`batch.rs`):
//! the settings its options give a job, the note's words for an alpha that a
//! job's type reduction does not use, and where the files of a result go
//! (checked against the inputs, staged, written all or nothing).

use std::path::PathBuf;

use t2spline::job::{Overrides, RunOutput};
use t2spline_io::{
    stage_csv, write_json_pretty, write_parquet, Error, Staged, CSV_FILES, DERIVATIVES_CSV,
};

use crate::clash::Claims;
use crate::cli::RunArgs;
use crate::output::NewFolders;

/// Where the files of one result go.
#[derive(Debug, Default)]
pub(super) struct Destinations {
    /// The result file (`None`: standard output, or none in a run of many).
    pub(super) json: Option<PathBuf>,
    /// The folder of the CSV files.
    pub(super) csv: Option<PathBuf>,
    /// The Parquet file.
    pub(super) parquet: Option<PathBuf>,
}

impl Destinations {
    /// Claims every output of these destinations: an error if one would
    /// overwrite an input or another output, or lie inside the CSV folder
    /// (the rule of [`Claims`]).
    pub(super) fn claim(&self, claims: &mut Claims) -> anyhow::Result<()> {
        if let Some(p) = &self.json {
            claims.file("--output", p)?;
        }
        if let Some(dir) = &self.csv {
            let names = CSV_FILES.iter().map(|f| f.0).chain([DERIVATIVES_CSV]);
            claims.folder("--csv", dir, names)?;
        }
        if let Some(p) = &self.parquet {
            claims.file("--parquet", p)?;
        }
        Ok(())
    }

    /// Stages every file of `result` (the CSV folder created, and recorded
    /// in `folders`); the caller commits.
    fn stage<'a>(
        &self,
        staged: &mut Staged<'a>,
        folders: &mut NewFolders,
        result: &'a RunOutput,
    ) -> Result<(), Error> {
        if let Some(dir) = &self.csv {
            folders.create(dir)?;
            stage_csv(staged, dir, result)?;
        }
        if let Some(path) = &self.parquet {
            staged.add(path, |w| write_parquet(w, result))?;
        }
        if let Some(path) = &self.json {
            staged.add(path, |w| write_json_pretty(w, result))?;
        }
        Ok(())
    }

    /// Writes every file of `result`, all or nothing: each complete in a
    /// temporary file before any is renamed; folders made for the CSV files
    /// are removed again on failure.
    pub(super) fn write<'a>(
        &self,
        mut staged: Staged<'a>,
        result: &'a RunOutput,
    ) -> Result<(), Error> {
        let mut folders = NewFolders::default();
        let files = self
            .stage(&mut staged, &mut folders, result)
            .and_then(|()| staged.commit());
        if files.is_err() {
            folders.remove();
        }
        files
    }
}

/// The settings of a run from the options.
pub(super) fn overrides(args: &RunArgs) -> Overrides {
    Overrides {
        alpha: args.alpha,
        type_reduction: args.reduction.type_reduction,
        samples: args.samples.clone(),
        derivatives: args.derivatives,
    }
}
