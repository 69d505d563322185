//! Fitting a freshly built cage under chosen subdivision options: what the profile, revolve
//! and sweep constructions share.
//!
//! The constructions build quads whose vertices sit at their data points; [`fit_cage`] tags
//! the mesh with the options it is fitted under (so an OBJ reader evaluates it the same way:
//! `t interpolateboundary`, `t creasemethod`) and moves the control points so that the exact
//! limit under those options passes through every data point.

use glam::DVec3;

use super::{fit_limit, FitReport, Role};
use crate::control::Control;
use crate::error::{Error, Result};
use crate::eval::vertices_with_surface;
use crate::mesh::{Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, CreaseMethod, PartialOptions, SubdivOptions};

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
/// `control` is polled at each stage: mesh check 0–5 %, limit check 5–10 %, then
/// [`fit_limit`].
///
/// Errors: those of [`Mesh::from_parts`] and [`fit_limit`]; [`Error::InvalidArgument`] when
/// boundary interpolation *none* leaves vertices without a limit surface (see
/// [`check_limit_exists`]).
///
/// `roles` (empty, or one per vertex): vertices that keep their position as control point
/// or are faired instead of interpolated ([`fit_limit`]); their limit positions become
/// their data points.
pub fn fit_cage(
    mut parts: MeshParts,
    options: FitOptions,
    roles: &[Role],
    control: &Control,
) -> Result<FittedCage> {
    control.report(0.0)?;
    parts.options = options.tags();
    let cage = Mesh::from_parts(parts)?;
    control.report(0.05)?;
    let resolved = options.resolve();
    check_limit_exists(&cage, &resolved)?;
    // The check above is one evaluation per vertex: a poll between it and the fit.
    control.report(0.08)?;
    let (mesh, targets, fit) = fit_limit(
        &cage,
        &resolved,
        cage.positions(),
        roles,
        &control.stage(0.1, 1.0),
    )?;
    Ok(FittedCage { mesh, targets, fit })
}

/// [`vertices_with_surface`] without building a refinement level where no face can be a
/// hole (none tagged, boundary interpolation other than *none*): then a vertex has a surface
/// exactly when a face uses it.
fn surface_vertices(mesh: &Mesh, options: &SubdivOptions) -> Vec<bool> {
    if !mesh.holes().is_empty() || options.boundary == BoundaryInterpolation::None {
        return vertices_with_surface(mesh, options);
    }
    let mut used = vec![false; mesh.num_vertices()];
    for &v in mesh.face_indices() {
        used[v as usize] = true;
    }
    used
}

