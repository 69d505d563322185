//! Interpolating fit: control points whose limit surface passes through given data points.
//!
//! The limit position of every control vertex is a fixed linear combination of the control
//! points (its limit stencil row, which depends only on topology and sharpness), so asking
//! each vertex's limit to equal its data point is the square sparse system `A X = D`, with
//! `A` the limit stencil matrix (non-symmetric, well conditioned on meshes of mostly regular
//! vertices). It is solved with `faer`: first by BiCGSTAB with a Jacobi preconditioner (a
//! few dozen sparse products), and if that does not reach the tolerance, by sparse LU with
//! partial pivoting followed by iterative refinement. The achieved residual is measured on
//! the stencil rows themselves and reported.
//!
//! [`cage`]: the constructions' shared entry point, which tags a cage with its subdivision
//! options and fits it under them.

pub mod cage;

pub use cage::{fit_cage, FitOptions, FittedCage};

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::solvers::Solve;
use faer::matrix_free::bicgstab::{bicgstab, bicgstab_scratch, BicgParams};
use faer::matrix_free::IdentityPrecond;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Col, Mat, Par};
use glam::DVec3;

use crate::error::{Error, Result};
use crate::eval::{limit_stencils, StencilTable};
use crate::mesh::Mesh;
use crate::options::SubdivOptions;

/// Relative tolerance of [`fit_limit`]: residual ≤ this × the data points' bounding-box
/// diagonal.
pub const RELATIVE_TOLERANCE: f64 = 1e-10;

/// A square sparse matrix in compressed rows: row `i` has weights `weights[offsets[i]..
/// offsets[i+1]]` on columns `indices[..]` (the layout of a limit stencil table).
#[derive(Debug, Clone, Copy)]
pub struct CsrRef<'a> {
    /// Row starts, `n + 1` entries.
    pub offsets: &'a [u32],
    /// Column of each weight.
    pub indices: &'a [u32],
    /// The weights.
    pub weights: &'a [f64],
}

/// How well a fit met its data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitReport {
    /// Largest distance between a vertex's limit position and its data point.
    pub residual: f64,
    /// The tolerance the residual had to meet.
    pub tolerance: f64,
    /// How the system was solved.
    pub method: SolveMethod,
    /// BiCGSTAB iterations, or LU refinement steps after the first solve.
    pub iterations: usize,
}

/// The solver that produced a fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolveMethod {
    /// Preconditioned BiCGSTAB reached the tolerance.
    BiCgStab,
    /// Sparse LU with iterative refinement (after BiCGSTAB did not converge).
    SparseLu,
}

/// BiCGSTAB stops at this fraction of the tolerance.
const KRYLOV_MARGIN: f64 = 1e-3;

/// Most BiCGSTAB iterations before falling back to LU.
const MAX_KRYLOV_ITERATIONS: usize = 500;

/// Most refinement steps before giving up.
const MAX_REFINEMENTS: usize = 8;

impl CsrRef<'_> {
    fn rows(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// `A x` for points.
    pub fn apply(&self, x: &[DVec3]) -> Vec<DVec3> {
        (0..self.rows())
            .map(|i| {
                let (a, b) = (self.offsets[i] as usize, self.offsets[i + 1] as usize);
                self.indices[a..b]
                    .iter()
                    .zip(&self.weights[a..b])
                    .map(|(&j, &w)| x[j as usize] * w)
                    .sum()
            })
            .collect()
    }

    fn check(&self, n: usize) -> Result<()> {
        let nnz = self.indices.len();
        let ok = self.offsets.len() == n + 1
            && self.weights.len() == nnz
            && self.offsets[0] == 0
            && self.offsets[n] as usize == nnz
            && self.offsets.windows(2).all(|w| w[0] <= w[1])
            && self.indices.iter().all(|&j| (j as usize) < n)
            && self.weights.iter().all(|w| w.is_finite());
        if ok {
            Ok(())
        } else {
            Err(Error::invalid_argument(format!(
                "the stencil matrix is not a valid {n} × {n} compressed-row matrix"
            )))
        }
    }
}

/// Largest Euclidean norm of `d[i] - (A x)[i]`.
pub fn residual(a: CsrRef<'_>, x: &[DVec3], d: &[DVec3]) -> f64 {
    a.apply(x)
        .iter()
        .zip(d)
        .map(|(ax, d)| (*d - *ax).length())
        .fold(0.0, f64::max)
}

