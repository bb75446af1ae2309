//! Apache Parquet files (feature `parquet`): a run's sampled curves as one
//! table, and the summary of many runs.
//!
//! Written with the `parquet` crate's column writers, which take `&[f64]`
//! straight from the result's vectors: no Arrow arrays, no copy of the
//! result. Columns are `DOUBLE` (float64) and required, except the optional
//! ones of the summary. Floats are encoded `BYTE_STREAM_SPLIT` (the k-th
//! bytes of all values together, so that the sign, exponent and leading
//! mantissa bytes of neighbouring samples, nearly equal on a smooth curve,
//! sit side by side) and compressed with Snappy: 60 % of the plain size for
//! the shipped example; no dictionaries (useless for a
//! million distinct floats); page statistics on, so engines can skip pages
//! by value.
//!
//! Measured on the shipped example at 10⁶ samples, with pyarrow rewriting the
//! same table: plain 240 MB; Snappy alone 235 MB (sampled floats are noise in
//! their low bits); byte-stream-split with Snappy 144 MB; with zstd at level 1
//! or 3, 133 MB. Snappy is pure Rust and every Parquet reader has it, where
//! zstd would save another 7 % for a C library in the build. Arrow arrays were
//! left out because they would copy every column (or take ownership the
//! writers do not have) and bring the `arrow-*` crates into the build. The
//! other keys of the result (`alpha`, `regime`, `error`, `control_points`, the
//! spline) go into the file's key-value metadata as JSON text, so one file
//! carries the whole result.

use std::io::Write;
use std::sync::Arc;

use parquet::basic::{Compression, Encoding, LogicalType, Repetition, Type as Physical};
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType};
use parquet::errors::ParquetError;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::{WriterProperties, WriterPropertiesBuilder, WriterVersion};
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;
use t2spline::job::RunOutput;

use crate::keys::top_level_json;
use crate::table::{derivative_order, jobs_column_names, one_table, Table};

/// Rows per row group: large enough for a million samples in one, as
/// pyarrow and parquet-rs do by default.
pub(crate) const ROW_GROUP: usize = 1 << 20;

/// Values computed per call of the column writer (a surface's `u`, `v`, the
/// distance), so that no column is stored whole.
const CHUNK: usize = 1 << 16;

/// The key-value metadata of a result file: every key of the result file
/// but the samples, each value as compact JSON text (the same digits as the
/// JSON file).
fn metadata(result: &RunOutput) -> Result<Vec<KeyValue>, serde_json::Error> {
    Ok(top_level_json(result, &["curves", "surfaces"])?
        .into_iter()
        .map(|(k, v)| KeyValue::new(k, v))
        .collect())
}

/// The data page size of the one table of many jobs: 64 KiB rather than
/// the writer's 1 MiB. A page is buffered and compressed whole, and buffers
/// of a megabyte are taken from the operating system and given back to it
/// on every page (the allocator's threshold for mapping memory), a fault
/// per 4 KiB each time; buffers of 64 KiB stay in the allocator's free
/// lists. Measured on 1 000 jobs of 101 samples: a third fewer page faults
/// and a quarter less time, for a file 0.1 % larger (docs/performance.md).
const JOBS_PAGE: usize = 1 << 16;

/// The writer's settings: Snappy compression, no dictionaries, our name.
fn builder(metadata: Vec<KeyValue>) -> WriterPropertiesBuilder {
    WriterProperties::builder()
        .set_writer_version(WriterVersion::PARQUET_1_0)
        .set_compression(Compression::SNAPPY)
        .set_dictionary_enabled(false)
        .set_max_row_group_size(ROW_GROUP)
        .set_created_by(format!("t2spline {}", env!("CARGO_PKG_VERSION")))
        .set_key_value_metadata(Some(metadata))
}

/// The settings of a result file: [`builder`]'s; for columns of floats
/// (`split`) the byte-stream-split encoding.
pub(crate) fn properties(metadata: Vec<KeyValue>, split: bool) -> Arc<WriterProperties> {
    let builder = builder(metadata);
    let builder = if split {
        builder.set_encoding(Encoding::BYTE_STREAM_SPLIT)
    } else {
        builder
    };
    Arc::new(builder.build())
}

/// A required `DOUBLE` column.
pub(crate) fn double(name: &str) -> Result<Arc<Type>, ParquetError> {
    Type::primitive_type_builder(name, Physical::DOUBLE)
        .with_repetition(Repetition::REQUIRED)
        .build()
        .map(Arc::new)
}

