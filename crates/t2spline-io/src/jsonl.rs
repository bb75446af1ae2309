//! JSON Lines: the sampled curves of many runs as one text file, a JSON
//! object per line and per job and parameter, with the keys and the values
//! of the one Parquet table of many jobs ([`crate::write_jobs_parquet`]):
//! `job` (its name), `alpha` (`null` where the type reduction does not use
//! it), then every sample column of the one schema
//! ([`sample_column_names`](crate::sample_column_names), then the derivative
//! columns of x, y and z up to the highest order any job has), `null` where
//! a job lacks the column (a plane
//! curve's `_z`, a lower cut above `h`). Every line has the same keys in the
//! same order, whatever the model and the regime.
//!
//! Numbers are written as the result file writes them (the shortest decimal
//! that reads back to the same `f64`, [`crate::number`]), so a reader gets
//! the Parquet file's doubles bit for bit. One line of a plane curve:
//! `{"job":"a","alpha":0.5,"t":0.0,"u":null,"v":null,"upper_left_x":…}`.

use std::io::{self, Write};

use t2spline::job::RunOutput;

use crate::table::{derivative_order, jobs_column_names, one_table, Table, Values};

/// Writes the sampled curves of many runs as JSON Lines (the module's
/// layout), jobs in the order given, `\n` after every line.
///
/// # Errors
/// The errors of `writer`.
///
/// # Examples
/// ```
/// # use t2spline::job::Overrides;
/// let job = t2spline_io::read_job(std::path::Path::new("../../examples/paper-alg-1-1.json"))?;
/// let overrides = Overrides { samples: Some(vec![3]), ..Overrides::default() };
/// let result = job.run(&job.settings(&overrides)?)?;
/// let mut bytes = Vec::new();
/// t2spline_io::write_jobs_jsonl(&mut bytes, &[("a", &result)])?;
/// let text = String::from_utf8(bytes)?;
/// assert_eq!(text.lines().count(), 3);
/// assert!(text.starts_with(r#"{"job":"a","alpha":0.8,"t":0.0,"u":null,"v":null,"upper_left_x":"#));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_jobs_jsonl<W: Write>(writer: W, jobs: &[(&str, &RunOutput)]) -> io::Result<()> {
    let tables: Vec<Table<'_>> = jobs.iter().map(|(_, r)| one_table(r)).collect();
    let order = jobs.iter().map(|(_, r)| derivative_order(r)).max();
    let names = jobs_column_names(order.unwrap_or(0));
    // `"name":` of every column, once.
    let keys: Vec<Vec<u8>> = names
        .iter()
        .map(|n| {
            serde_json::to_vec(n).map(|mut k| {
                k.push(b':');
                k
            })
        })
        .collect::<Result<_, _>>()?;
    let mut w = io::BufWriter::with_capacity(1 << 16, writer);
    for ((name, result), table) in jobs.iter().zip(&tables) {
        // Each job's column for each name of the schema, if it has it.
        let columns: Vec<Option<&Values<'_>>> = names
            .iter()
            .map(|n| {
                table
                    .columns
                    .iter()
                    .find(|c| &c.name == n)
                    .map(|c| &c.values)
            })
            .collect();
        let mut head = b"{\"job\":".to_vec();
        serde_json::to_writer(&mut head, name)?;
        head.extend_from_slice(b",\"alpha\":");
        if result.alpha_used {
            crate::number::json(&mut head, result.alpha)?;
        } else {
            head.extend_from_slice(b"null");
        }
        for row in 0..table.rows {
            w.write_all(&head)?;
            for (key, column) in keys.iter().zip(&columns) {
                w.write_all(b",")?;
                w.write_all(key)?;
                match column {
                    Some(values) => crate::number::json(&mut w, values.get(row))?,
                    None => w.write_all(b"null")?,
                }
            }
            w.write_all(b"}\n")?;
        }
    }
    w.flush()
}