/// Whether every vertex of `mesh` lies on the limit surface under `options`: a vertex without
/// limit surface ([`crate::eval::surface`]) cannot interpolate anything. That happens under
/// boundary interpolation *none* (OpenSubdiv makes the faces at an open boundary holes) and
/// would otherwise give a fit to a limit that no evaluator shows.
///
/// Errors: [`Error::InvalidArgument`] naming the first such vertex, its data point and the
/// remedies.
pub fn check_limit_exists(mesh: &Mesh, options: &SubdivOptions) -> Result<()> {
    let without: Vec<usize> = surface_vertices(mesh, options)
        .iter()
        .enumerate()
        .filter(|(_, &has)| !has)
        .map(|(v, _)| v)
        .collect();
    let Some(&first) = without.first() else {
        return Ok(());
    };
    let p = mesh.positions()[first];
    let cause = if options.boundary == BoundaryInterpolation::None {
        "boundary interpolation none makes the faces at an open boundary holes, as \
         OpenSubdiv does"
    } else {
        "they are isolated, or all their faces are holes"
    };
    Err(Error::invalid_argument(format!(
        "cannot interpolate the data points of {} (the first: vertex {first} at \
         ({}, {}, {})): no limit surface passes through them ({cause}); use boundary \
         edge-only or edge-and-corner, or close the surface (flat caps, poles, a full turn, \
         closed curves)",
        match without.len() {
            1 => "1 vertex".to_string(),
            n => format!("{n} vertices"),
        },
        p.x,
        p.y,
        p.z
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math;

    /// The level-free surface test gives the level's answer: an isolated vertex, with and
    /// without a hole, under every boundary rule.
    #[test]
    fn surface_vertices_without_a_level_agree_with_the_level() {
        for holes in [vec![], vec![4]] {
            let mut parts = grid(3, holes);
            parts.positions.push(DVec3::splat(9.0));
            let mesh = Mesh::from_parts(parts).unwrap();
            for boundary in BoundaryInterpolation::ALL {
                let options = SubdivOptions {
                    boundary,
                    ..Default::default()
                };
                let quick = surface_vertices(&mesh, &options);
                assert_eq!(quick, vertices_with_surface(&mesh, &options));
                assert!(!quick[16], "{boundary:?}");
            }
        }
    }

    /// A wavy `n × n` grid of quads; `holes` tagged.
    fn grid(n: u32, holes: Vec<u32>) -> MeshParts {
        let idx = |i: u32, j: u32| i * (n + 1) + j;
        let mut parts = MeshParts {
            positions: (0..=n)
                .flat_map(|i| (0..=n).map(move |j| (i, j)))
                .map(|(i, j)| DVec3::new(i as f64, j as f64, math::sin((i * j) as f64 * 0.7)))
                .collect(),
            holes,
            ..Default::default()
        };
        for i in 0..n {
            for j in 0..n {
                parts.face_sizes.push(4);
                parts.face_indices.extend([
                    idx(i, j),
                    idx(i + 1, j),
                    idx(i + 1, j + 1),
                    idx(i, j + 1),
                ]);
            }
        }
        parts
    }

    fn message(r: Result<FittedCage>) -> String {
        match r {
            Err(Error::InvalidArgument(m)) => m,
            other => panic!("expected InvalidArgument, got {other:?}"),
        }
    }

    #[test]
    fn fits_and_tags_under_the_given_options() {
        for boundary in [
            BoundaryInterpolation::EdgeOnly,
            BoundaryInterpolation::EdgeAndCorner,
        ] {
            let options = FitOptions::new(boundary, CreaseMethod::Chaikin);
            let fitted = fit_cage(grid(4, vec![]), options, &[], &Control::NONE).unwrap();
            assert_eq!(fitted.mesh.options(), options.tags());
            assert_eq!(fitted.targets, grid(4, vec![]).positions);
            let limits = crate::eval::limit_stencils(&fitted.mesh, &options.resolve())
                .unwrap()
                .apply(fitted.mesh.positions())
                .unwrap();
            for (l, t) in limits.iter().zip(&fitted.targets) {
                assert!((*l - *t).length() <= fitted.fit.tolerance);
            }
        }
    }

    #[test]
    fn refuses_vertices_without_a_limit_surface() {
        // Boundary none: the 12 border faces are holes, so the 16 border vertices have no
        // surface; the 9 interior vertices keep the 4 inner faces.
        let none = FitOptions::new(BoundaryInterpolation::None, CreaseMethod::Uniform);
        let m = message(fit_cage(grid(4, vec![]), none, &[], &Control::NONE));
        assert!(
            m.contains("of 16 vertices (the first: vertex 0 at (0, 0, 0))"),
            "{m}"
        );
        assert!(
            m.contains("boundary interpolation none makes the faces"),
            "{m}"
        );
        // A tagged hole takes the surface from the corner vertex it alone holds.
        let m = message(fit_cage(
            grid(4, vec![0]),
            FitOptions::default(),
            &[],
            &Control::NONE,
        ));
        assert!(
            m.contains("of 1 vertex (") && m.contains("all their faces are holes"),
            "{m}"
        );
        assert!(fit_cage(grid(4, vec![5]), FitOptions::default(), &[], &Control::NONE).is_ok());
    }
}
