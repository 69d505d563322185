//! Fitting a freshly built cage under chosen subdivision options: what the profile, revolve
//! and sweep constructions share.
//!
//! The constructions build quads whose vertices sit at their data points; [`fit_cage`] tags
//! the mesh with the options it is fitted under (so an OBJ reader evaluates it the same way:
//! `t interpolateboundary`, `t creasemethod`) and moves the control points so that the exact
//! limit under those options passes through every data point.

use glam::DVec3;

use super::{fit_limit, FitReport};
use crate::error::{Error, Result};
use crate::mesh::{Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, CreaseMethod, PartialOptions, SubdivOptions};
use crate::topology::Level;

/// The subdivision options a construction is fitted under. The triangle rule does not apply:
/// the constructions make quads only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FitOptions {
    /// Boundary interpolation (default edge-and-corner).
    pub boundary: BoundaryInterpolation,
    /// Crease method (default uniform).
    pub crease_method: CreaseMethod,
}

impl FitOptions {
    /// The options from their two settings.
    pub fn new(boundary: BoundaryInterpolation, crease_method: CreaseMethod) -> FitOptions {
        FitOptions {
            boundary,
            crease_method,
        }
    }

    /// The option tags the fitted mesh carries: boundary and crease method set, the
    /// triangle rule left unset.
    pub fn tags(self) -> PartialOptions {
        PartialOptions {
            boundary: Some(self.boundary),
            crease_method: Some(self.crease_method),
            triangles: None,
        }
    }

    /// The resolved options the fit evaluates the limit with.
    pub fn resolve(self) -> SubdivOptions {
        self.tags().resolve()
    }
}

/// A fitted cage: the control mesh and the data point each vertex's limit passes through.
#[derive(Debug, Clone, PartialEq)]
pub struct FittedCage {
    /// The control mesh (fitted positions, the cage's tags, `options` as option tags).
    pub mesh: Mesh,
    /// The data point of each vertex, in vertex order.
    pub targets: Vec<DVec3>,
    /// How well the fit met the data.
    pub fit: FitReport,
}

/// Fit `parts` (each vertex at its data point) under `options`: the exact limit position of
/// every vertex, with the cage's creases and corners and these options, is its data point
/// (to [`super::RELATIVE_TOLERANCE`] × their diagonal). The mesh is tagged with `options`.
///
/// Errors: those of [`Mesh::from_parts`] and [`fit_limit`]; [`Error::InvalidArgument`] when
/// boundary interpolation *none* leaves vertices without a limit surface (see
/// [`check_limit_exists`]).
pub fn fit_cage(mut parts: MeshParts, options: FitOptions) -> Result<FittedCage> {
    parts.options = options.tags();
    let cage = Mesh::from_parts(parts)?;
    let resolved = options.resolve();
    check_limit_exists(&cage, &resolved)?;
    let targets = cage.positions().to_vec();
    let (mesh, fit) = fit_limit(&cage, &resolved, &targets)?;
    Ok(FittedCage { mesh, targets, fit })
}

/// Whether every vertex of `mesh` lies on the limit surface under `options`: a vertex all of
/// whose faces have no limit surface cannot interpolate anything. That happens under
/// boundary interpolation *none* (OpenSubdiv makes the faces at an open boundary holes) and
/// would otherwise give a fit to a limit that no evaluator shows.
///
/// Errors: [`Error::InvalidArgument`] naming the first such vertex, its data point and the
/// remedies.
pub fn check_limit_exists(mesh: &Mesh, options: &SubdivOptions) -> Result<()> {
    let level = Level::from_mesh_with_options(mesh, options);
    let without: Vec<usize> = (0..mesh.num_vertices())
        .filter(|&v| {
            let faces = level.vertex_faces(v);
            !faces.is_empty() && faces.iter().all(|&f| level.is_face_hole(f as usize))
        })
        .collect();
    let Some(&first) = without.first() else {
        return Ok(());
    };
    let p = mesh.positions()[first];
    let cause = if options.boundary == BoundaryInterpolation::None {
        "boundary interpolation none makes the faces at an open boundary holes, as \
         OpenSubdiv does"
    } else {
        "all their faces are holes"
    };
    Err(Error::invalid_argument(format!(
        "cannot interpolate the data points of {} vertices (the first: vertex {first} at \
         ({}, {}, {})): no limit surface passes through them ({cause}); use boundary \
         edge-only or edge-and-corner, or close the surface (flat caps, poles, a full turn, \
         closed curves)",
        without.len(),
        p.x,
        p.y,
        p.z
    )))
}
