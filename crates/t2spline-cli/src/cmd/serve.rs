//! `t2spline serve [JOB.json] [--port N]`: the live editor in the browser.
//! Reads the job once (as `run` reads it), listens on loopback, prints the
//! page's address as its first line and answers until Ctrl-C: the server in
//! `serve/server.rs`, its checks in `serve/security.rs`, the JSON API in
//! `serve/api.rs` (through `prepare.rs`, `region.rs`, `membership.rs`), the
//! page in `serve/page.{html,css,js}`.

mod answer;
mod api;
mod http;
mod security;
mod server;

use crate::cli::ServeArgs;
use crate::output::{is_stdio, job_name, read_input, to_stdout};
use answer::Served;
use server::Server;

/// The shipped example, opened when no job is named.
const EXAMPLE: &str = include_str!("../../../../examples/paper-alg-1-1.json");

pub fn serve(args: &ServeArgs) -> anyhow::Result<()> {
    let job = match &args.job {
        Some(path) => Served::new(
            job_name(path),
            read_input(path)?,
            (!is_stdio(path)).then(|| path.clone()),
        ),
        None => Served::new("paper-alg-1-1.json".to_owned(), EXAMPLE.to_owned(), None),
    };
    // A job that breaks a rule is refused as `run` refuses it.
    t2spline_io::parse_job(&job.text, &job.name)?;
    let server = Server::start(job, args.port)?;
    to_stdout(|w| {
        writeln!(w, "{}", server.url())?;
        w.flush()
    })?;
    server.run();
    Ok(())
}