/// A message type (the schema) of `fields`.
pub(crate) fn schema(fields: Vec<Arc<Type>>) -> Result<Arc<Type>, ParquetError> {
    Type::group_type_builder("schema")
        .with_fields(fields)
        .build()
        .map(Arc::new)
}

/// `ParquetError` as an I/O error, for [`crate::Staged`] and its callers.
pub(crate) fn io_error(e: ParquetError) -> std::io::Error {
    match e {
        ParquetError::External(inner) => match inner.downcast::<std::io::Error>() {
            Ok(io) => *io,
            Err(other) => std::io::Error::other(other),
        },
        other => std::io::Error::other(other),
    }
}

/// Writes the sampled curves (or surfaces) of `result` as one Parquet table:
/// one row per parameter, a `DOUBLE` column per curve and coordinate with the
/// names of the CSV columns (`t` or `u, v`; `upper_left_x`, …, `crisp_x`,
/// …; `alpha_cut_upper_left_x`, … for the alpha-cut layers that exist;
/// `left_*`, `right_*`, `defuzzified_*`, `distance`; `crisp_d1_x`, … with
/// derivatives), and every other key of the result file (`alpha`, `regime`,
/// `error`, `control_points`, the spline's `order`, `degree`, `weights`,
/// `knots`, `domain`, …) as key-value metadata whose values are JSON text.
///
/// # Errors
/// The errors of `writer`.
///
/// # Examples
/// ```
/// # use t2spline::job::Overrides;
/// let job = t2spline_io::read_job(std::path::Path::new("../../examples/paper-alg-1-1.json"))?;
/// let result = job.run(&job.settings(&Overrides::default())?)?;
/// let mut bytes = Vec::new();
/// t2spline_io::write_parquet(&mut bytes, &result)?;
/// assert_eq!(&bytes[..4], b"PAR1");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_parquet<W: Write + Send>(writer: W, result: &RunOutput) -> std::io::Result<()> {
    let table = one_table(result);
    let metadata = metadata(result).map_err(std::io::Error::from)?;
    write_table(writer, &table, metadata).map_err(io_error)
}

fn write_table<W: Write + Send>(
    writer: W,
    table: &Table<'_>,
    metadata: Vec<KeyValue>,
) -> Result<(), ParquetError> {
    let fields = table
        .columns
        .iter()
        .map(|c| double(&c.name))
        .collect::<Result<_, _>>()?;
    let mut file = SerializedFileWriter::new(writer, schema(fields)?, properties(metadata, true))?;
    let mut scratch = Vec::new();
    for start in (0..table.rows).step_by(ROW_GROUP) {
        let end = (start + ROW_GROUP).min(table.rows);
        let mut group = file.next_row_group()?;
        for column in &table.columns {
            let mut out = next(&mut group)?;
            for chunk in (start..end).step_by(CHUNK) {
                let rows = chunk..(chunk + CHUNK).min(end);
                let values = column.values.rows(rows, &mut scratch);
                out.typed::<DoubleType>().write_batch(values, None, None)?;
            }
            out.close()?;
        }
        group.close()?;
    }
    file.close()?;
    Ok(())
}

/// Writes the sampled curves of many runs as one Parquet table: a row per
/// job and parameter, the job's name in `job` (text), its level in `alpha`
/// (null where the type reduction does not use it), then the columns of
/// [`sample_column_names`](crate::sample_column_names), one schema whatever
/// the model and the regime (a column a job lacks is null in its rows: a
/// plane curve's `_z`, a lower cut above `h`), and after them, when the
/// jobs have derivatives, those of orders 1 to the highest any job has
/// (`crisp_d1_x`, `crisp_d1_y`, `crisp_d1_z`, …, `defuzzified_d1_x`, …).
/// Jobs follow in the order given; row groups hold whole jobs.
///
/// # Errors
/// The errors of `writer`.
pub fn write_jobs_parquet<W: Write + Send>(
    writer: W,
    jobs: &[(&str, &RunOutput)],
) -> std::io::Result<()> {
    let order = jobs
        .iter()
        .map(|(_, r)| derivative_order(r))
        .max()
        .unwrap_or(0);
    let mut table = JobsParquet::new(writer, order)?;
    table.write(jobs)?;
    table.finish().map(drop)
}

/// The one table of [`write_jobs_parquet`], written a group of jobs at a
/// time, so that a run of many jobs need not hold every result until the
/// end; its schema is fixed when it is made, by the order of the
/// derivatives the jobs have (0: none).
pub struct JobsParquet<W: Write + Send> {
    file: SerializedFileWriter<W>,
    names: Vec<String>,
}

