//! Evaluator benches: construction, random (face, u, v) evaluation, vertex limit stencils and
//! uniform refinement, on a profile model with extraordinary vertices and creases.
//!
//! `cargo bench --bench evaluator`. Absolute times only: the ratios to OpenSubdiv come from
//! the C++ bench `cpp_tests/bench_eval.cpp`, which runs both in one process.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use profsubd::eval::{limit_stencils, Evaluator};
use profsubd::refine::refine_uniform;
use profsubd::SubdivOptions;

mod support;

fn benches(c: &mut Criterion) {
    let model = support::bottle(64, 48);
    let mesh = &model.mesh;
    let options = SubdivOptions::default();
    let label = format!("bottle {} quads", mesh.num_faces());

    c.bench_function(&format!("evaluator build, {label}"), |b| {
        b.iter(|| Evaluator::new(mesh, &options).unwrap())
    });

    let mut ev = Evaluator::new(mesh, &options).unwrap();
    ev.set_threads(1);
    let moved: Vec<_> = mesh.positions().iter().map(|p| *p * 1.01).collect();
    c.bench_function(&format!("evaluator position update, {label}"), |b| {
        b.iter(|| ev.set_positions(&moved).unwrap())
    });
    let n = 10_000;
    let (faces, us, vs) = support::random_points(&ev, n);
    c.bench_function(
        &format!("evaluate {n} random points, one thread, {label}"),
        |b| b.iter(|| ev.evaluate_many(&faces, &us, &vs).unwrap()),
    );
    ev.set_threads(0);
    c.bench_function(
        &format!("evaluate {n} random points, all cores, {label}"),
        |b| b.iter(|| ev.evaluate_many(&faces, &us, &vs).unwrap()),
    );

    c.bench_function(&format!("vertex limit stencils, {label}"), |b| {
        b.iter(|| limit_stencils(mesh, &options).unwrap())
    });

    let mut group = c.benchmark_group("refinement");
    group.sample_size(10);
    group.bench_function(format!("refine_uniform level 3, {label}"), |b| {
        b.iter_batched(
            || mesh.clone(),
            |m| refine_uniform(&m, &options, 3).unwrap(),
            BatchSize::LargeInput,
        )
    });
    group.finish();
}

criterion_group!(evaluator, benches);
criterion_main!(evaluator);
