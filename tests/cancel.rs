//! Progress and cancellation through the Rust API (one [`Control`] for all): every
//! construction (through `Settings`), the evaluator build, uniform refinement and the fold
//! check report fractions from 0 to 1, stop with `Error::Cancelled` at the first callback or at 50 %, and
//! refuse work above a memory budget with `Error::LimitExceeded`. Also the command line:
//! SIGINT stops a long construction with exit code 130 and no output file.

use std::path::Path;
use std::sync::{Arc, Mutex};

use profsubd::eval::folds::{find_folds_with, FoldSettings};
use profsubd::io::obj::read_obj_file;
use profsubd::refine::{refine_uniform_with, VertexOrder};
use profsubd::{
    profile, revolve, sweep, Control, Error, Evaluator, Mesh, RevolveInput, Settings,
    SubdivOptions, SweepInput,
};

/// The fractions a hook saw; it cancels at the first one `>= cancel_at`.
fn recording(cancel_at: f64) -> (Control, Arc<Mutex<Vec<f64>>>) {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let log = seen.clone();
    let control = Control::NONE.with_progress(move |f: f64| {
        log.lock().unwrap().push(f);
        f >= cancel_at
    });
    (control, seen)
}

type Work = Box<dyn Fn(&Control) -> Result<(), Error>>;

fn example(path: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(path)
        .to_string_lossy()
        .into_owned()
}

fn works() -> Vec<(&'static str, Work)> {
    let mesh: Arc<Mesh> = Arc::new(
        read_obj_file(Path::new(&example("examples/profiles/vase.obj")))
            .unwrap()
            .mesh,
    );
    let m2 = mesh.clone();
    let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
    vec![
        (
            "profile",
            Box::new(|c: &Control| {
                let (input, settings) = profile::default_model();
                let settings = Settings {
                    control: c.clone(),
                    ..settings
                };
                profile::build(&input, &settings).map(drop)
            }),
        ),
        (
            "revolve",
            Box::new(|c: &Control| {
                let input = RevolveInput::new(vec![[1.0, 0.0], [1.4, 0.8], [1.3, 2.0], [0.9, 3.0]]);
                let settings = Settings {
                    control: c.clone(),
                    ..Settings::default()
                };
                revolve::build(&input, &settings).map(drop)
            }),
        ),
        (
            "sweep",
            Box::new(|c: &Control| {
                let (input, mut settings): (SweepInput, Settings) =
                    profsubd::construct::settings::read_json(Path::new(&example(
                        "examples/sweeps/handrail.json",
                    )))
                    .unwrap();
                settings.control = c.clone();
                sweep::build(&input, &settings).map(drop)
            }),
        ),
        (
            "evaluator",
            Box::new(move |c: &Control| {
                Evaluator::with_control(&mesh, &mesh.options().resolve(), c).map(drop)
            }),
        ),
        (
            "refine",
            Box::new(move |c: &Control| {
                let o: SubdivOptions = m2.options().resolve();
                refine_uniform_with(&m2, &o, 3, VertexOrder::VerticesFirst, c).map(drop)
            }),
        ),
        (
            "fold check",
            Box::new(move |c: &Control| {
                find_folds_with(&ev, &FoldSettings::default(), c).map(drop)
            }),
        ),
    ]
}

#[test]
fn every_long_call_reports_progress_and_cancels() {
    for (name, work) in works() {
        // To the end: from 0 to 1, never decreasing.
        let (control, seen) = recording(f64::INFINITY);
        work(&control).unwrap_or_else(|e| panic!("{name}: {e}"));
        let full = seen.lock().unwrap().clone();
        assert!(full.len() >= 3, "{name}: {full:?}");
        assert_eq!((full[0], *full.last().unwrap()), (0.0, 1.0), "{name}");
        assert!(full.windows(2).all(|w| w[0] <= w[1]), "{name}: {full:?}");

        // At the first callback.
        let (control, seen) = recording(0.0);
        match work(&control) {
            Err(Error::Cancelled(m)) => assert!(m.contains("at 0.0 %"), "{name}: {m}"),
            other => panic!("{name}: {other:?}"),
        }
        assert_eq!(seen.lock().unwrap().len(), 1, "{name}");

        // At 50 %: the call returns at the first report at or past it.
        let (control, seen) = recording(0.5);
        assert!(matches!(work(&control), Err(Error::Cancelled(_))), "{name}");
        let half = seen.lock().unwrap().clone();
        let last = *half.last().unwrap();
        assert!((0.5..1.0).contains(&last), "{name}: stopped at {last}");
        assert_eq!(
            half[..],
            full[..half.len()],
            "{name}: same reports until the stop"
        );
        assert!(half.len() < full.len(), "{name}");

        // A 1 KiB budget: refused before the work, with both figures.
        match work(&Control::NONE.with_memory_budget(Some(1024))) {
            Err(Error::LimitExceeded(m)) => {
                assert!(
                    m.contains("above the memory budget of 1024 bytes"),
                    "{name}: {m}"
                )
            }
            other => panic!("{name}: {other:?}"),
        }
    }
}

