//! Ctrl-C, `SIGTERM` and `SIGHUP` remove the named temporary files of
//! outputs still being written (up to hundreds of megabytes of
//! `.t2spline-*.tmp`; new files on Linux have no name until complete),
//! then end the program by the signal, as it would have ended without a
//! handler (the shell sees 130 for Ctrl-C, 143 for `SIGTERM`).

/// Starts a thread that waits for those signals.
#[cfg(unix)]
pub fn remove_temporary_files_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    // Without the handler the signals keep their default action: the
    // program ends, only the temporary files stay.
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    std::thread::spawn(move || {
        if let Some(signal) = signals.forever().next() {
            t2spline_io::remove_temporary_files();
            let _ = signal_hook::low_level::emulate_default_handler(signal);
            // Reached only if the default action did not end the process.
            std::process::exit(128 + signal);
        }
    });
}

/// Elsewhere the signals keep their default action.
#[cfg(not(unix))]
pub fn remove_temporary_files_on_signals() {}
