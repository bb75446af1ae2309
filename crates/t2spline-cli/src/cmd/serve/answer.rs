//! What the server of `t2spline serve` holds and gives: the job being
//! edited (`Served`) and an answer to a request (`Answer`), below both the
//! routes (`server.rs`) and the endpoints (`api.rs`) that use them.

use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The job being edited: its name in messages, its text as read at start,
/// and the file it may be saved over (none for the example or standard
/// input).
#[derive(Debug)]
pub struct Served {
    /// How messages name the job (the path as given, `<stdin>`, or the
    /// example's file name).
    pub name: String,
    /// The text read at start.
    pub text: String,
    /// The job file named on the command line.
    pub path: Option<PathBuf>,
    /// The file's text as the server last read or wrote it: a save over a
    /// file that changed since is refused unless asked to overwrite.
    on_disk: Mutex<String>,
}

impl Served {
    /// The job `text` named `name`, read from `path` (none: nothing to
    /// save over).
    pub fn new(name: String, text: String, path: Option<PathBuf>) -> Served {
        Served {
            name,
            on_disk: Mutex::new(text.clone()),
            text,
            path,
        }
    }

    /// The file's text as last read or written (a poisoned lock still
    /// holds it: every write to it is one assignment).
    pub(super) fn on_disk(&self) -> MutexGuard<'_, String> {
        self.on_disk.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// An answer: status, media type and body.
#[derive(Debug)]
pub struct Answer {
    pub(super) status: u16,
    pub(super) media: &'static str,
    pub(super) body: Vec<u8>,
}

impl Answer {
    pub(super) fn new(status: u16, media: &'static str, body: Vec<u8>) -> Answer {
        Answer {
            status,
            media,
            body,
        }
    }

    /// A JSON answer.
    pub(super) fn json(status: u16, value: &serde_json::Value) -> Answer {
        Answer::new(status, "application/json", value.to_string().into_bytes())
    }

    /// A refusal or error with one message, as `{"problems": [MESSAGE]}`.
    pub(super) fn problem(status: u16, message: &str) -> Answer {
        Answer::json(status, &serde_json::json!({ "problems": [message] }))
    }
}
