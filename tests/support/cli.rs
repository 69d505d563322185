//! Running the `profsubd` binary in tests: the command, its output as text, the bundled
//! examples and written inputs it reads, and the checks of a refusal. `mod cli;` via
//! `#[path = "support/cli.rs"]` in a test crate.
// Each test crate uses some of these helpers.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Run the `profsubd` binary with `args` and wait for it.
pub fn profsubd(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_profsubd"))
        .args(args)
        .output()
        .expect("run profsubd")
}

/// What the run printed on standard output (UTF-8).
pub fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

/// What the run printed on standard error (UTF-8).
pub fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// The numbers the run printed, one line of space-separated numbers a point (`limit`,
/// `offset`).
pub fn numbers(o: &Output) -> Vec<Vec<f64>> {
    stdout(o)
        .lines()
        .map(|l| l.split(' ').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// `examples/<dir>/<name>.<ext>` in the repository.
pub fn example_file(dir: &str, name: &str, ext: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples")
        .join(dir)
        .join(format!("{name}.{ext}"))
}

/// Write `text` to the file `name` in `dir` (an input for the run) and return its path.
pub fn write_input(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The run `o` refused its input: exit status 1, `message` on standard error, nothing on
/// standard output, and none of `outputs` written. `what` names the case on failure.
pub fn assert_refused(o: &Output, message: &str, outputs: &[&Path], what: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(1), "{what}: {err}");
    assert!(err.contains(message), "{what}: {err}");
    assert!(o.stdout.is_empty(), "{what}: printed {}", stdout(o));
    for path in outputs {
        assert!(!path.exists(), "{what}: {} was written", path.display());
    }
}
