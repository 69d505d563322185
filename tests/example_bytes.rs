//! Determinism: the CLI writes every bundled example (`examples/profiles/`, `examples/sweeps/`,
//! `examples/curves/`, `examples/blends/`)
//! byte for byte as committed, OBJ and data points, so outputs can be diffed and cached
//! across machines. The fit is scalar code in a fixed order (`profsubd::fit`); a different
//! CPU or SIMD level must not change a digit (`scripts/check_determinism.sh` runs the same
//! builds under emulated CPUs without AVX/FMA). Regenerate with
//! `scripts/regenerate_examples.sh` after an intended change.

#[path = "support/cli.rs"]
mod cli;

use std::path::Path;

use cli::profsubd;

#[test]
fn examples_are_written_byte_for_byte_as_committed() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let out = tempfile::tempdir().unwrap();
    let mut checked = 0;
    for dir in ["profiles", "sweeps", "curves", "blends"] {
        let mut inputs: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        inputs.sort();
        for json in inputs {
            let text = std::fs::read_to_string(&json).unwrap();
            let command = match dir {
                "profiles" => "profile",
                "curves" => "curves",
                "blends" => "blend",
                _ if text.contains("\"trajectory\"") => "sweep",
                _ => "revolve",
            };
            let name = json.file_stem().unwrap().to_str().unwrap();
            let (obj, targets) = (
                out.path().join(format!("{name}.obj")),
                out.path().join(format!("{name}.targets.txt")),
            );
            let status = profsubd(&[
                command,
                json.to_str().unwrap(),
                "-o",
                obj.to_str().unwrap(),
                "--targets",
                targets.to_str().unwrap(),
            ]);
            assert!(status.status.success(), "{name}: {status:?}");
            for (written, committed) in [
                (obj, json.with_extension("obj")),
                (targets, json.with_extension("targets.txt")),
            ] {
                let (a, b) = (
                    std::fs::read_to_string(&written).unwrap(),
                    std::fs::read_to_string(&committed).unwrap(),
                );
                if let Some((i, (x, y))) = a
                    .lines()
                    .zip(b.lines())
                    .enumerate()
                    .find(|(_, (x, y))| x != y)
                {
                    panic!(
                        "{}: line {} differs:\n  written   {x}\n  committed {y}",
                        committed.display(),
                        i + 1
                    );
                }
                assert_eq!(a.len(), b.len(), "{}", committed.display());
                checked += 1;
            }
        }
    }
    // 4 profiles, 5 sweeps, 4 sketch-curve patches and 10 blends, two files each.
    assert_eq!(checked, 46);
}
