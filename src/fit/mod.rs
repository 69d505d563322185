//! Interpolating fit: control points whose limit surface passes through given data points.
//!
//! The limit position of every control vertex is a fixed linear combination of the control
//! points (its limit stencil row, which depends only on topology and sharpness), so asking
//! each vertex's limit to equal its data point is the square sparse system `A X = D`, with
//! `A` the limit stencil matrix (non-symmetric, well conditioned on meshes of mostly regular
//! vertices). It is solved first by BiCGSTAB with a Jacobi preconditioner (a few dozen sparse
//! products), and if that does not reach the tolerance, by dense LU with partial pivoting
//! followed by iterative refinement (small systems only). The achieved residual is measured
//! on the stencil rows themselves and reported. Both solvers are plain scalar loops in a
//! fixed order, so a fit gives the same bits on every CPU: a library with runtime-dispatched
//! SIMD kernels (faer's, through pulp, which this module used before) rounds differently on
//! machines with and without AVX2/FMA.
//!
//! [`cage`]: the constructions' shared entry point, which tags a cage with its subdivision
//! options and fits it under them.

pub mod cage;
pub mod fair;

pub use cage::{fit_cage, FitOptions, FittedCage};

use glam::DVec3;

use crate::control::Control;
use crate::error::{Error, Result};
use crate::eval::vertex_limit::limit_stencils_with;
use crate::eval::StencilTable;
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
    /// Condition estimate of the fit: how much a relative change of the data points (to
    /// their bounding-box diagonal) can grow relative to the smallest distance between two
    /// neighbouring data points, `κ × diagonal / smallest spacing`, with `κ` the stencil
    /// matrix's amplification measured on this solve (the fit computes it). Fits above
    /// [`MAX_CONDITION`] are refused.
    pub condition: f64,
}

/// Largest accepted [`FitReport::condition`]: above it, the fit's tolerance
/// (1e-10 × the diagonal, amplified) would exceed 1 % of the smallest
/// spacing between neighbouring data points, so nearly coincident samples could not be told
/// apart.
pub const MAX_CONDITION: f64 = 1e-2 / RELATIVE_TOLERANCE;

