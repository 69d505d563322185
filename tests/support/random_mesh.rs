//! Random test meshes: a grid of quads with random positions, some quads split into
//! triangles or merged into hexagons, random creases, corners, holes and options. Each test
//! sets its own chances; a chance of 0 draws nothing from the generator, so a test's meshes
//! stay the same for its seed when other tests change theirs. `mod random_mesh;` via
//! `#[path = "support/random_mesh.rs"]` in a test crate.

use glam::DVec3;
use profsubd::options::{BoundaryInterpolation, CreaseMethod, PartialOptions};
use profsubd::{Corner, Crease, Mesh, MeshParts};
use rand::Rng;

/// The shape of a random grid mesh and the chance of each feature.
pub struct RandomGrid {
    /// Cells across.
    pub nx: u32,
    /// Cells up.
    pub ny: u32,
    /// Coordinates are uniform in `-span..span`...
    pub span: f64,
    /// ...or, with this chance, one of [`AWKWARD`].
    pub awkward: f64,
    /// Chance that a cell and the next are one hexagon (drawn where a next cell exists).
    pub hexagons: f64,
    /// Chance that a quad is split into two triangles.
    pub triangles: f64,
    /// Chance of a crease on a cell's edge from its corner 0 to `crease_to` (1: the bottom
    /// edge, 3: the left edge).
    pub creases: f64,
    /// The corner a crease goes to from a cell's corner 0.
    pub crease_to: usize,
    /// Crease sharpness is uniform in `0..max_crease`.
    pub max_crease: f32,
    /// Chance that a vertex is a corner.
    pub corners: f64,
    /// Corner sharpness is uniform in `0..max_corner`.
    pub max_corner: f32,
    /// Chance that a face is a hole.
    pub holes: f64,
    /// The boundary tags, one drawn uniformly.
    pub boundaries: [Option<BoundaryInterpolation>; 3],
}

/// Coordinates that stress number formatting and arithmetic: signed zero, subnormal, huge,
/// inexact in binary.
pub const AWKWARD: [f64; 8] = [0.0, -0.0, 1e-300, 5e-324, 1e300, 0.1, 1.0 / 3.0, -2.5e-8];

impl RandomGrid {
    /// A mesh drawn from `rng`; Chaikin creases with a chance of one half.
    pub fn mesh(&self, rng: &mut impl Rng) -> Mesh {
        let (nx, ny) = (self.nx, self.ny);
        let positions = (0..(nx + 1) * (ny + 1))
            .map(|_| DVec3::from_array([0; 3].map(|_| self.coordinate(rng))))
            .collect();
        let mut parts = MeshParts {
            positions,
            ..Default::default()
        };
        let id = |i: u32, j: u32| j * (nx + 1) + i;
        for j in 0..ny {
            let mut i = 0;
            while i < nx {
                let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
                if self.hexagons > 0.0 && i + 1 < nx && rng.random_bool(self.hexagons) {
                    let h = [q[0], q[1], id(i + 2, j), id(i + 2, j + 1), q[2], q[3]];
                    parts.face_sizes.push(6);
                    parts.face_indices.extend(h);
                    i += 2;
                    continue;
                }
                if rng.random_bool(self.triangles) {
                    parts.face_sizes.extend([3, 3]);
                    parts
                        .face_indices
                        .extend([q[0], q[1], q[2], q[0], q[2], q[3]]);
                } else {
                    parts.face_sizes.push(4);
                    parts.face_indices.extend(q);
                }
                if rng.random_bool(self.creases) {
                    parts.creases.push(Crease {
                        vertices: [q[0], q[self.crease_to]],
                        sharpness: rng.random_range(0.0..self.max_crease),
                    });
                }
                i += 1;
            }
        }
        for v in 0..parts.positions.len() as u32 {
            if rng.random_bool(self.corners) {
                parts.corners.push(Corner {
                    vertex: v,
                    sharpness: rng.random::<f32>() * self.max_corner,
                });
            }
        }
        let nf = parts.face_sizes.len() as u32;
        parts.holes = (0..nf).filter(|_| rng.random_bool(self.holes)).collect();
        parts.options = PartialOptions {
            boundary: self.boundaries[rng.random_range(0..self.boundaries.len())],
            crease_method: rng.random_bool(0.5).then_some(CreaseMethod::Chaikin),
            triangles: None,
        };
        Mesh::from_parts(parts).unwrap()
    }

    fn coordinate(&self, rng: &mut impl Rng) -> f64 {
        if self.awkward > 0.0 && rng.random_bool(self.awkward) {
            AWKWARD[rng.random_range(0..AWKWARD.len())]
        } else {
            rng.random_range(-self.span..self.span)
        }
    }
}
