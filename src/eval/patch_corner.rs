//! A point exactly on a vertex that never becomes regular under refinement.
//!
//! Around an extraordinary vertex, a dart or an infinitely sharp vertex with smooth edges,
//! every refinement leaves one irregular sub-face at the vertex, so the quadtree descent
//! would never end there. The limit at the vertex itself is known exactly: the vertex-limit
//! code ([`super::vertex_limit`]) applied to the current neighbourhood, whose face 0 is the
//! sub-face being refined and so the vertex's first face — its derivatives are then in that
//! sub-face's parameterization (interior vertices; at a boundary vertex the first face is
//! the leading boundary face, see [`super::vertex_limit`] for the convention).

use glam::DVec3;

use super::patch_topology::Neighbourhood;
use super::sample::LimitSample;
use super::vertex_limit::limit_vertex_samples;
use crate::error::Result;
use crate::mesh::SHARPNESS_INFINITE;
use crate::options::SubdivOptions;

fn is_semi_sharp(s: f32) -> bool {
    s > 0.0 && s < SHARPNESS_INFINITE
}

/// True when vertex `c` or one of its edges still has finite non-zero sharpness: the limit
/// there may need more than `c`'s faces (Chaikin averages over neighbouring vertices), so
/// refine first.
fn has_semi_sharpness(nb: &Neighbourhood, c: u32) -> bool {
    if is_semi_sharp(nb.vertex_tag(c)) {
        return true;
    }
    nb.vertex_faces(c).iter().any(|&g| {
        let face = nb.face(g);
        let n = face.len();
        (0..n).any(|i| {
            face[i] == c
                && (is_semi_sharp(nb.edge_tag(c, face[(i + 1) % n]))
                    || is_semi_sharp(nb.edge_tag(c, face[(i + n - 1) % n])))
        })
    })
}

/// The exact limit at corner `k` of face 0 of `nb` (vertex positions `positions`),
/// derivatives multiplied by `scale`; `None` while sharpness at the corner has not decayed
/// (refine further).
pub fn corner_limit(
    nb: &Neighbourhood,
    positions: &[DVec3],
    k: usize,
    options: &SubdivOptions,
    scale: f64,
) -> Result<Option<LimitSample>> {
    let c = nb.face(0)[k];
    if has_semi_sharpness(nb, c) {
        return Ok(None);
    }
    let samples = limit_vertex_samples(&nb.to_mesh(options, positions), options)?;
    let s = samples[c as usize];
    Ok(Some(LimitSample {
        position: s.position,
        du: s.du * scale,
        dv: s.dv * scale,
    }))
}