/// The solver that produced a fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SolveMethod {
    /// Preconditioned BiCGSTAB reached the tolerance.
    BiCgStab,
    /// Dense LU with partial pivoting and iterative refinement (after BiCGSTAB did not
    /// converge, on systems of at most [`DENSE_LU_MAX_ROWS`] rows).
    DenseLu,
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
/// The result is a deterministic function of the input on every machine: both solvers are
/// plain scalar loops in a fixed order (no runtime-dispatched SIMD, no parallel reduction, no
/// fused multiply-add), so the same bits come out on any x86_64 or aarch64 CPU.
///
/// `control` is polled at every BiCGSTAB iteration (0–60 %) and every LU column (60–100 %);
/// its memory budget is checked before the dense LU allocates.
///
/// Errors: [`Error::InvalidArgument`] for a malformed matrix or mismatched sizes;
/// [`Error::NumericalFailure`] if `A` is singular, if BiCGSTAB does not converge on a system
/// larger than [`DENSE_LU_MAX_ROWS`], or if the residual stays above the tolerance;
/// [`Error::Cancelled`] and [`Error::LimitExceeded`] from `control`. The report's
/// `condition` is left at 1 (see [`fit_limit`]).
pub fn solve(
    a: CsrRef<'_>,
    d: &[DVec3],
    tolerance: f64,
    control: &Control,
) -> Result<(Vec<DVec3>, FitReport)> {
    let n = d.len();
    a.check(n)?;
    if n == 0 {
        return Err(Error::invalid_argument("nothing to fit: no data points"));
    }
    if let Some((x, iterations)) = krylov(a, d, tolerance, &control.stage(0.0, 0.6))? {
        let r = residual(a, &x, d);
        if r <= tolerance {
            let method = SolveMethod::BiCgStab;
            control.report(1.0)?;
            return Ok((
                x,
                FitReport {
                    residual: r,
                    tolerance,
                    method,
                    iterations,
                    condition: 1.0,
                },
            ));
        }
    }
    if n > DENSE_LU_MAX_ROWS {
        return Err(Error::NumericalFailure(format!(
            "BiCGSTAB did not reach the tolerance on the {n} × {n} limit stencil system, and \
             the dense LU fallback is limited to {DENSE_LU_MAX_ROWS} rows"
        )));
    }
    control.check_memory(
        &format!("the dense LU of the {n} × {n} stencil matrix"),
        (n * n * 8) as u64,
    )?;
    let lu = DenseLu::factor(a, &control.stage(0.6, 1.0))?.ok_or_else(|| {
        Error::NumericalFailure("the limit stencil matrix is singular".to_string())
    })?;
    let mut x = lu.solve(d);
    let mut r = residual(a, &x, d);
    let mut refinements = 0;
    while r > tolerance && refinements < MAX_REFINEMENTS && r.is_finite() {
        let ax = a.apply(&x);
        let rhs: Vec<DVec3> = d.iter().zip(&ax).map(|(d, ax)| *d - *ax).collect();
        let dx = lu.solve(&rhs);
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
    control.report(1.0)?;
    Ok((
        x,
        FitReport {
            residual: r,
            tolerance,
            method: SolveMethod::DenseLu,
            iterations: refinements,
            condition: 1.0,
        },
    ))
}

/// Largest system the dense LU fallback factors (2048² doubles = 32 MiB).
pub const DENSE_LU_MAX_ROWS: usize = 2048;

/// `A x` for one coordinate column, rows summed in stored order.
fn apply_scalar(a: CsrRef<'_>, x: &[f64], out: &mut [f64]) {
    for (i, o) in out.iter_mut().enumerate() {
        let (s, e) = (a.offsets[i] as usize, a.offsets[i + 1] as usize);
        let mut sum = 0.0;
        for k in s..e {
            sum += a.weights[k] * x[a.indices[k] as usize];
        }
        *o = sum;
    }
}

/// Sequential dot product (a fixed summation order, unlike a SIMD reduction).
fn dot(u: &[f64], v: &[f64]) -> f64 {
    let mut sum = 0.0;
    for (a, b) in u.iter().zip(v) {
        sum += a * b;
    }
    sum
}

/// BiCGSTAB on each coordinate column, right-preconditioned by the inverse diagonal, from a
/// zero start; `None` if it does not converge (or a diagonal entry vanishes, or it breaks
/// down). Each coordinate stops when its residual's Euclidean norm, which bounds its rows'
/// residuals, is below a margin of the tolerance (a few more iterations, so that the fit has
/// margin for other evaluators). Each coordinate fills a third of `control`.
fn krylov(
    a: CsrRef<'_>,
    d: &[DVec3],
    tolerance: f64,
    control: &Control,
) -> Result<Option<(Vec<DVec3>, usize)>> {
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
        return Ok(None);
    }
    let inv_diag: Vec<f64> = diag.iter().map(|d| 1.0 / d).collect();
    let stop = KRYLOV_MARGIN * tolerance;
    let mut out = vec![DVec3::ZERO; n];
    let mut iterations = 0;
    for j in [0usize, 1, 2] {
        let b: Vec<f64> = d.iter().map(|p| p[j]).collect();
        let third = control.stage(j as f64 / 3.0, (j + 1) as f64 / 3.0);
        let Some((x, its)) = bicgstab_column(a, &inv_diag, &b, stop, &third)? else {
            return Ok(None);
        };
        iterations = iterations.max(its);
        for (o, x) in out.iter_mut().zip(x) {
            o[j] = x;
        }
    }
    Ok(Some((out, iterations)))
}

