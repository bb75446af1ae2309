//! The server's part of an edit in `t2spline serve`: the page's two requests
//! for a changed job (`POST /api/run`, `POST /api/region` at the page's tolerance, a
//! quarter of a pixel: 0.001 for the example's view) answered by a
//! running `t2spline serve` over loopback, beside the same run in this
//! process (`Prepared::from_text`, `run`, `write_json_pretty`: the core's
//! and the writer's work alone) as the baseline of the same run. Each
//! iteration sends a job whose crisp point 1 moved, as a drag sends it.
//!
//! Cases: the shipped example (4 points) and a 200-point cubic.
//!
//! ```sh
//! cargo bench -p t2spline-cli --bench serve
//! ```

#![allow(missing_docs)] // criterion_group! makes an undocumented function

use std::hint::black_box;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

use criterion::{criterion_group, criterion_main, Criterion};
use serde_json::{json, Value};
use t2spline::job::Overrides;
use t2spline_io::{MissingAlpha, Prepared};

/// A running `t2spline serve` (the release binary next to this bench).
struct Serve {
    child: Child,
    port: u16,
    token: String,
}

impl Drop for Serve {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Serve {
    fn start() -> Serve {
        let mut child = Command::new(env!("CARGO_BIN_EXE_t2spline"))
            .arg("serve")
            .stdout(Stdio::piped())
            .spawn()
            .expect("t2spline serve");
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let rest = line.trim().strip_prefix("http://127.0.0.1:").unwrap();
        let (port, token) = rest.split_once("/?token=").unwrap();
        Serve {
            port: port.parse().unwrap(),
            token: token.to_owned(),
            child,
        }
    }

    /// `POST path` with `body`; the answer's length (checked 200).
    fn post(&self, path: &str, body: &[u8]) -> usize {
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).unwrap();
        write!(
            s,
            "POST {path} HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nX-T2spline-Token: {}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
            self.port,
            self.token,
            body.len()
        )
        .unwrap();
        s.write_all(body).unwrap();
        let mut answer = Vec::new();
        s.read_to_end(&mut answer).unwrap();
        assert!(answer.starts_with(b"HTTP/1.1 200"), "{path}");
        answer.len()
    }
}

/// The shipped example as JSON.
fn example() -> Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/paper-alg-1-1.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

fn number(c: f64, s: f64) -> Value {
    json!({"crisp": c, "upper": [c - 3.0 * s, c + 3.0 * s], "primary": [c - 2.0 * s, c + 2.0 * s],
           "lower": [c - s, c + s]})
}

/// A 200-point cubic: a wave with spreads of 0.05 to 0.1.
fn wave() -> Value {
    let points: Vec<Value> = (0..200)
        .map(|i| {
            let t = f64::from(i);
            json!({"x": number(t, 0.05 + 0.05 * (t / 200.0)), "y": number((t / 7.0).sin() * 5.0, 0.1)})
        })
        .collect();
    json!({"order": 4, "alpha": 0.5, "lower_height": 0.6, "points": points})
}

/// The job with crisp point 1 moved by `d` in x (all seven values).
fn moved(job: &Value, d: f64) -> Vec<u8> {
    let mut job = job.clone();
    let x = &mut job["points"][1]["x"];
    for key in ["upper", "primary", "lower"] {
        for side in 0..2 {
            x[key][side] = json!(x[key][side].as_f64().unwrap() + d);
        }
    }
    x["crisp"] = json!(x["crisp"].as_f64().unwrap() + d);
    serde_json::to_vec_pretty(&job).unwrap()
}

fn edit(c: &mut Criterion) {
    let serve = Serve::start();
    let mut group = c.benchmark_group("serve-edit");
    for (name, job) in [("example", example()), ("200-point cubic", wave())] {
        let jobs: Vec<Vec<u8>> = (0..16).map(|k| moved(&job, f64::from(k) * 1e-3)).collect();
        let mut k = 0;
        group.bench_function(
            format!("{name}: baseline in process (run and write)"),
            |b| {
                b.iter(|| {
                    k = (k + 1) % jobs.len();
                    let text = std::str::from_utf8(&jobs[k]).unwrap();
                    let refuse = MissingAlpha::Refuse { advice: "" };
                    let prepared =
                        Prepared::from_text(text, "job.json", &Overrides::default(), refuse)
                            .unwrap();
                    let mut out = Vec::new();
                    t2spline_io::write_json_pretty(&mut out, &prepared.run().unwrap()).unwrap();
                    black_box(out.len())
                });
            },
        );
        group.bench_function(
            format!("{name}: server, run and region over loopback"),
            |b| {
                b.iter(|| {
                    k = (k + 1) % jobs.len();
                    black_box(
                        serve.post("/api/run", &jobs[k])
                            + serve.post("/api/region?tolerance=0.001", &jobs[k]),
                    )
                });
            },
        );
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30);
    targets = edit
}
criterion_main!(benches);