/// Solve `A X = D` to a residual `≤ tolerance` (largest point distance).
///
/// Errors: [`Error::InvalidArgument`] for a malformed matrix or mismatched sizes;
/// [`Error::NumericalFailure`] if `A` is singular or the residual stays above the tolerance.
pub fn solve(a: CsrRef<'_>, d: &[DVec3], tolerance: f64) -> Result<(Vec<DVec3>, FitReport)> {
    let n = d.len();
    a.check(n)?;
    if n == 0 {
        return Err(Error::invalid_argument("nothing to fit: no data points"));
    }
    let mut triplets = Vec::with_capacity(a.indices.len());
    for i in 0..n {
        for k in a.offsets[i] as usize..a.offsets[i + 1] as usize {
            triplets.push(Triplet::new(i as u32, a.indices[k], a.weights[k]));
        }
    }
    let matrix = SparseColMat::<u32, f64>::try_new_from_triplets(n, n, &triplets)
        .map_err(|e| Error::NumericalFailure(format!("building the sparse matrix: {e:?}")))?;
    if let Some((x, iterations)) = krylov(&matrix, a, d, tolerance) {
        let r = residual(a, &x, d);
        if r <= tolerance {
            let method = SolveMethod::BiCgStab;
            return Ok((
                x,
                FitReport {
                    residual: r,
                    tolerance,
                    method,
                    iterations,
                },
            ));
        }
    }
    let lu = matrix.sp_lu().map_err(|e| {
        Error::NumericalFailure(format!("the limit stencil matrix is singular: {e:?}"))
    })?;
    let solve_points = |rhs: &[DVec3]| -> Vec<DVec3> {
        let mut m = Mat::<f64>::from_fn(n, 3, |i, j| rhs[i][j]);
        lu.solve_in_place(m.as_mut());
        (0..n)
            .map(|i| DVec3::new(m[(i, 0)], m[(i, 1)], m[(i, 2)]))
            .collect()
    };
    let mut x = solve_points(d);
    let mut r = residual(a, &x, d);
    let mut refinements = 0;
    while r > tolerance && refinements < MAX_REFINEMENTS && r.is_finite() {
        let ax = a.apply(&x);
        let rhs: Vec<DVec3> = d.iter().zip(&ax).map(|(d, ax)| *d - *ax).collect();
        let dx = solve_points(&rhs);
        let candidate: Vec<DVec3> = x.iter().zip(&dx).map(|(x, dx)| *x + *dx).collect();
        let rc = residual(a, &candidate, d);
        refinements += 1;
        if rc.is_nan() || rc >= r {
            break;
        }
        x = candidate;
        r = rc;
    }
    if r.is_nan() || r > tolerance {
        return Err(Error::NumericalFailure(format!(
            "interpolating fit reached residual {r:e}, above the tolerance {tolerance:e}"
        )));
    }
    Ok((
        x,
        FitReport {
            residual: r,
            tolerance,
            method: SolveMethod::SparseLu,
            iterations: refinements,
        },
    ))
}

/// BiCGSTAB on the three coordinate columns at once, right-preconditioned by the inverse
/// diagonal; `None` if it does not converge (or a diagonal entry vanishes).
fn krylov(
    matrix: &SparseColMat<u32, f64>,
    a: CsrRef<'_>,
    d: &[DVec3],
    tolerance: f64,
) -> Option<(Vec<DVec3>, usize)> {
    let n = d.len();
    let mut diag = vec![0.0; n];
    for (i, di) in diag.iter_mut().enumerate() {
        for k in a.offsets[i] as usize..a.offsets[i + 1] as usize {
            if a.indices[k] as usize == i {
                *di += a.weights[k];
            }
        }
    }
    if diag.iter().any(|&x| x.abs() < 1e-12) {
        return None;
    }
    let jacobi = Col::<f64>::from_fn(n, |i| 1.0 / diag[i]).into_diagonal();
    let identity = IdentityPrecond { dim: n };
    let mut mem = MemBuffer::new(bicgstab_scratch(&identity, &jacobi, matrix, 1, Par::Seq));
    // The zero start is passed as a guess (`MaybeNonZero`, the default): faer 0.24 leaves
    // the residual unset with `InitialGuessStatus::Zero`. Each coordinate's residual norm
    // bounds its rows' residuals; aim well below the tolerance (a few more iterations) so
    // that the fit has margin for other evaluators.
    let params = BicgParams::<f64> {
        abs_tolerance: KRYLOV_MARGIN * tolerance,
        rel_tolerance: 0.0,
        max_iters: MAX_KRYLOV_ITERATIONS,
        ..Default::default()
    };
    let mut out = Mat::<f64>::zeros(n, 3);
    let mut iterations = 0;
    for j in [0usize, 1, 2] {
        let rhs = Mat::<f64>::from_fn(n, 1, |i, _| d[i][j]);
        let info = bicgstab(
            out.as_mut().subcols_mut(j, 1),
            &identity,
            &jacobi,
            matrix,
            rhs.as_ref(),
            params,
            |_| {},
            Par::Seq,
            MemStack::new(&mut mem),
        );
        iterations = iterations.max(info.ok()?.iter_count);
    }
    let x = (0..n)
        .map(|i| DVec3::new(out[(i, 0)], out[(i, 1)], out[(i, 2)]))
        .collect();
    Some((x, iterations))
}