/// One column of [`krylov`]: `x` with `‖b − A x‖₂ < stop`, and the iteration count
/// (`None`: no convergence). Progress is the residual's decrease on a log scale from
/// `‖b‖` to `stop`, never going back.
fn bicgstab_column(
    a: CsrRef<'_>,
    inv_diag: &[f64],
    b: &[f64],
    stop: f64,
    control: &Control,
) -> Result<Option<(Vec<f64>, usize)>> {
    let n = b.len();
    let mut x = vec![0.0; n];
    let mut r = b.to_vec();
    let start = dot(&r, &r).sqrt();
    control.report(0.0)?;
    if start < stop {
        return Ok(Some((x, 0)));
    }
    let mut done = 0.0f64;
    let mut progress = |norm: f64| {
        let f = crate::math::ln(start / norm) / crate::math::ln(start / stop);
        if f.is_finite() {
            done = done.max(f);
        }
        control.report(done)
    };
    let r_hat = r.clone();
    let (mut rho, mut alpha, mut omega) = (1.0, 1.0, 1.0);
    let (mut p, mut v) = (vec![0.0; n], vec![0.0; n]);
    let (mut y, mut z, mut s, mut t) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for it in 1..=MAX_KRYLOV_ITERATIONS {
        let rho_next = dot(&r_hat, &r);
        if rho_next == 0.0 || !rho_next.is_finite() {
            return Ok(None);
        }
        let beta = (rho_next / rho) * (alpha / omega);
        rho = rho_next;
        for i in 0..n {
            p[i] = r[i] + beta * (p[i] - omega * v[i]);
            y[i] = inv_diag[i] * p[i];
        }
        apply_scalar(a, &y, &mut v);
        let rv = dot(&r_hat, &v);
        if rv == 0.0 || !rv.is_finite() {
            return Ok(None);
        }
        alpha = rho / rv;
        for i in 0..n {
            x[i] += alpha * y[i];
            s[i] = r[i] - alpha * v[i];
        }
        if dot(&s, &s).sqrt() < stop {
            return Ok(Some((x, it)));
        }
        for i in 0..n {
            z[i] = inv_diag[i] * s[i];
        }
        apply_scalar(a, &z, &mut t);
        let tt = dot(&t, &t);
        if tt == 0.0 || !tt.is_finite() {
            return Ok(None);
        }
        omega = dot(&t, &s) / tt;
        if omega == 0.0 {
            return Ok(None);
        }
        for i in 0..n {
            x[i] += omega * z[i];
            r[i] = s[i] - omega * t[i];
        }
        let norm = dot(&r, &r).sqrt();
        if norm < stop {
            return Ok(Some((x, it)));
        }
        progress(norm)?;
    }
    Ok(None)
}

/// LU factors with partial pivoting of a small dense copy of `A` (row-major), for systems
/// BiCGSTAB does not solve: scalar loops in a fixed order, like [`krylov`].
struct DenseLu {
    n: usize,
    /// `L` below the diagonal (unit diagonal implied) and `U` on and above it.
    lu: Vec<f64>,
    /// Row `k` of the factors is row `perm[k]` of `A`.
    perm: Vec<usize>,
}

impl DenseLu {
    /// `None` if a pivot column is exactly zero (a singular matrix). Each column is a step
    /// of `control` (the work per column falls as `(n − k)²`).
    fn factor(a: CsrRef<'_>, control: &Control) -> Result<Option<Self>> {
        let n = a.rows();
        let mut lu = vec![0.0; n * n];
        for i in 0..n {
            for k in a.offsets[i] as usize..a.offsets[i + 1] as usize {
                lu[i * n + a.indices[k] as usize] += a.weights[k];
            }
        }
        let mut perm: Vec<usize> = (0..n).collect();
        let total = (n * n * n) as f64;
        for k in 0..n {
            let left = (n - k) as f64;
            control.report(1.0 - left * left * left / total)?;
            // The first row of largest magnitude: ties broken by position, deterministically.
            let mut best = k;
            for i in k + 1..n {
                if lu[i * n + k].abs() > lu[best * n + k].abs() {
                    best = i;
                }
            }
            let pivot = lu[best * n + k];
            if pivot == 0.0 || !pivot.is_finite() {
                return Ok(None);
            }
            if best != k {
                for j in 0..n {
                    lu.swap(k * n + j, best * n + j);
                }
                perm.swap(k, best);
            }
            let (upper, lower) = lu.split_at_mut((k + 1) * n);
            let row_k = &upper[k * n..];
            for row in lower.chunks_exact_mut(n) {
                let l = row[k] / pivot;
                row[k] = l;
                if l != 0.0 {
                    for j in k + 1..n {
                        row[j] -= l * row_k[j];
                    }
                }
            }
        }
        Ok(Some(DenseLu { n, lu, perm }))
    }

