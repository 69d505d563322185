//! Tests of [`super::evaluator`] against analytic surfaces.

use glam::DVec3;

use crate::eval::bspline::BicubicPatch;
use crate::eval::evaluator::Evaluator;
use crate::mesh::{Crease, Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, SubdivOptions};

/// An `n × n` grid of unit quads, vertex `(i, j)` at `(i, j, height(i, j))`, face `(i, j)`
/// = index `j * n + i` with corner 0 at `(i, j)`.
fn grid(n: usize, height: impl Fn(f64, f64) -> f64) -> MeshParts {
    let mut positions = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            positions.push(DVec3::new(i as f64, j as f64, height(i as f64, j as f64)));
        }
    }
    let id = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    let mut face_indices = Vec::new();
    for j in 0..n {
        for i in 0..n {
            face_indices.extend([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    MeshParts {
        positions,
        face_sizes: vec![4; n * n],
        face_indices,
        ..Default::default()
    }
}

fn bumpy(x: f64, y: f64) -> f64 {
    (0.7 * x).sin() * (0.4 * y + 0.3).cos() + 0.05 * x * y
}

#[test]
fn interior_face_of_a_grid_is_the_bicubic_b_spline() {
    let n = 5;
    let parts = grid(n, bumpy);
    let mesh = Mesh::from_parts(parts.clone()).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    // Face (2, 2): control points (1..=4, 1..=4).
    let pts: [DVec3; 16] =
        std::array::from_fn(|k| parts.positions[(1 + k / 4) * (n + 1) + 1 + k % 4]);
    let patch = BicubicPatch::with_boundary(pts, 0);
    for &(u, v) in &[(0.0, 0.0), (0.3, 0.8), (1.0, 0.5), (0.5, 1.0), (0.123, 0.987)] {
        let got = ev.evaluate((2 * n + 2) as u32, u, v).unwrap();
        let (p, du, dv) = patch.evaluate(u, v);
        assert!((got.position - p).length() < 1e-15, "{u} {v}");
        assert!((got.du - du).length() < 1e-14);
        assert!((got.dv - dv).length() < 1e-14);
        // B-splines reproduce the linear x and y of the grid.
        assert!((got.position.x - (2.0 + u)).abs() < 1e-14);
        assert!((got.position.y - (2.0 + v)).abs() < 1e-14);
        assert!((got.du.x - 1.0).abs() < 1e-14 && got.du.y.abs() < 1e-14);
    }
}

#[test]
fn boundary_and_corner_faces_follow_the_crease_rules() {
    // Under edge-and-corner interpolation the boundary is the cubic B-spline of the boundary
    // vertices, interpolating the corners; a planar grid stays exactly linear.
    let n = 4;
    let mesh = Mesh::from_parts(grid(n, |x, y| 0.25 * x * x - 0.1 * y * y * y)).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let corner = ev.evaluate(0, 0.0, 0.0).unwrap();
    assert!((corner.position - DVec3::ZERO).length() < 1e-15);
    // Along the bottom boundary y = 0, heights 0.25 x²: the B-spline of x² samples with the
    // end rule reproduces x² + 1/3·(B-spline offset) away from the ends; at the limit point
    // of vertex (2, 0) it is (P1 + 4 P2 + P3) / 6.
    let p = ev.evaluate(1, 1.0, 0.0).unwrap().position;
    let want = (0.25 * 1.0 + 4.0 * 0.25 * 4.0 + 0.25 * 9.0) / 6.0;
    assert!((p - DVec3::new(2.0, 0.0, want)).length() < 1e-15, "{p}");
    // x and y stay linear everywhere, boundary faces included.
    for f in [0u32, 1, 3, 4, 15] {
        let (i, j) = ((f % 4) as f64, (f / 4) as f64);
        let s = ev.evaluate(f, 0.25, 0.75).unwrap();
        assert!((s.position.x - (i + 0.25)).abs() < 1e-14, "face {f}");
        assert!((s.position.y - (j + 0.75)).abs() < 1e-14, "face {f}");
        assert!((s.du.x - 1.0).abs() < 1e-14 && (s.dv.y - 1.0).abs() < 1e-14);
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let mesh = Mesh::from_parts(grid(4, bumpy)).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let h = 1e-6;
    for f in 0..16u32 {
        let (u, v) = (0.37, 0.61);
        let s = ev.evaluate(f, u, v).unwrap();
        let fu = (ev.evaluate(f, u + h, v).unwrap().position
            - ev.evaluate(f, u - h, v).unwrap().position)
            / (2.0 * h);
        let fv = (ev.evaluate(f, u, v + h).unwrap().position
            - ev.evaluate(f, u, v - h).unwrap().position)
            / (2.0 * h);
        assert!((s.du - fu).length() < 1e-8, "face {f}");
        assert!((s.dv - fv).length() < 1e-8, "face {f}");
    }
}

#[test]
fn infinitely_sharp_crease_splits_the_grid_into_two_boundary_patches() {
    // A crease along x = 2 makes both sides boundary patches: the crease curve is the
    // B-spline of the crease vertices alone, whatever the heights beside it.
    let mut parts = grid(4, |x, y| if x == 2.0 { 0.1 * y * y } else { (x * y).sin() });
    for j in 0..4u32 {
        parts.creases.push(Crease {
            vertices: [j * 5 + 2, (j + 1) * 5 + 2],
            sharpness: 10.0,
        });
    }
    let mesh = Mesh::from_parts(parts).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    // Face (1, 1) has its right edge on the crease; at (1, 0) it is the crease's limit at
    // vertex (2, 1): (z(2,0) + 4 z(2,1) + z(2,2)) / 6.
    let left = ev.evaluate(5, 1.0, 0.0).unwrap().position;
    let right = ev.evaluate(6, 0.0, 0.0).unwrap().position;
    let want = DVec3::new(2.0, 1.0, (0.0 + 4.0 * 0.1 + 0.4) / 6.0);
    assert!((left - want).length() < 1e-15, "{left}");
    assert!((right - want).length() < 1e-15, "{right}");
}

#[test]
fn bad_input_is_rejected_with_a_reason() {
    let mut parts = grid(3, bumpy);
    parts.holes.push(4);
    let mesh = Mesh::from_parts(parts).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let msg = |r: crate::Result<_>| format!("{}", r.unwrap_err());
    assert!(msg(ev.evaluate(9, 0.5, 0.5)).contains("out of range"));
    assert!(msg(ev.evaluate(0, 1.5, 0.5)).contains("outside [0, 1]"));
    assert!(msg(ev.evaluate(0, 0.5, f64::NAN)).contains("outside [0, 1]"));
    assert!(msg(ev.evaluate(4, 0.5, 0.5)).contains("hole"));
    let none = SubdivOptions {
        boundary: BoundaryInterpolation::None,
        ..Default::default()
    };
    let ev = Evaluator::new(&mesh, &none).unwrap();
    assert!(msg(ev.evaluate(0, 0.5, 0.5)).contains("no limit surface"));
    assert!(ev.evaluate_many(&[0, 1], &[0.5], &[0.5, 0.5]).is_err());
}