impl<W: Write + Send> std::fmt::Debug for JobsParquet<W> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("JobsParquet")
            .field("names", &self.names)
            .finish_non_exhaustive()
    }
}

impl<W: Write + Send> JobsParquet<W> {
    /// A table into `writer`, with the derivative columns of orders 1 to
    /// `derivatives`.
    ///
    /// # Errors
    /// The errors of `writer`.
    pub fn new(writer: W, derivatives: usize) -> std::io::Result<Self> {
        let names = jobs_column_names(derivatives);
        let build = || -> Result<SerializedFileWriter<W>, ParquetError> {
            let mut fields = vec![
                text("job", Repetition::REQUIRED)?,
                optional_double("alpha")?,
            ];
            for name in &names {
                fields.push(optional_double(name)?);
            }
            let properties = builder(Vec::new())
                .set_data_page_size_limit(JOBS_PAGE)
                .build();
            SerializedFileWriter::new(writer, schema(fields)?, Arc::new(properties))
        };
        Ok(JobsParquet {
            file: build().map_err(io_error)?,
            names,
        })
    }

    /// Appends the rows of `jobs`, in their order, in row groups of whole
    /// jobs.
    ///
    /// # Errors
    /// The errors of the writer.
    pub fn write(&mut self, jobs: &[(&str, &RunOutput)]) -> std::io::Result<()> {
        self.write_groups(jobs).map_err(io_error)
    }

    /// Ends the table (its footer) and gives the writer back.
    ///
    /// # Errors
    /// The errors of the writer.
    pub fn finish(self) -> std::io::Result<W> {
        self.file.into_inner().map_err(io_error)
    }

    fn write_groups(&mut self, jobs: &[(&str, &RunOutput)]) -> Result<(), ParquetError> {
        let tables: Vec<Table<'_>> = jobs.iter().map(|(_, r)| one_table(r)).collect();
        let mut scratch = Vec::new();
        let mut start = 0;
        while start < jobs.len() {
            // Whole jobs, up to a row group's rows (at least one job).
            let mut end = start + 1;
            let mut rows = tables[start].rows;
            while end < jobs.len() && rows + tables[end].rows <= ROW_GROUP {
                rows += tables[end].rows;
                end += 1;
            }
            let mut group = self.file.next_row_group()?;
            let mut c = next(&mut group)?;
            for k in start..end {
                let name = ByteArray::from(jobs[k].0);
                c.typed::<ByteArrayType>()
                    .write_batch(&vec![name; tables[k].rows], None, None)?;
            }
            c.close()?;
            let mut c = next(&mut group)?;
            for k in start..end {
                let r = jobs[k].1;
                let (values, level) = if r.alpha_used {
                    (vec![r.alpha], 1)
                } else {
                    (Vec::new(), 0)
                };
                let values = values.repeat(tables[k].rows);
                c.typed::<DoubleType>().write_batch(
                    &values,
                    Some(&vec![level; tables[k].rows]),
                    None,
                )?;
            }
            c.close()?;
            // Each column of the group in one batch: the jobs' values one after
            // another, a definition level per row (0 where a job lacks it).
            let (mut values, mut levels) = (Vec::with_capacity(rows), Vec::with_capacity(rows));
            for name in &self.names {
                values.clear();
                levels.clear();
                for table in &tables[start..end] {
                    match table.columns.iter().find(|col| &col.name == name) {
                        Some(column) => {
                            values
                                .extend_from_slice(column.values.rows(0..table.rows, &mut scratch));
                            levels.resize(levels.len() + table.rows, 1);
                        }
                        None => levels.resize(levels.len() + table.rows, 0),
                    }
                }
                let mut c = next(&mut group)?;
                c.typed::<DoubleType>()
                    .write_batch(&values, Some(&levels), None)?;
                c.close()?;
            }
            group.close()?;
            start = end;
        }
        Ok(())
    }
}

/// A `BYTE_ARRAY` column of UTF-8 text, required or optional.
pub(crate) fn text(name: &str, repetition: Repetition) -> Result<Arc<Type>, ParquetError> {
    Type::primitive_type_builder(name, Physical::BYTE_ARRAY)
        .with_repetition(repetition)
        .with_logical_type(Some(LogicalType::String))
        .build()
        .map(Arc::new)
}

