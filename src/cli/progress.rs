//! The command line's progress bar and Ctrl-C: a [`Control`] whose hook draws an indicatif
//! bar on stderr once the work has run for a second (and only on a terminal), and cancels
//! when Ctrl-C was pressed. A cancelled command writes nothing and exits with
//! [`EXIT_INTERRUPTED`].

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use crate::control::Control;
use crate::error::{Error, Result};

/// Exit code of a command stopped by Ctrl-C (128 + SIGINT, as shells report it).
pub const EXIT_INTERRUPTED: i32 = 130;

/// Work shorter than this shows no bar.
const SHOW_AFTER: Duration = Duration::from_secs(1);

/// Set by the Ctrl-C handler.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// Install the Ctrl-C handler (once per process): it only sets a flag, which the work polls,
/// so that the command stops between two steps and writes nothing.
pub fn install_interrupt_handler() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // Failing to install (another handler exists) leaves the default: Ctrl-C kills.
        let _ = ctrlc::set_handler(|| INTERRUPTED.store(true, Ordering::SeqCst));
    });
}

/// Errors: [`Error::Cancelled`] when Ctrl-C was pressed; what a command checks before
/// writing its output.
pub fn check_interrupted() -> Result<()> {
    if INTERRUPTED.load(Ordering::SeqCst) {
        Err(Error::Cancelled(
            "interrupted (Ctrl-C); nothing written".into(),
        ))
    } else {
        Ok(())
    }
}

/// The control of one piece of work named `what` (the bar's message).
pub fn control(what: &'static str) -> Control {
    let start = Instant::now();
    let bar = Mutex::new(None::<ProgressBar>);
    Control::NONE.with_progress(move |fraction: f64| {
        if INTERRUPTED.load(Ordering::SeqCst) {
            if let Some(b) = bar.lock().ok().and_then(|mut b| b.take()) {
                b.abandon();
            }
            return true;
        }
        if start.elapsed() >= SHOW_AFTER {
            if let Ok(mut b) = bar.lock() {
                let b = b.get_or_insert_with(|| new_bar(what));
                b.set_position((fraction * 1000.0) as u64);
                if fraction >= 1.0 {
                    b.finish_and_clear();
                }
            }
        }
        false
    })
}

fn new_bar(what: &'static str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(1000), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("{msg} [{bar:40}] {percent:>3}% {elapsed_precise}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what);
    bar
}
