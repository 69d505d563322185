//! Fixtures shared by the unit tests (compiled for tests only): the one place a test module
//! takes a fixture from another module's tests.

use std::f64::consts::TAU;

use glam::DVec3;

use crate::mesh::{Crease, Mesh, MeshParts};

/// The unit square as one quad without tags.
pub(crate) fn quad() -> MeshParts {
    MeshParts {
        positions: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ],
        face_sizes: vec![4],
        face_indices: vec![0, 1, 2, 3],
        ..Default::default()
    }
}

/// The square pyramid: unit square base (a quad facing down), apex (0.5, 0.5, 1), four
/// triangles.
pub(crate) fn square_pyramid() -> MeshParts {
    let mut positions = quad().positions;
    positions.push(DVec3::new(0.5, 0.5, 1.0));
    MeshParts {
        positions,
        face_sizes: vec![4, 3, 3, 3, 3],
        face_indices: vec![0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4],
        ..Default::default()
    }
}

/// The unit square as a one-quad mesh.
pub(crate) fn quad_mesh() -> Mesh {
    Mesh::from_parts(quad()).unwrap()
}

/// The unit cube `[0, 1]³`, vertex `k` at `(k & 1, k >> 1 & 1, k >> 2)`, outward quads,
/// with `creases`.
pub(crate) fn unit_cube(creases: Vec<Crease>) -> Mesh {
    let positions = (0..8)
        .map(|k| DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64))
        .collect();
    Mesh::from_parts(MeshParts {
        positions,
        face_sizes: vec![4; 6],
        face_indices: vec![
            0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
        ],
        creases,
        ..Default::default()
    })
    .unwrap()
}

/// `n` points on the circle of radius `r` about the origin, counter-clockwise.
pub(crate) fn circle2(n: usize, r: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let t = TAU * i as f64 / n as f64;
            [r * crate::math::cos(t), r * crate::math::sin(t)]
        })
        .collect()
}

/// An `n × n` grid of unit quads, vertex `(i, j)` at `(i, j, height(i, j))`, face `(i, j)`
/// = index `j * n + i` with corner 0 at `(i, j)`.
pub(crate) fn grid(n: usize, height: impl Fn(f64, f64) -> f64) -> MeshParts {
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