/// The stages before and after a construction's fit are polled too (#17 item 5): the layout's
/// design lattice reports at fraction 0 before the fit's first report, and a partial turn's
/// fold check reports at 1 after the fit's last; a cancel there stops the call. The fit alone
/// reports 0 and 1 once each, so cancelling at the third report of either needs those polls.
#[test]
fn layout_and_fold_check_are_polled() {
    let build = |c: &Control| {
        let mut input = RevolveInput::new(vec![[0.6, 0.0], [0.8, 0.5], [0.4, 1.2], [0.5, 1.6]]);
        input.angle_deg = 270.0;
        let settings = Settings {
            control: c.clone(),
            ..Settings::default()
        };
        revolve::build(&input, &settings).map(drop)
    };
    build(&Control::NONE).unwrap();
    for at in [0.0, 1.0] {
        let count = Arc::new(Mutex::new(0usize));
        let seen = count.clone();
        let control = Control::NONE.with_progress(move |f: f64| {
            let mut n = seen.lock().unwrap();
            *n += usize::from(f == at);
            *n >= 3
        });
        match build(&control) {
            Err(Error::Cancelled(m)) => {
                assert!(m.contains(&format!("at {:.1} %", 100.0 * at)), "{m}")
            }
            other => panic!("at {at}: {other:?}"),
        }
        assert_eq!(*count.lock().unwrap(), 3, "at {at}");
    }
}

/// The longest unpolled steps of the evaluator build and uniform refinement are polled inside
/// (#17 item 5): the evaluator's position pass (fractions strictly between 0.95 and 1) and the
/// last level's topology of a level-3 refinement (strictly between the end of level 2 and the
/// middle of level 3: `(4^3 - 4) / 252` and `(60 + 252) / 504`). A cancel at the first report
/// inside either stops the call with that fraction; uncancelled, the polls change nothing
/// (the same evaluator and refined mesh, bit for bit, as without a hook). The same for the
/// base level that a construction's fit builds its limit stencils on (a revolution's fit
/// fills 10–100 % of the call, its stencils 0–29 % of the fit, their base level 0–10 % of
/// those: strictly between 0.1 and 0.1 + 0.9 × 0.029).
#[test]
fn position_pass_and_refined_topology_are_polled() {
    let mesh = read_obj_file(Path::new(&example("examples/profiles/vase.obj")))
        .unwrap()
        .mesh;
    let options: SubdivOptions = mesh.options().resolve();
    let (lo, hi) = (60.0 / 252.0, (60.0 + 252.0) / 504.0);
    let level_end = 0.1 + 0.9 * 0.29 * 0.1;
    // (name, fractions inside the polled step, fewest reports there, work)
    let cases: [(&str, (f64, f64), usize, Work); 3] = [
        // Its faces and vertices passes report up to a thousand times each (1346 here); an
        // unpolled base level would leave only the stencils' vertex loop, whose thousand
        // reports spread over 0.1–0.361 put 67 in this window.
        ("fit's base level", (0.1 + 1e-9, level_end - 1e-9), 500, {
            let mut input = RevolveInput::new(vec![[0.0, 0.0], [1.0, 0.0], [1.3, 2.0], [0.0, 3.0]]);
            (input.samples_profile, input.samples_around) = (32, 64);
            let plain = revolve::build(&input, &Settings::default()).unwrap().mesh;
            Box::new(move |c: &Control| {
                let settings = Settings {
                    control: c.clone(),
                    ..Settings::default()
                };
                assert_eq!(revolve::build(&input, &settings)?.mesh, plain);
                Ok(())
            })
        }),
        ("evaluator", (0.95, 1.0), 2, {
            // A revolution through the axis: its poles' rings of refined fragments make
            // enough points for several polls (one per 1024 points).
            let mut input = RevolveInput::new(vec![[0.0, 0.0], [1.0, 0.0], [1.3, 2.0], [0.0, 3.0]]);
            input.samples_around = 64;
            let mesh = revolve::build(&input, &Settings::default()).unwrap().mesh;
            let options = mesh.options().resolve();
            let plain = Evaluator::new(&mesh, &options).unwrap();
            Box::new(move |c: &Control| {
                let ev = Evaluator::with_control(&mesh, &options, c)?;
                assert_eq!(ev.limit_vertices()?, plain.limit_vertices()?);
                Ok(())
            })
        }),
        ("refine", (lo, hi), 2, {
            let mesh = mesh.clone();
            let order = VertexOrder::VerticesFirst;
            let plain = refine_uniform_with(&mesh, &options, 3, order, &Control::NONE).unwrap();
            Box::new(move |c: &Control| {
                assert_eq!(refine_uniform_with(&mesh, &options, 3, order, c)?, plain);
                Ok(())
            })
        }),
    ];
    for (name, (from, to), least, work) in cases {
        let (control, seen) = recording(f64::INFINITY);
        work(&control).unwrap();
        let inside: Vec<f64> = (seen.lock().unwrap().iter().copied())
            .filter(|&f| from < f && f < to)
            .collect();
        assert!(
            inside.len() >= least,
            "{name}: {} reports inside",
            inside.len()
        );
        let (control, seen) = recording(inside[0]);
        match work(&control) {
            Err(Error::Cancelled(m)) => {
                assert!(m.contains(&format!("at {:.1} %", 100.0 * inside[0])), "{m}")
            }
            other => panic!("{name}: {other:?}"),
        }
        assert_eq!(*seen.lock().unwrap().last().unwrap(), inside[0], "{name}");
    }
}

/// SIGINT during a long construction: exit code 130, a message, and no output file.
#[test]
fn ctrl_c_stops_the_command_line_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("big.json");
    // About 4 s of fitting on this machine (1024 x 1024 samples).
    std::fs::write(
        &input,
        r#"{"profile": [[1,0],[1.4,0.8],[1.3,2],[0.9,3]], "samples_profile": 1024,
            "samples_around": 1024}"#,
    )
    .unwrap();
    let output = dir.path().join("big.obj");
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_profsubd"))
        .arg("revolve")
        .arg(&input)
        .arg("-o")
        .arg(&output)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Past the handler's installation (the first thing the command does), well before
    // the fit ends.
    std::thread::sleep(std::time::Duration::from_millis(500));
    let kill = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("cancelled"), "{stderr}");
    assert!(!output.exists());
}