    /// `A⁻¹ rhs` for points.
    fn solve(&self, rhs: &[DVec3]) -> Vec<DVec3> {
        let n = self.n;
        let mut x: Vec<DVec3> = self.perm.iter().map(|&i| rhs[i]).collect();
        for i in 0..n {
            let row = &self.lu[i * n..i * n + i];
            let mut sum = x[i];
            for (xj, l) in x[..i].iter().zip(row) {
                sum -= *xj * *l;
            }
            x[i] = sum;
        }
        for i in (0..n).rev() {
            let row = &self.lu[i * n + i + 1..(i + 1) * n];
            let mut sum = x[i];
            for (xj, u) in x[i + 1..].iter().zip(row) {
                sum -= *xj * *u;
            }
            x[i] = sum / self.lu[i * n + i];
        }
        x
    }
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
/// [`RELATIVE_TOLERANCE`] × the targets' bounding-box diagonal; except that a vertex with
/// `fixed[i]` (`fixed` empty: none) keeps `targets[i]` as its control point (its row of the
/// system is the identity), where the data leave the surface free (a flat cap's inside).
/// Topology and tags are kept. Returns the fitted mesh, every vertex's limit position (the
/// targets, with the fixed vertices' limits in their place) and the report.
///
/// The report's condition estimate ([`FitReport::condition`]) is `κ × diagonal / spacing`:
/// `spacing` the smallest distance between the targets of two vertices joined by an edge,
/// `κ = ‖A‖∞ × max|x − c| / max|d − c|` (`c` the targets' box centre; the limit stencil rows
/// sum to 1, so centring makes it independent of translation) — the amplification this
/// solve showed, a lower estimate of the stencil matrix's condition number. Everything in
/// it is a ratio of lengths, unchanged by translation, rotation and uniform scaling.
///
/// `control` is polled while the stencils are built (0–30 %) and while solving (30–100 %),
/// and its memory budget checked before the stencils are built.
///
/// Errors: [`Error::InvalidArgument`] if the target count differs from the vertex count;
/// [`Error::NumericalFailure`] if the stencil matrix is singular or the tolerance is missed
/// (a vertex without limit surface has an empty stencil row, so a mesh with one is singular:
/// [`cage::check_limit_exists`] names such vertices first), or if the condition estimate is
/// above [`MAX_CONDITION`] (nearly coincident targets: checked on the spacing before solving,
/// then with `κ`); [`Error::Cancelled`], [`Error::LimitExceeded`] from `control`.
pub fn fit_limit(
    mesh: &Mesh,
    options: &SubdivOptions,
    targets: &[DVec3],
    fixed: &[bool],
    control: &Control,
) -> Result<(Mesh, Vec<DVec3>, FitReport)> {
    if targets.len() != mesh.num_vertices() || !(fixed.is_empty() || fixed.len() == targets.len()) {
        return Err(Error::invalid_argument(format!(
            "{} targets ({} fixed flags) for a mesh of {} vertices",
            targets.len(),
            fixed.len(),
            mesh.num_vertices()
        )));
    }
    control.check_memory(
        &format!("the fit of {} vertices", mesh.num_vertices()),
        fit_bytes(mesh.num_vertices(), mesh.face_indices().len()),
    )?;
    let (lo, hi) = targets.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    let diagonal = (hi - lo).length().max(f64::MIN_POSITIVE);
    let (spacing, pair) = smallest_spacing(mesh, targets);
    let geometric = diagonal / spacing;
    let refuse = |condition: f64| {
        Error::NumericalFailure(format!(
            "ill-conditioned fit: condition estimate {condition:.3e} above {MAX_CONDITION:e} \
             (the data points of vertices {} and {} are {spacing:e} apart, {:.3e} of the \
             model's size): nearly coincident samples or a nearly degenerate profile; \
             remove repeated points or use fewer samples",
            pair.0,
            pair.1,
            spacing / diagonal
        ))
    };
    if geometric.is_nan() || geometric > MAX_CONDITION {
        return Err(refuse(geometric));
    }
    let limit = limit_stencils_with(mesh, options, &control.stage(0.0, 0.3))?;
    // A fixed vertex's row is the identity: it keeps its position as control point.
    let is_fixed = |i: usize| fixed.get(i).copied().unwrap_or(false);
    let mut system = StencilTable::new();
    for i in 0..targets.len() {
        let (a, b) = (limit.offsets[i] as usize, limit.offsets[i + 1] as usize);
        if is_fixed(i) {
            system.indices.push(i as u32);
            system.weights.push(1.0);
        } else {
            system.indices.extend_from_slice(&limit.indices[a..b]);
            system.weights.extend_from_slice(&limit.weights[a..b]);
        }
        system.offsets.push(system.indices.len() as u32);
    }
    let tolerance = RELATIVE_TOLERANCE * diagonal;
    let a: CsrRef<'_> = (&system).into();
    let (x, mut report) = solve(a, targets, tolerance, &control.stage(0.3, 1.0))?;
    let centre = (lo + hi) * 0.5;
    let spread = |p: &[DVec3]| p.iter().map(|p| (*p - centre).length()).fold(0.0, f64::max);
    let norm = (0..a.rows())
        .map(|i| {
            a.weights[a.offsets[i] as usize..a.offsets[i + 1] as usize]
                .iter()
                .map(|w| w.abs())
                .sum::<f64>()
        })
        .fold(0.0, f64::max);
    let kappa = (norm * spread(&x) / spread(targets).max(f64::MIN_POSITIVE)).max(1.0);
    report.condition = kappa * geometric;
    if report.condition.is_nan() || report.condition > MAX_CONDITION {
        return Err(refuse(report.condition));
    }
    let limits = CsrRef::from(&limit).apply(&x);
    let reached = (0..targets.len())
        .map(|i| if is_fixed(i) { limits[i] } else { targets[i] })
        .collect();
    let mut parts = mesh.parts().clone();
    parts.positions = x;
    Ok((Mesh::from_parts(parts)?, reached, report))
}

/// Estimated bytes a fit of `vertices` vertices and `face_indices` face-vertex indices
/// allocates before any dense fallback: the refinement level (about 40 bytes per index),
/// the limit stencils (a row of about 1 + 2 × valence entries of 12 bytes per vertex) and
/// BiCGSTAB's ten vectors, the fitted mesh and its targets (about 130 bytes per vertex).
pub fn fit_bytes(vertices: usize, face_indices: usize) -> u64 {
    64 * face_indices as u64 + 160 * vertices as u64
}

/// The smallest distance between the targets of two vertices joined by an edge of `mesh`,
/// and the two vertices (`f64::INFINITY` for a mesh without edges).
fn smallest_spacing(mesh: &Mesh, targets: &[DVec3]) -> (f64, (u32, u32)) {
    let mut best = (f64::INFINITY, (0, 0));
    let mut start = 0;
    for &size in mesh.face_sizes() {
        let face = &mesh.face_indices()[start..start + size as usize];
        for (k, &a) in face.iter().enumerate() {
            let b = face[(k + 1) % face.len()];
            let d = (targets[a as usize] - targets[b as usize]).length();
            if d < best.0 {
                best = (d, (a.min(b), a.max(b)));
            }
        }
        start += size as usize;
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math;

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
                DVec3::new(math::cos(t), math::sin(t), t * t)
            })
            .collect();
        let d = a.apply(&truth);
        let (x, report) = solve(a, &d, 1e-12, &Control::NONE).unwrap();
        assert!(report.residual <= 1e-12);
        assert_eq!(report.method, SolveMethod::BiCgStab);
        for (x, t) in x.iter().zip(&truth) {
            assert!((*x - *t).length() < 1e-10);
        }
    }

    #[test]
    fn falls_back_to_dense_lu_when_the_diagonal_vanishes() {
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
        let (x, report) = solve(a, &d, 1e-14, &Control::NONE).unwrap();
        assert_eq!(report.method, SolveMethod::DenseLu);
        assert_eq!(x, vec![DVec3::Z * 2.0, DVec3::X, DVec3::Y * 0.5]);
    }

    #[test]
    fn refuses_the_dense_fallback_above_its_size_limit() {
        // A cyclic shift: zero diagonal (no Jacobi preconditioner), one row too many for LU.
        let n = DENSE_LU_MAX_ROWS + 1;
        let offsets: Vec<u32> = (0..=n as u32).collect();
        let indices: Vec<u32> = (0..n as u32).map(|i| (i + 1) % n as u32).collect();
        let weights = vec![1.0; n];
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        match solve(a, &vec![DVec3::ONE; n], 1e-10, &Control::NONE) {
            Err(Error::NumericalFailure(m)) => assert!(m.contains("limited to 2048 rows"), "{m}"),
            other => panic!("{other:?}"),
        }
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
            solve(a, &d, 1e-10, &Control::NONE),
            Err(Error::NumericalFailure(_))
        ));
        let bad = [0u32, 5];
        let b = CsrRef { offsets: &bad, ..a };
        assert!(matches!(
            solve(b, &d[..1], 1e-10, &Control::NONE),
            Err(Error::InvalidArgument(_))
        ));
    }
}
