//! Where the limit surface exists: which faces and control vertices have one.
//!
//! OpenSubdiv's rule, which profsubd follows:
//! - a **face** has no limit surface when it is a hole: tagged as one, or, under boundary
//!   interpolation *none*, a face at a boundary (or non-manifold) vertex with a boundary edge
//!   not tagged infinitely sharp. Far's `PatchTable` has no patch for it and
//!   `Bfr::SurfaceFactory::InitVertexSurface` declines it;
//! - a **control vertex** has a limit position when at least one of its faces has a limit
//!   surface (the surface of that face passes through the vertex's limit). A vertex with no
//!   face (an isolated vertex) or whose faces are all holes has none. Non-manifold vertices
//!   (bow-ties, vertices on edges of three or more faces) have a surface like any other;
//!   their limit is the one Bfr gives at the vertex's corner of each of its faces.
//!
//! The APIs mark a point without surface instead of inventing a position:
//! [`LimitSample::NO_SURFACE`](super::LimitSample::NO_SURFACE) (all NaN) in arrays of samples,
//! `None` where they return `Option`s, an empty row in a [`StencilTable`](super::StencilTable)
//! (which [`StencilTable::apply`](super::StencilTable::apply) turns into NaN).

use crate::error::{Error, Result};
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use crate::topology::Level;

use super::sample::LimitSample;

/// Whether each control vertex of `mesh` has a limit position under `options` (see the
/// module doc for the rule), in vertex order.
pub fn vertices_with_surface(mesh: &Mesh, options: &SubdivOptions) -> Vec<bool> {
    vertices_with_surface_in(&Level::from_mesh_with_options(mesh, options))
}

/// [`vertices_with_surface`] on a level already built.
pub(crate) fn vertices_with_surface_in(level: &Level) -> Vec<bool> {
    (0..level.num_vertices())
        .map(|v| {
            level
                .vertex_faces(v)
                .iter()
                .any(|&f| !level.is_face_hole(f as usize))
        })
        .collect()
}

/// Strict mode for results that mark points without surface: the samples themselves, or
/// [`Error::InvalidArgument`] naming the first point (`what` and its index) that has none.
pub fn require_surface(samples: Vec<Option<LimitSample>>, what: &str) -> Result<Vec<LimitSample>> {
    if let Some(i) = samples.iter().position(Option::is_none) {
        return Err(no_surface_strict(what, i));
    }
    Ok(samples.into_iter().flatten().collect())
}

/// The strict-mode error of `what` number `i` without limit surface.
pub(crate) fn no_surface_strict(what: &str, i: usize) -> Error {
    Error::invalid_argument(format!("{what} {i} has no limit surface (strict mode)"))
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::mesh::MeshParts;
    use crate::options::BoundaryInterpolation;

    /// A 3 x 1 strip of quads (vertices 0-7) and an isolated vertex 8.
    fn strip(holes: Vec<u32>) -> Mesh {
        let mut positions: Vec<DVec3> = (0..8)
            .map(|k| DVec3::new((k % 4) as f64, (k / 4) as f64, 0.0))
            .collect();
        positions.push(DVec3::splat(5.0));
        Mesh::from_parts(MeshParts {
            positions,
            face_sizes: vec![4; 3],
            face_indices: vec![0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6],
            holes,
            ..Default::default()
        })
        .unwrap()
    }

    #[test]
    fn isolated_vertices_and_vertices_of_holes_only_have_no_surface() {
        let all = vertices_with_surface(&strip(vec![]), &SubdivOptions::default());
        assert_eq!(all, [true, true, true, true, true, true, true, true, false]);
        let holed = vertices_with_surface(&strip(vec![0, 2]), &SubdivOptions::default());
        assert_eq!(
            holed,
            [false, true, true, false, false, true, true, false, false]
        );
        // Boundary "none": every face touches a soft boundary, so nothing has a surface.
        let none = SubdivOptions {
            boundary: BoundaryInterpolation::None,
            ..SubdivOptions::default()
        };
        assert!(vertices_with_surface(&strip(vec![]), &none)
            .iter()
            .all(|&s| !s));
    }

    #[test]
    fn strict_mode_names_the_first_point_without_surface() {
        let s = LimitSample::default();
        assert_eq!(
            require_surface(vec![Some(s), Some(s)], "point").unwrap(),
            vec![s, s]
        );
        let e = require_surface(vec![Some(s), None, None], "vertex").unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid argument: vertex 1 has no limit surface (strict mode)"
        );
    }
}
