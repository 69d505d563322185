//! The hollow solid: the outer control mesh (the input refined to the crust's level), an
//! inner one with the same topology and reversed faces whose vertices sit at the offset, and
//! for open surfaces a rim of quads joining each boundary loop of the two, creased
//! infinitely sharp where it meets them.
//!
//! Vertices: the outer mesh's `n`, then their inner twins `n..2n`. Faces: the outer faces,
//! the inner faces reversed, then one rim quad per boundary edge. A closed input gives two
//! closed sheets (Euler characteristic 2 × the input's); an open one a single closed
//! surface. Under the infinitely sharp rim creases each side's limit is the open
//! surface's own (a boundary under the boundary rules is a crease), so the outer wall is
//! the input surface exactly; the data points are the outer limit positions and the
//! offset at each vertex ([`super::offset`]).

use glam::DVec3;

use super::offset::OffsetSurface;
use crate::construct::design::{bilinear, DesignLattice, LATTICE};
use crate::error::Result;
use crate::eval::limit_vertex_samples;
use crate::mesh::{Crease, MeshParts, SHARPNESS_INFINITE};

/// The cage of the hollow solid of `offset` (each vertex at its data point) and its design
/// lattice: the limit surface on outer faces, the offset on inner faces, the bilinear
/// interpolation of the corners on the rim.
pub fn hollow_parts(offset: &OffsetSurface) -> Result<(MeshParts, DesignLattice)> {
    let ev = offset.fine();
    let outer = ev.mesh();
    let n = outer.num_vertices() as u32;
    let limits = limit_vertex_samples(outer, ev.options())?;
    let mut positions: Vec<DVec3> = limits.iter().map(|s| s.position).collect();
    let inner: Vec<DVec3> = positions
        .iter()
        .zip(offset.corner_vectors())
        .map(|(p, d)| *p - *d)
        .collect();
    positions.extend(&inner);
    let src = outer.parts();
    let mut parts = MeshParts {
        positions,
        face_sizes: Vec::new(),
        face_indices: src.face_indices.clone(),
        creases: src.creases.clone(),
        corners: src.corners.clone(),
        holes: src.holes.clone(),
        ..Default::default()
    };
    let faces = outer.num_faces() as u32;
    for f in 0..faces as usize {
        let face = outer.face(f);
        parts.face_indices.extend(face.iter().rev().map(|&v| v + n));
    }
    parts.creases.extend(src.creases.iter().map(|c| Crease {
        vertices: c.vertices.map(|v| v + n),
        sharpness: c.sharpness,
    }));
    parts
        .corners
        .extend(src.corners.iter().map(|c| crate::mesh::Corner {
            vertex: c.vertex + n,
            sharpness: c.sharpness,
        }));
    parts.holes.extend(src.holes.iter().map(|&h| h + faces));
    // The rim: for each side a → b with no twin b → a, the quad (b, a, a', b').
    let mut sides = std::collections::HashSet::new();
    for f in 0..faces as usize {
        let face = outer.face(f);
        for k in 0..face.len() {
            sides.insert((face[k], face[(k + 1) % face.len()]));
        }
    }
    let mut rim = Vec::new();
    for f in 0..faces as usize {
        let face = outer.face(f);
        for k in 0..face.len() {
            let (a, b) = (face[k], face[(k + 1) % face.len()]);
            if !sides.contains(&(b, a)) {
                rim.push([b, a, a + n, b + n]);
            }
        }
    }
    for q in &rim {
        parts.face_indices.extend(q);
        for pair in [[q[0], q[1]], [q[2], q[3]]] {
            parts.creases.push(Crease {
                vertices: pair,
                sharpness: SHARPNESS_INFINITE,
            });
        }
    }
    parts.face_sizes = vec![4; parts.face_indices.len() / 4];
    let design = lattice(offset, &parts, faces as usize, &rim)?;
    Ok((parts, design))
}

/// The design lattice of the solid's faces (see [`hollow_parts`]).
fn lattice(
    offset: &OffsetSurface,
    parts: &MeshParts,
    faces: usize,
    rim: &[[u32; 4]],
) -> Result<DesignLattice> {
    let ev = offset.fine();
    let m = LATTICE + 1;
    let mut points = Vec::with_capacity((2 * faces + rim.len()) * m * m);
    let uv = |k: usize| {
        (
            (k % m) as f64 / LATTICE as f64,
            (k / m) as f64 / LATTICE as f64,
        )
    };
    for f in 0..faces as u32 {
        for k in 0..m * m {
            let (u, v) = uv(k);
            points.push(if ev.has_surface(f) {
                ev.evaluate(f, u, v)?.position
            } else {
                DVec3::ZERO
            });
        }
    }
    // A reversed face [d, c, b, a] of [a, b, c, d]: its (u, v) is the outer (u, 1 − v).
    for f in 0..faces as u32 {
        for k in 0..m * m {
            let (u, v) = uv(k);
            points.push(if ev.has_surface(f) {
                offset.evaluate_fine(f, u, 1.0 - v, 1.0)?.position
            } else {
                DVec3::ZERO
            });
        }
    }
    for q in rim {
        let c = q.map(|v| parts.positions[v as usize]);
        for k in 0..m * m {
            let (u, v) = uv(k);
            points.push(bilinear(c, u, v));
        }
    }
    Ok(DesignLattice::from_points(points))
}
