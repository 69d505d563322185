//! Checks shared by the sweep and revolution tests: `mod swept;` via
//! `#[path = "support/swept.rs"]` in a test crate.

use glam::DVec3;
use profsubd::eval::{limit_stencils, Evaluator};
use profsubd::Fitted;

/// Largest distance between a vertex's exact limit position and its target, over the diagonal.
pub fn relative_residual(s: &Fitted) -> f64 {
    let table = limit_stencils(&s.mesh, &s.mesh.options().resolve()).unwrap();
    let limits = table.apply(s.mesh.positions()).unwrap();
    let worst = limits
        .iter()
        .zip(&s.targets)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    worst / s.mesh.bounding_box_diagonal()
}

/// How many vertices have 1, 2, 3 and 4 crease edges.
pub fn crease_degrees(s: &Fitted) -> Vec<usize> {
    let mut degree = vec![0usize; s.mesh.num_vertices()];
    for c in s.mesh.creases() {
        for v in c.vertices {
            degree[v as usize] += 1;
        }
    }
    (1..=4)
        .map(|k| degree.iter().filter(|&&d| d == k).count())
        .collect()
}

/// The exact limit surface of each of `faces` at the `(n + 1) × (n + 1)` parameters
/// `(a / n, b / n)`.
pub fn limit_samples(s: &Fitted, faces: &[u32], n: usize) -> Vec<DVec3> {
    let eval = Evaluator::new(&s.mesh, &s.mesh.options().resolve()).unwrap();
    let mut out = Vec::new();
    for &f in faces {
        for a in 0..=n {
            for b in 0..=n {
                let (u, v) = (a as f64 / n as f64, b as f64 / n as f64);
                out.push(eval.evaluate(f, u, v).unwrap().position);
            }
        }
    }
    out
}
