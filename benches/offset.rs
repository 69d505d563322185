//! Offset evaluation (`construct::shell`) beside plain limit evaluation at the same random
//! points, one thread, and the hollow solid's construction beside its evaluator's build.
//!
//! `cargo bench --bench offset`. Absolute times; the README quotes the ratio offset / limit
//! from one run (not asserted). On a loaded machine criterion's separate runs of the two
//! drift apart, so the ratio is also measured *paired*: rounds timing the limit then the
//! offset back to back over the same points, the median of the per-round ratios printed.
//!
//! Instruction counts, which the machine's load does not change: with
//! `PROFSUBD_OFFSET_PASSES=K` the bench only runs `K` passes of [`limit_pass`] and of
//! [`offset_pass`] (one thread, the same points) and exits; under
//! `valgrind --tool=callgrind` their inclusive counts give the ratio (README).

use criterion::{criterion_group, criterion_main, Criterion};
use profsubd::construct::shell::{hollow_solid, OffsetSettings, OffsetSurface};
use profsubd::eval::{Domain, Evaluator};
use std::time::Instant;

mod support;

/// Rounds of the paired ratio measurement.
const PAIRED_ROUNDS: usize = 21;

/// The limit at every point, one by one.
#[inline(never)]
fn limit_pass(ev: &Evaluator, faces: &[u32], us: &[f64], vs: &[f64]) {
    for i in 0..faces.len() {
        std::hint::black_box(ev.evaluate(faces[i], us[i], vs[i]).unwrap());
    }
}

/// The offset at every point, one by one.
#[inline(never)]
fn offset_pass(offset: &OffsetSurface, faces: &[u32], us: &[f64], vs: &[f64]) {
    for i in 0..faces.len() {
        std::hint::black_box(offset.evaluate(faces[i], us[i], vs[i]).unwrap());
    }
}

fn benches(c: &mut Criterion) {
    let model = support::bottle(64, 48);
    let mesh = &model.mesh;
    let options = mesh.options().resolve();
    let label = format!("bottle {} quads", mesh.num_faces());
    let thickness = 0.002 * mesh.bounding_box_diagonal();
    // One thread for the batches too: the offset's batches run on its evaluator's threads.
    let ev = Evaluator::with_threads(mesh, &options, 1).unwrap();
    let n = 10_000;
    let (faces, us, vs) = support::random_points(&ev, n);
    let mut level0 = OffsetSurface::new(mesh, &options, OffsetSettings::new(thickness)).unwrap();
    level0.set_threads(1);
    if let Ok(passes) = std::env::var("PROFSUBD_OFFSET_PASSES") {
        let passes: usize = passes.parse().expect("PROFSUBD_OFFSET_PASSES: a count");
        for _ in 0..passes {
            limit_pass(&ev, &faces, &us, &vs);
            offset_pass(&level0, &faces, &us, &vs);
        }
        std::process::exit(0);
    }
    c.bench_function(&format!("limit at {n} random points, {label}"), |b| {
        b.iter(|| limit_pass(&ev, &faces, &us, &vs))
    });
    // Batches, one thread each (`evaluate_points`: the same per-point work behind the
    // batch's checks).
    c.bench_function(
        &format!("limit batch of {n} points, 1 thread, {label}"),
        |b| b.iter(|| std::hint::black_box(ev.evaluate_points(Domain::Ptex, &faces, &us, &vs))),
    );
    c.bench_function(
        &format!("offset batch of {n} points, 1 thread, {label}"),
        |b| b.iter(|| std::hint::black_box(level0.evaluate_points(Domain::Ptex, &faces, &us, &vs))),
    );
    // Each round: the fastest of three passes of each (a pass preempted by another process
    // is slower, never faster).
    let fastest = |pass: &dyn Fn()| {
        (0..3)
            .map(|_| {
                let start = Instant::now();
                pass();
                start.elapsed().as_secs_f64()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let mut ratios: Vec<f64> = (0..PAIRED_ROUNDS)
        .map(|_| {
            let limit = fastest(&|| limit_pass(&ev, &faces, &us, &vs));
            let offset = fastest(&|| offset_pass(&level0, &faces, &us, &vs));
            offset / limit
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    println!(
        "paired offset (level 0) / limit over {n} points, {label}: median {:.3} (min {:.3}, \
         max {:.3}, {PAIRED_ROUNDS} rounds)",
        ratios[PAIRED_ROUNDS / 2],
        ratios[0],
        ratios[PAIRED_ROUNDS - 1]
    );
    for level in [0, 2] {
        // Timing only: the level-2 crust folds next to this model's creases (see the README).
        let settings = OffsetSettings {
            level,
            accept_folds: true,
            ..OffsetSettings::new(thickness)
        };
        let offset = OffsetSurface::new(mesh, &options, settings).unwrap();
        c.bench_function(
            &format!("offset at {n} random points, level {level}, {label}"),
            |b| b.iter(|| offset_pass(&offset, &faces, &us, &vs)),
        );
    }

    let big = support::bottle(128, 80);
    let big_mesh = &big.mesh;
    let big_label = format!("bottle {} quads", big_mesh.num_faces());
    let mut group = c.benchmark_group("shell");
    group.sample_size(10);
    group.bench_function(format!("evaluator build, {big_label}"), |b| {
        b.iter(|| Evaluator::new(big_mesh, &options).unwrap())
    });
    group.bench_function(format!("hollow solid (offset + fit), {big_label}"), |b| {
        b.iter(|| {
            let offset = OffsetSurface::new(
                big_mesh,
                &options,
                OffsetSettings::new(0.002 * big_mesh.bounding_box_diagonal()),
            )
            .unwrap();
            hollow_solid(&offset, &profsubd::Control::NONE).unwrap()
        })
    });
    group.finish();
}

criterion_group!(offset, benches);
criterion_main!(offset);
