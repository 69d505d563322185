//! The main job end to end: profile curves → fitted Catmull-Clark cage (sampling, sweeps,
//! caps, crease tags, limit stencils and the interpolating solve).
//!
//! `cargo bench --bench profile`. The ratio to OpenSubdiv's limit stencil table of the same
//! mesh comes from the C++ bench `cpp_tests/bench_profile.cpp`.

use criterion::{criterion_group, criterion_main, Criterion};

mod support;

fn benches(c: &mut Criterion) {
    let mut group = c.benchmark_group("profile pipeline");
    group.sample_size(10);
    for (around, along) in [(32, 16), (128, 64)] {
        group.bench_function(format!("bottle {around} x {along}"), |b| {
            b.iter(|| support::bottle(around, along))
        });
    }
    group.finish();
}

criterion_group!(profile, benches);
criterion_main!(profile);