impl<'a> From<&'a StencilTable> for CsrRef<'a> {
    fn from(t: &'a StencilTable) -> Self {
        CsrRef {
            offsets: &t.offsets,
            indices: &t.indices,
            weights: &t.weights,
        }
    }
}

/// Move the control points of `mesh` so that the exact limit position of vertex `i` (under
/// `options`, with the mesh's creases and corners) is `targets[i]`, to a residual ≤
/// [`RELATIVE_TOLERANCE`] × the targets' bounding-box diagonal. Topology and tags are kept.
///
/// Errors: [`Error::InvalidArgument`] if the target count differs from the vertex count;
/// [`Error::NumericalFailure`] if the stencil matrix is singular or the tolerance is missed
/// (a vertex without limit surface has an empty stencil row, so a mesh with one is singular:
/// [`cage::check_limit_exists`] names such vertices first).
pub fn fit_limit(
    mesh: &Mesh,
    options: &SubdivOptions,
    targets: &[DVec3],
) -> Result<(Mesh, FitReport)> {
    if targets.len() != mesh.num_vertices() {
        return Err(Error::invalid_argument(format!(
            "{} targets for a mesh of {} vertices",
            targets.len(),
            mesh.num_vertices()
        )));
    }
    let table = limit_stencils(mesh, options)?;
    let (lo, hi) = targets.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let tolerance = RELATIVE_TOLERANCE * (hi - lo).length().max(f64::MIN_POSITIVE);
    let (x, report) = solve((&table).into(), targets, tolerance)?;
    let mut parts = mesh.parts().clone();
    parts.positions = x;
    Ok((Mesh::from_parts(parts)?, report))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The limit mask of a closed ring of cubic B-spline points (1/6, 4/6, 1/6), plus one
    /// identity row: non-trivial, well conditioned, with a known answer.
    #[test]
    fn solves_a_bspline_limit_system_to_the_tolerance() {
        let n = 50usize;
        let (mut offsets, mut indices, mut weights) = (vec![0u32], vec![], vec![]);
        for i in 0..n {
            if i == 0 {
                indices.push(0);
                weights.push(1.0);
            } else {
                for (j, w) in [
                    ((i + n - 1) % n, 1.0 / 6.0),
                    (i, 4.0 / 6.0),
                    ((i + 1) % n, 1.0 / 6.0),
                ] {
                    indices.push(j as u32);
                    weights.push(w);
                }
            }
            offsets.push(indices.len() as u32);
        }
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        let truth: Vec<DVec3> = (0..n)
            .map(|i| {
                let t = i as f64 * 0.3;
                DVec3::new(t.cos(), t.sin(), t * t)
            })
            .collect();
        let d = a.apply(&truth);
        let (x, report) = solve(a, &d, 1e-12).unwrap();
        assert!(report.residual <= 1e-12);
        assert_eq!(report.method, SolveMethod::BiCgStab);
        for (x, t) in x.iter().zip(&truth) {
            assert!((*x - *t).length() < 1e-10);
        }
    }

    #[test]
    fn falls_back_to_lu_when_the_diagonal_vanishes() {
        // A permutation with a scaled row: no usable Jacobi preconditioner.
        let offsets = [0u32, 1, 2, 3];
        let indices = [1u32, 2, 0];
        let weights = [1.0, 2.0, 0.5];
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        let d = [DVec3::X, DVec3::Y, DVec3::Z];
        let (x, report) = solve(a, &d, 1e-14).unwrap();
        assert_eq!(report.method, SolveMethod::SparseLu);
        assert_eq!(x, vec![DVec3::Z * 2.0, DVec3::X, DVec3::Y * 0.5]);
    }

    #[test]
    fn reports_singular_and_malformed_systems() {
        let offsets = [0u32, 1, 2];
        let indices = [0u32, 0];
        let weights = [1.0, 1.0];
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        let d = [DVec3::ONE, DVec3::ZERO];
        assert!(matches!(
            solve(a, &d, 1e-10),
            Err(Error::NumericalFailure(_))
        ));
        let bad = [0u32, 5];
        let b = CsrRef { offsets: &bad, ..a };
        assert!(matches!(
            solve(b, &d[..1], 1e-10),
            Err(Error::InvalidArgument(_))
        ));
    }
}
