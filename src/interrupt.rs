//! Interruption: Ctrl-C (SIGINT) or SIGTERM asks the solve to stop at the end of the current
//! cycle, so that the run can write its history, its last state and a summary with status
//! `interrupted`. A second signal ends the process at once (the handler restores the default).

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Whether an interruption was asked for.
#[inline]
pub fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}

/// Ask for an interruption: what the signal handler does, and what the Python package does when
/// Python reports a Ctrl-C.
pub fn request() {
    REQUESTED.store(true, Ordering::Relaxed);
}

/// Forget an earlier request: a run starts with none (`run_scene`), so a Ctrl-C that stopped one
/// run of a process does not stop the next.
pub fn clear() {
    REQUESTED.store(false, Ordering::Relaxed);
}

extern "C" fn on_signal(signal: libc::c_int) {
    request();
    // Async-signal-safe: an atomic store and `signal` itself. The next one kills.
    unsafe {
        libc::signal(signal, libc::SIG_DFL);
    }
}

/// Catch SIGINT and SIGTERM from here on (the `adit` command calls it once).
pub fn install() {
    let handler = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
    for signal in [libc::SIGINT, libc::SIGTERM] {
        unsafe {
            libc::signal(signal, handler);
        }
    }
}