/// The values and definition levels (1 present, 0 null) of an optional
/// column.
fn optional<T: Clone>(values: impl Iterator<Item = Option<T>>) -> (Vec<T>, Vec<i16>) {
    let mut present = Vec::new();
    let levels = values
        .map(|v| match v {
            Some(v) => {
                present.push(v);
                1
            }
            None => 0,
        })
        .collect();
    (present, levels)
}

/// Writes the summary of a run of many jobs as a Parquet table with the
/// columns of [`SUMMARY_COLUMNS`](crate::SUMMARY_COLUMNS): `name`, `file`
/// and `status` required text, `type_reduction`, `regime`, `description`
/// and `message` optional text, `alpha`, `h`, `error_max`, `error_max_at`,
/// `error_max_at_v`, `error_rms` optional `DOUBLE` (null for a job that did
/// not run or has no such value).
///
/// # Errors
/// The errors of `writer`.
pub fn write_summary_parquet<W: Write + Send>(
    writer: W,
    jobs: &[crate::summary::JobSummary],
) -> std::io::Result<()> {
    write_summary(writer, jobs).map_err(io_error)
}

fn write_summary<W: Write + Send>(
    writer: W,
    jobs: &[crate::summary::JobSummary],
) -> Result<(), ParquetError> {
    const OPTIONAL: Repetition = Repetition::OPTIONAL;
    const REQUIRED: Repetition = Repetition::REQUIRED;
    let [name, file, status, reduction, regime, alpha, h, max, max_at, max_at_v, rms, description, message] =
        crate::summary::SUMMARY_COLUMNS;
    let fields = vec![
        text(name, REQUIRED)?,
        text(file, REQUIRED)?,
        text(status, REQUIRED)?,
        text(reduction, OPTIONAL)?,
        text(regime, OPTIONAL)?,
        optional_double(alpha)?,
        optional_double(h)?,
        optional_double(max)?,
        optional_double(max_at)?,
        optional_double(max_at_v)?,
        optional_double(rms)?,
        text(description, OPTIONAL)?,
        text(message, OPTIONAL)?,
    ];
    let mut out =
        SerializedFileWriter::new(writer, schema(fields)?, properties(Vec::new(), false))?;
    let mut group = out.next_row_group()?;
    let strings = |f: &dyn Fn(&crate::summary::JobSummary) -> Option<&str>| {
        optional(jobs.iter().map(|j| f(j).map(ByteArray::from)))
    };
    let numbers =
        |f: &dyn Fn(&crate::summary::JobSummary) -> Option<f64>| optional(jobs.iter().map(f));
    let columns_of_text = [
        strings(&|j| Some(&j.name)),
        strings(&|j| Some(&j.file)),
        strings(&|j| Some(&j.status)),
        strings(&|j| j.type_reduction.as_deref()),
        strings(&|j| j.regime.as_deref()),
    ];
    for (k, (values, levels)) in columns_of_text.iter().enumerate() {
        let mut c = next(&mut group)?;
        // The first three are required.
        let levels = (k >= 3).then_some(&levels[..]);
        c.typed::<ByteArrayType>()
            .write_batch(values, levels, None)?;
        c.close()?;
    }
    for (values, levels) in [
        numbers(&|j| j.alpha),
        numbers(&|j| j.h),
        numbers(&|j| j.error_max),
        numbers(&|j| j.error_max_at),
        numbers(&|j| j.error_max_at_v),
        numbers(&|j| j.error_rms),
    ] {
        let mut c = next(&mut group)?;
        c.typed::<DoubleType>()
            .write_batch(&values, Some(&levels), None)?;
        c.close()?;
    }
    for (values, levels) in [
        strings(&|j| j.description.as_deref()),
        strings(&|j| j.message.as_deref()),
    ] {
        let mut c = next(&mut group)?;
        c.typed::<ByteArrayType>()
            .write_batch(&values, Some(&levels), None)?;
        c.close()?;
    }
    group.close()?;
    out.close()?;
    Ok(())
}

/// An optional `DOUBLE` column.
fn optional_double(name: &str) -> Result<Arc<Type>, ParquetError> {
    Type::primitive_type_builder(name, Physical::DOUBLE)
        .with_repetition(Repetition::OPTIONAL)
        .build()
        .map(Arc::new)
}

/// The next column of a row group, which the schema says exists.
pub(crate) fn next<'g, W: Write + Send>(
    group: &'g mut parquet::file::writer::SerializedRowGroupWriter<'_, W>,
) -> Result<parquet::file::writer::SerializedColumnWriter<'g>, ParquetError> {
    group
        .next_column()?
        .ok_or_else(|| ParquetError::General("fewer columns than the schema".into()))
}
