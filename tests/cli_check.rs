//! The `profsubd` binary on real files: exact output, exit codes, error messages.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn profsubd(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_profsubd"))
        .args(args)
        .output()
        .expect("run profsubd")
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("examples/meshes")
        .join(name)
}

#[test]
fn convert_overrides_the_option_tags_and_keeps_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("cube.obj");
    let input = example("cube_creased.obj");
    let o = profsubd(&[
        "convert",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--boundary",
        "edge-only",
        "--crease",
        "chaikin",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        stdout(&o),
        format!(
            "wrote {} (8 vertices, 6 faces, 5 creases, 1 corners, 0 holes)\n",
            out.display()
        )
    );
    assert_eq!(stderr(&o), "");
    let text = std::fs::read_to_string(&out).unwrap();
    let tags: Vec<&str> = text.lines().filter(|l| l.starts_with("t ")).collect();
    assert_eq!(
        tags,
        [
            "t interpolateboundary 1/0/0 2",
            "t creasemethod 0/0/1 chaikin",
            "t crease 2/1/0 4 5 2",
            "t crease 2/1/0 5 6 2",
            "t crease 2/1/0 6 7 2",
            "t crease 2/1/0 7 4 2",
            "t crease 2/1/0 1 5 10",
            "t corner 1/1/0 2 3",
        ]
    );
    let faces: Vec<&str> = text.lines().filter(|l| l.starts_with("f ")).collect();
    assert_eq!(faces[0], "f 1 4 3 2");
    assert_eq!(faces.len(), 6);
}

#[test]
fn convert_reports_a_missing_input_and_a_bad_flag() {
    let o = profsubd(&["convert", "/nonexistent/in.obj", "-o", "/tmp/never.obj"]);
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        stderr(&o),
        "profsubd: error: /nonexistent/in.obj: No such file or directory (os error 2)\n"
    );
    let input = example("cube_creased.obj");
    let o = profsubd(&[
        "convert",
        input.to_str().unwrap(),
        "-o",
        "/tmp/never.obj",
        "--boundary",
        "sometimes",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("invalid value 'sometimes' for '--boundary <RULE>'"));
}

#[test]
fn help_lists_the_subcommands_and_exit_codes() {
    let o = profsubd(&["--help"]);
    assert_eq!(o.status.code(), Some(0));
    let text = stdout(&o);
    assert!(text.contains("convert"), "{text}");
    assert!(text.contains("Exit codes: 0 success, 1 error"), "{text}");
}

#[test]
fn convert_reports_ignored_tags_on_stderr() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.obj");
    std::fs::write(
        &input,
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nt vertexedit 1/0/0 0\n",
    )
    .unwrap();
    let out = dir.path().join("out.obj");
    let o = profsubd(&[
        "convert",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stderr(&o),
        format!(
            "profsubd: warning: {}:5: ignored hierarchical edit `vertexedit` \
             (not supported by OpenSubdiv 3 either)\n",
            input.display()
        )
    );
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(written.ends_with("v 1 1 0\nf 1 2 3\n"), "{written}");
}
