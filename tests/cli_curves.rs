//! `profsubd curves`: bad input is refused with a specific message on stderr, a non-zero exit
//! status, and neither the OBJ nor the targets file written. (A good run's output, byte for
//! byte as committed: `tests/example_bytes.rs`.)

#[path = "support/cli.rs"]
mod cli;

use std::path::{Path, PathBuf};
use std::process::Output;

use cli::{assert_refused, example_file, profsubd, write_input};

/// A unit square's four sides, each bowed up in the middle: a valid boundary.
const SQUARE: &str = "[[0,0,0],[0.5,0,0.1],[1,0,0]], [[1,0,0],[1,0.5,0.1],[1,1,0]], \
                      [[1,1,0],[0.5,1,0.1],[0,1,0]], [[0,1,0],[0,0.5,0.1],[0,0,0]]";

/// Run `curves` on `json` with `-o` and `--targets`; returns the output and the OBJ and
/// targets files it was told to write.
fn run(dir: &Path, name: &str, json: &str) -> (Output, [PathBuf; 2]) {
    let input = write_input(dir, &format!("{name}.json"), json);
    let [obj, targets] = [format!("{name}.obj"), format!("{name}.txt")].map(|f| dir.join(f));
    let out = profsubd(&[
        "curves",
        input.to_str().unwrap(),
        "-o",
        obj.to_str().unwrap(),
        "--targets",
        targets.to_str().unwrap(),
    ]);
    (out, [obj, targets])
}

#[test]
fn bad_input_is_refused_with_a_message_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    // The base input works: each case below breaks one thing of it.
    let (out, files) = run(
        dir.path(),
        "good",
        &format!(r#"{{"boundary": [{SQUARE}]}}"#),
    );
    assert!(out.status.success(), "{out:?}");
    assert_eq!(files.map(|f| f.exists()), [true, true]);

    let bonnet = std::fs::read_to_string(example_file("curves", "bonnet", "json")).unwrap();
    let example_keys = r#""samples": [8, 6], "tau": 1.5"#;
    assert!(bonnet.contains(example_keys));
    let cases: [(&str, String, &str); 11] = [
        (
            "two boundary curves",
            r#"{"boundary": [[[0,0,0],[1,0,0]], [[1,0,0],[1,1,0]]]}"#.into(),
            "boundary: 3 or 4 curves are needed around the patch, got 2",
        ),
        (
            "five boundary curves",
            format!(r#"{{"boundary": [{SQUARE}, [[0,0,0],[1,1,0]]]}}"#),
            "3 or 4 curves are needed around the patch, got 5",
        ),
        (
            "a boundary curve of one point",
            r#"{"boundary": [[[0,0,0]], [[0,0,0],[1,0,0]], [[1,0,0],[1,1,0]], [[1,1,0],[0,0,0]]]}"#
                .into(),
            "boundary 0: an open curve needs at least 2 points, got 1",
        ),
        (
            "an interior curve of two equal points",
            format!(r#"{{"boundary": [{SQUARE}], "interior": [[[0.2,0.2,0.1],[0.2,0.2,0.1]]]}}"#),
            "interior 0: points 0 and 1 coincide",
        ),
        (
            // JSON has no NaN; the reader refuses a number beyond f64 instead of making it
            // infinite.
            "a coordinate out of range",
            format!(
                r#"{{"boundary": [{}]}}"#,
                SQUARE.replacen("0.1", "1e999", 1)
            ),
            "number out of range",
        ),
        (
            "all curves on one line",
            r#"{"boundary": [[[0,0,0],[1,0,0]], [[1,0,0],[2,0,0]], [[2,0,0],[3,0,0]], [[3,0,0],[0,0,0]]]}"#
                .into(),
            "all curve points lie on one line, so no plane fits them",
        ),
        (
            "a boundary whose projection crosses itself",
            r#"{"boundary": [[[0,0,0],[2,0,0]], [[2,0,0],[0,1,0]], [[0,1,0],[3,1.5,0]], [[3,1.5,0],[0,0,0]]]}"#
                .into(),
            "the boundary's projection folds over itself",
        ),
        (
            "tau < 0",
            format!(r#"{{"boundary": [{SQUARE}], "tau": -1}}"#),
            "tau = -1 must be a finite number >= 0",
        ),
        (
            "an unknown method",
            format!(r#"{{"boundary": [{SQUARE}], "method": "smooth"}}"#),
            "unknown variant `smooth`, expected `attraction` or `fair`",
        ),
        (
            "an unknown key",
            format!(r#"{{"boundary": [{SQUARE}], "colour": 1}}"#),
            "unknown field `colour`",
        ),
        (
            // The README's example of the fold guard: the bonnet at 16 × 16, τ = 2.
            "a blend whose limit surface folds",
            bonnet.replace(example_keys, r#""samples": [16, 16], "tau": 2"#),
            "the fitted limit surface would fold in 20 faces",
        ),
    ];
    for (i, (what, json, message)) in cases.iter().enumerate() {
        let (out, [obj, targets]) = run(dir.path(), &format!("bad{i}"), json);
        assert_refused(&out, message, &[&obj, &targets], what);
    }
}
