//! Writing the result of the shipped example at 10⁶ samples (about 700 MB
//! of JSON, 720 MB of CSV, 230 MB of Parquet): each writer beside a plain write of the same
//! number of bytes into the same folder, in one run, so that the ratio holds
//! on a noisy machine. Criterion prints both as bytes per second.
//!
//! Every output goes through `Staged` (a temporary file beside the target)
//! and is dropped before the commit, so neither the flush to disk nor the
//! rename is timed; the plain write goes the same way.
//!
//! The group `write-small` writes the example at its own samples (72 kB)
//! into memory: the formatting alone, which each job of a run of many pays.
//!
//! ```sh
//! cargo bench -p t2spline-io --bench write
//! T2SPLINE_BENCH_SAMPLES=100000 cargo bench -p t2spline-io --bench write   # quicker
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;
use std::io::Write;
use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use t2spline::job::{Overrides, RunOutput};
use t2spline_io::{stage_csv, write_json_pretty, Staged};

/// The example at `T2SPLINE_BENCH_SAMPLES` samples (default 10⁶).
fn example() -> RunOutput {
    let samples: u64 = std::env::var("T2SPLINE_BENCH_SAMPLES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    example_at(Some(samples))
}

/// The example at `samples` samples (`None`: the job's own).
fn example_at(samples: Option<u64>) -> RunOutput {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-alg-1-1.json");
    let job = t2spline_io::read_job(&path).expect("the shipped example");
    let settings = job
        .settings(&Overrides {
            samples: samples.map(|n| vec![n]),
            ..Overrides::default()
        })
        .expect("valid settings");
    job.run(&settings).expect("the example runs")
}

/// Counts the bytes written through it.
struct Count(u64);

impl Write for Count {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0 += buf.len() as u64;
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// `n` bytes in blocks of 64 KiB, as plainly as a program writes.
fn plain(w: &mut dyn Write, n: u64) -> std::io::Result<()> {
    let block = vec![b'0'; 1 << 16];
    let mut left = n;
    while left > 0 {
        let k = left.min(block.len() as u64) as usize;
        w.write_all(&block[..k])?;
        left -= k as u64;
    }
    Ok(())
}

fn bench(c: &mut Criterion) {
    let result = example();
    let dir = tempfile::tempdir_in(env!("CARGO_TARGET_TMPDIR")).expect("a folder for outputs");
    let json_bytes = {
        let mut n = Count(0);
        write_json_pretty(&mut n, &result).expect("counting");
        n.0
    };
    let csv = dir.path().join("csv");
    let csv_bytes: u64 = t2spline_io::write_csv(&csv, &result)
        .expect("written")
        .iter()
        .map(|p| std::fs::metadata(p).expect("written").len())
        .sum();

    let mut g = c.benchmark_group("write");
    g.sample_size(10);
    g.throughput(Throughput::Bytes(json_bytes));
    let json = dir.path().join("result.json");
    g.bench_function("json", |b| {
        b.iter(|| {
            let mut staged = Staged::default();
            staged
                .add(&json, |w| write_json_pretty(w, black_box(&result)))
                .expect("written");
        });
    });
    g.bench_function("plain-write-of-json-size", |b| {
        b.iter(|| {
            let mut staged = Staged::default();
            staged
                .add(&json, |w| plain(w, json_bytes))
                .expect("written");
        });
    });
    g.throughput(Throughput::Bytes(csv_bytes));
    g.bench_function("csv", |b| {
        b.iter(|| {
            let mut staged = Staged::default();
            stage_csv(&mut staged, &csv, black_box(&result)).expect("written");
        });
    });
    g.bench_function("plain-write-of-csv-size", |b| {
        b.iter(|| {
            let mut staged = Staged::default();
            staged
                .add(&csv.join("plain.csv"), |w| plain(w, csv_bytes))
                .expect("written");
        });
    });
    #[cfg(feature = "parquet")]
    parquet(&mut g, dir.path(), &result);
    g.finish();
}

/// Parquet: the time of one file, beside a plain write of its size.
#[cfg(feature = "parquet")]
fn parquet(
    g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    dir: &Path,
    result: &RunOutput,
) {
    let parquet = dir.join("result.parquet");
    let parquet_bytes = {
        let mut n = Count(0);
        t2spline_io::write_parquet(&mut n, result).expect("counting");
        n.0
    };
    g.throughput(Throughput::Bytes(parquet_bytes));
    g.bench_function("parquet", |b| {
        b.iter(|| {
            let mut staged = Staged::default();
            staged
                .add(&parquet, |w| {
                    t2spline_io::write_parquet(w, black_box(result))
                })
                .expect("written");
        });
    });
    g.bench_function("plain-write-of-parquet-size", |b| {
        b.iter(|| {
            let mut staged = Staged::default();
            staged
                .add(&parquet, |w| plain(w, parquet_bytes))
                .expect("written");
        });
    });
}

/// The example at its own samples (72 kB of JSON), written into memory: the
/// formatting alone, as each job of a run of many pays it.
fn small(c: &mut Criterion) {
    let result = example_at(None);
    let mut out = Vec::new();
    write_json_pretty(&mut out, &result).expect("in memory");
    let mut g = c.benchmark_group("write-small");
    g.throughput(Throughput::Bytes(out.len() as u64));
    g.bench_function("json-in-memory", |b| {
        b.iter(|| {
            out.clear();
            write_json_pretty(&mut out, black_box(&result)).expect("in memory");
        });
    });
    g.finish();
}

criterion_group!(benches, small, bench);
criterion_main!(benches);
