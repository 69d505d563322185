//! GBS limit positions by refinement: refine to a level, then put each vertex where the limit
//! surface passes, exactly where a closed-form stencil is known (order 4: smooth valence-4
//! vertices with four quads, crease vertices, corners; tension included) and otherwise the
//! refined control point itself (measured accuracy in the README: the gap shrinks about 4×
//! per level).

use glam::DVec3;

use super::refine::{vertex_kind, VertexKind};
use super::rules::order4_limit_weight;
use super::{refine_gbs, GbsLevel, GbsOptions};
use crate::error::Result;
use crate::topology::Level;

/// Limit points at the vertices of a refined level.
#[derive(Debug, Clone)]
pub struct LimitPoints {
    /// The refined level the points belong to.
    pub level: GbsLevel,
    /// One point per vertex of `level`.
    pub points: Vec<DVec3>,
    /// Whether each point is the exact limit (a closed-form stencil) or the control point.
    pub exact: Vec<bool>,
}

/// Limit points of `mesh` at its `level`-times refined vertices. Errors as
/// [`refine_gbs`].
pub fn limit_points(mesh: &crate::Mesh, options: &GbsOptions, level: u32) -> Result<LimitPoints> {
    let refined = refine_gbs(mesh, options, level)?;
    let (points, exact) = (0..refined.positions.len())
        .map(|i| vertex_limit(&refined, options.order, i))
        .unzip();
    Ok(LimitPoints {
        level: refined,
        points,
        exact,
    })
}

/// The limit of vertex `i` of `l` and whether it is exact.
fn vertex_limit(l: &GbsLevel, order: u32, i: usize) -> (DVec3, bool) {
    let p = &l.positions;
    let level = &l.level;
    match vertex_kind(level, i) {
        VertexKind::Corner => (p[i], order % 2 == 0),
        _ if order != 4 => (p[i], false),
        VertexKind::Crease(_, [a, b]) => {
            let w = order4_limit_weight(l.tension);
            ((p[a as usize] + p[i] * w + p[b as usize]) / (w + 2.0), true)
        }
        VertexKind::Smooth => match regular_ring(level, i) {
            Some((edge, diag)) => {
                // The tensor product of the curve stencil (1, w, 1)/(w + 2).
                let w = order4_limit_weight(l.tension);
                let e: DVec3 = edge.iter().map(|&j| p[j as usize]).sum();
                let d: DVec3 = diag.iter().map(|&j| p[j as usize]).sum();
                ((p[i] * (w * w) + e * w + d) / ((w + 2.0) * (w + 2.0)), true)
            }
            None => (p[i], false),
        },
    }
}

/// For a vertex of valence 4 on four quads: its four edge neighbours and four diagonal ones.
fn regular_ring(level: &Level, i: usize) -> Option<([u32; 4], [u32; 4])> {
    let faces = level.vertex_faces(i);
    if faces.len() != 4 || level.valence(i) != 4 {
        return None;
    }
    let (mut edge, mut diag) = ([0; 4], [0; 4]);
    for (j, (&f, &l)) in faces
        .iter()
        .zip(level.vertex_face_local_indices(i))
        .enumerate()
    {
        let fv = level.face_vertices(f as usize);
        if fv.len() != 4 {
            return None;
        }
        edge[j] = fv[(l as usize + 1) % 4];
        diag[j] = fv[(l as usize + 2) % 4];
    }
    Some((edge, diag))
}
