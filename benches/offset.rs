//! Offset evaluation (`construct::shell`) beside plain limit evaluation at the same random
//! points, one thread, and the hollow solid's construction beside its evaluator's build.
//!
//! `cargo bench --bench offset`. Absolute times; the README quotes the ratio offset / limit
//! from one run (not asserted). On a loaded machine criterion's separate runs of the two
//! drift apart, so the ratio is also measured *paired*: rounds timing the limit then the
//! offset back to back over the same points, the median of the per-round ratios printed.

use criterion::{criterion_group, criterion_main, Criterion};
use profsubd::construct::shell::{hollow_solid, OffsetSettings, OffsetSurface};
use profsubd::eval::Evaluator;
use std::time::Instant;

mod support;

/// Rounds of the paired ratio measurement.
const PAIRED_ROUNDS: usize = 21;

fn benches(c: &mut Criterion) {
    let model = support::bottle(64, 48);
    let mesh = &model.mesh;
    let options = mesh.options().resolve();
    let label = format!("bottle {} quads", mesh.num_faces());
    let thickness = 0.002 * mesh.bounding_box_diagonal();
    let ev = Evaluator::new(mesh, &options).unwrap();
    let n = 10_000;
    let (faces, us, vs) = support::random_points(&ev, n);
    c.bench_function(&format!("limit at {n} random points, {label}"), |b| {
        b.iter(|| {
            for i in 0..n {
                std::hint::black_box(ev.evaluate(faces[i], us[i], vs[i]).unwrap());
            }
        })
    });
    let level0 = OffsetSurface::new(mesh, &options, OffsetSettings::new(thickness)).unwrap();
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
            let limit = fastest(&|| {
                for i in 0..n {
                    std::hint::black_box(ev.evaluate(faces[i], us[i], vs[i]).unwrap());
                }
            });
            let offset = fastest(&|| {
                for i in 0..n {
                    std::hint::black_box(level0.evaluate(faces[i], us[i], vs[i]).unwrap());
                }
            });
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
            |b| {
                b.iter(|| {
                    for i in 0..n {
                        std::hint::black_box(offset.evaluate(faces[i], us[i], vs[i]).unwrap());
                    }
                })
            },
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
