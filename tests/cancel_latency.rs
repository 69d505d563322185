//! Where a cancel request waits longest: the six longest waits between two progress
//! callbacks (from the call to the first and from the last to the return included) of the
//! C harness's latency work (`build/cpp_tests/cancel --latency`), with the fractions at both
//! ends, which name the stage. A measurement, printed, not asserted; ignored by default:
//! `cargo test --release --test cancel_latency -- --ignored --nocapture`.
use profsubd::eval::folds::{find_folds_with, FoldSettings};
use profsubd::refine::{refine_uniform_with, VertexOrder};
use profsubd::{revolve, Control, Evaluator, RevolveInput, Settings};
use std::sync::{Arc, Mutex};
use std::time::Instant;

/// Run `f` with a recording hook; print the call's time and its longest waits.
fn gaps(name: &str, f: impl FnOnce(&Control)) {
    let log: Arc<Mutex<Vec<(f64, f64)>>> = Arc::new(Mutex::new(Vec::new()));
    let l = log.clone();
    let t0 = Instant::now();
    let c = Control::NONE.with_progress(move |x: f64| {
        l.lock().unwrap().push((t0.elapsed().as_secs_f64(), x));
        false
    });
    f(&c);
    let end = t0.elapsed().as_secs_f64();
    let mut v = log.lock().unwrap().clone();
    // Fraction -1 stands for the call, 2 for the return.
    v.insert(0, (0.0, -1.0));
    v.push((end, 2.0));
    let mut g: Vec<(f64, f64, f64)> = v
        .windows(2)
        .map(|w| (w[1].0 - w[0].0, w[0].1, w[1].1))
        .collect();
    g.sort_by(|a, b| b.0.partial_cmp(&a.0).unwrap());
    println!("{name}: whole {:.1} ms, {} calls", 1e3 * end, v.len() - 2);
    for (d, a, b) in g.iter().take(6) {
        println!("   gap {:.1} ms between {a:.4} and {b:.4}", 1e3 * d);
    }
}

/// The C harness's profile (with its axis point unless `partial`), sampled `a` × `b`.
fn input(a: usize, b: usize, angle: f64, partial: bool) -> RevolveInput {
    let p = [[0.0, 0.0], [0.6, 0.0], [0.8, 0.5], [0.4, 1.2], [0.5, 1.6]];
    let mut i = RevolveInput::new(if partial { p[1..].to_vec() } else { p.to_vec() });
    i.samples_profile = a;
    i.samples_around = b;
    i.angle_deg = angle;
    i
}

#[test]
#[ignore = "a measurement: run with --ignored --nocapture"]
fn where_the_gaps_are() {
    let big = revolve::build(&input(256, 512, 360.0, false), &Settings::default()).unwrap();
    gaps("revolve 256x512", |c| {
        let s = Settings {
            control: c.clone(),
            ..Settings::default()
        };
        revolve::build(&input(256, 512, 360.0, false), &s).unwrap();
    });
    let mesh = big.mesh.clone();
    gaps("evaluator", |c| {
        Evaluator::with_control(&mesh, &mesh.options().resolve(), c).unwrap();
    });
    let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
    gaps("fold check", |c| {
        find_folds_with(&ev, &FoldSettings::default(), c).unwrap();
    });
    gaps("refine 2", |c| {
        refine_uniform_with(
            &mesh,
            &mesh.options().resolve(),
            2,
            VertexOrder::default(),
            c,
        )
        .unwrap();
    });
    gaps("revolve 270 128x256", |c| {
        let s = Settings {
            control: c.clone(),
            ..Settings::default()
        };
        revolve::build(&input(128, 256, 270.0, true), &s).unwrap();
    });
}
