//! Interpolating fit: control points whose limit surface passes through given data points.
//!
//! The limit position of every control vertex is a fixed linear combination of the control
//! points (its limit stencil row, which depends only on topology and sharpness), so asking
//! each vertex's limit to equal its data point is the square sparse system `A X = D`, with
//! `A` the limit stencil matrix (non-symmetric, well conditioned on meshes of mostly regular
//! vertices). [`fit_limit`] solves it for the control points' offsets from the data points,
//! first by BiCGSTAB preconditioned by incomplete LU factors on the matrix's own pattern
//! (`ilu`: two or three iterations on a profile cage; the inverse diagonal, which needed a few
//! dozen, where they cannot be formed or do not converge), and if that does not reach the
//! tolerance, by dense LU with partial pivoting
//! followed by iterative refinement (small systems only). The achieved residual is measured
//! on the stencil rows themselves and reported. Both solvers are plain scalar loops in a
//! fixed order, so a fit gives the same bits on every CPU: a library with runtime-dispatched
//! SIMD kernels (faer's, through pulp, which this module used before) rounds differently on
//! machines with and without AVX2/FMA.
//!
//! The fit runs on [`Control::threads`] threads (default all cores: the limit stencils by
//! ranges of vertices, BiCGSTAB's three coordinate columns apart) with the result of one
//! thread, bit for bit.
//!
//! [`cage`]: the constructions' shared entry point, which tags a cage with its subdivision
//! options and fits it under them. [`bending`]: the fairness term for vertices without data
//! ([`Role::Fair`]).

pub mod bending;
pub mod cage;
pub mod fair;
mod ilu;

pub use cage::{fit_cage, FitOptions, FittedCage};

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use glam::DVec3;

use crate::control::Control;
use crate::error::{Error, Result};
use crate::eval::parallel::{on_threads, resolve_threads};
use crate::eval::vertex_limit::limit_stencils_with;
use crate::eval::StencilTable;
use crate::mesh::Mesh;
use crate::options::SubdivOptions;
use ilu::Ilu0;

/// Relative tolerance of [`fit_limit`]: residual ≤ this × the data points' bounding-box
/// diagonal.
pub const RELATIVE_TOLERANCE: f64 = 1e-10;

/// What the fit asks of one vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Role {
    /// Its limit position is its data point (the default).
    #[default]
    Interpolate,
    /// It keeps its data point as its control point (a flat cap's inside, whose shape its
    /// creased rim and its plane carry).
    Keep,
    /// No data constrain it: its control point is where the control net's bending energy
    /// is stationary with respect to it ([`bending::Umbrella::energy_row`]), given the
    /// other control points.
    Fair,
}

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

/// BiCGSTAB has converged at this fraction of the tolerance.
const KRYLOV_MARGIN: f64 = 1e-3;

/// Past convergence BiCGSTAB polishes on to this fraction of the margin (rounding level for
/// coordinates of the diagonal's size), for at most [`POLISH_ITERATIONS`] more iterations.
/// Stopping at the margin left the solution's error (up to κ × the margin) to depend on the
/// data's position and orientation, since a zero start is not translation-invariant:
/// translated or rotated inputs differed by up to 8.5e-13 of the model's size, 1e-13 after
/// polishing (#17 item 7), measured when [`fit_limit`] still started from zero rather than
/// from the data points.
const POLISH: f64 = 1e-2;

/// Most iterations spent polishing past convergence.
const POLISH_ITERATIONS: usize = 16;

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
/// its memory budget is checked before the dense LU allocates. BiCGSTAB's three coordinate
/// columns run on up to [`Control::threads`] threads: each is the same scalar loop whatever
/// thread runs it, so the result does not depend on the count.
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
    let krylov_stage = control.stage(0.0, 0.6);
    let krylov_result = krylov(a, d, tolerance, control.threads(), &krylov_stage)?;
    // BiCGSTAB's stage ends here whether it converged or not: with ILU(0) it takes two or
    // three iterations, whose own reports may all fall in its first half.
    krylov_stage.report(1.0)?;
    if let Some((x, iterations)) = krylov_result {
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
        // Zipped row slices: one bounds check a row instead of three an entry.
        for (&w, &j) in a.weights[s..e].iter().zip(&a.indices[s..e]) {
            sum += w * x[j as usize];
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

/// BiCGSTAB on each coordinate column, right-preconditioned by incomplete LU factors
/// ([`ilu`]), or by the inverse diagonal where they cannot be formed or do not converge,
/// from a zero start; `None` if it does not converge (or a diagonal entry vanishes, or it
/// breaks down). Each coordinate stops when its residual's Euclidean norm, which bounds its rows'
/// residuals, is below a margin of the tolerance (a few more iterations, so that the fit has
/// margin for other evaluators). Column `j` runs on thread `j mod threads` (0: all cores, at
/// most 3); the calling thread's columns fill `control` in equal parts, and a cancel there
/// stops the other threads at their next iteration.
fn krylov(
    a: CsrRef<'_>,
    d: &[DVec3],
    tolerance: f64,
    threads: usize,
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
    let stop = KRYLOV_MARGIN * tolerance;
    // ILU(0) first; the diagonal if it cannot be factored or does not converge (the rest of
    // the progress range).
    let jacobi_control = match Ilu0::new(a) {
        Some(ilu) => {
            let pre = Preconditioner::Ilu(ilu);
            if let Some(x) = krylov_with(a, d, stop, &pre, threads, &control.stage(0.0, 0.5))? {
                return Ok(Some(x));
            }
            control.stage(0.5, 1.0)
        }
        None => control.stage(0.0, 1.0),
    };
    let pre = Preconditioner::Jacobi(diag.iter().map(|d| 1.0 / d).collect());
    krylov_with(a, d, stop, &pre, threads, &jacobi_control)
}

/// How BiCGSTAB's search directions are preconditioned (on the right).
enum Preconditioner<'a> {
    /// The inverse diagonal.
    Jacobi(Vec<f64>),
    /// Incomplete LU factors on the matrix's pattern.
    Ilu(Ilu0<'a>),
}

impl Preconditioner<'_> {
    /// `out = M⁻¹ r`.
    fn apply(&self, r: &[f64], out: &mut [f64]) {
        match self {
            Preconditioner::Jacobi(inv_diag) => {
                for ((o, r), d) in out.iter_mut().zip(r).zip(inv_diag) {
                    *o = d * r;
                }
            }
            Preconditioner::Ilu(f) => f.solve(r, out),
        }
    }
}

/// [`krylov`] with preconditioner `pre`: its three columns on `threads` threads.
fn krylov_with(
    a: CsrRef<'_>,
    d: &[DVec3],
    stop: f64,
    pre: &Preconditioner<'_>,
    threads: usize,
    control: &Control,
) -> Result<Option<(Vec<DVec3>, usize)>> {
    let n = d.len();
    let threads = resolve_threads(threads).min(3);
    let cancelled = Arc::new(AtomicBool::new(false));
    let flag = cancelled.clone();
    let poll = Control::NONE.with_progress(move |_| flag.load(Ordering::Relaxed));
    // The columns of thread `t`, in order, until one fails or does not converge.
    let run = |t: usize| {
        let columns: Vec<usize> = (t..3).step_by(threads).collect();
        let mut out = Vec::new();
        for (k, &j) in columns.iter().enumerate() {
            let share = columns.len() as f64;
            let own = control.stage(k as f64 / share, (k + 1) as f64 / share);
            let b: Vec<f64> = d.iter().map(|p| p[j]).collect();
            let result = bicgstab_column(
                a,
                pre,
                &b,
                stop,
                stop * POLISH,
                if t == 0 { &own } else { &poll },
            );
            let stopped = !matches!(result, Ok(Some(_)));
            if t == 0 && result.is_err() {
                cancelled.store(true, Ordering::Relaxed);
            }
            out.push((j, result));
            if stopped {
                break;
            }
        }
        out
    };
    let mut columns: Vec<_> = on_threads(threads, run).into_iter().flatten().collect();
    columns.sort_by_key(|(j, _)| *j);
    let mut out = vec![DVec3::ZERO; n];
    let mut iterations = 0;
    // In column order, as one thread would stop: the first failure or non-convergence.
    for j in 0..3 {
        let Some((x, its)) = columns
            .iter_mut()
            .find(|(c, _)| *c == j)
            .map(|(_, r)| std::mem::replace(r, Ok(None)))
            .transpose()?
            .flatten()
        else {
            return Ok(None);
        };
        iterations = iterations.max(its);
        for (o, x) in out.iter_mut().zip(x) {
            o[j] = x;
        }
    }
    Ok(Some((out, iterations)))
}

/// One column of [`krylov`]: `x` with `‖b − A x‖₂ < stop` (recurrence residual), polished
/// on towards `polish` ([`POLISH`]), and the iteration count (`None`: no convergence to
/// `stop`). Progress is the residual's decrease on a log scale from `‖b‖` to `stop`, never
/// going back.
fn bicgstab_column(
    a: CsrRef<'_>,
    pre: &Preconditioner<'_>,
    b: &[f64],
    stop: f64,
    polish: f64,
    control: &Control,
) -> Result<Option<(Vec<f64>, usize)>> {
    let n = b.len();
    let mut x = vec![0.0; n];
    let mut r = b.to_vec();
    let start = dot(&r, &r).sqrt();
    control.report(0.0)?;
    if start < polish {
        return Ok(Some((x, 0)));
    }
    let mut done = 0.0f64;
    let mut progress = |norm: f64| {
        let f = crate::math::ln(start / norm) / crate::math::ln(start / stop);
        if f.is_finite() {
            done = done.max(f).min(1.0);
        }
        control.report(done)
    };
    // The latest iterate within `stop` and its iteration: the answer if polishing breaks
    // down or runs out of iterations.
    let mut converged: Option<(Vec<f64>, usize)> = (start < stop).then(|| (x.clone(), 0));
    let mut since = 0;
    let r_hat = r.clone();
    let (mut rho, mut alpha, mut omega) = (1.0, 1.0, 1.0);
    let (mut p, mut v) = (vec![0.0; n], vec![0.0; n]);
    let (mut y, mut z, mut s, mut t) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for it in 1..=MAX_KRYLOV_ITERATIONS {
        if converged.is_some() {
            since += 1;
            if since > POLISH_ITERATIONS {
                break;
            }
        }
        let rho_next = dot(&r_hat, &r);
        if rho_next == 0.0 || !rho_next.is_finite() {
            return Ok(converged);
        }
        let beta = (rho_next / rho) * (alpha / omega);
        rho = rho_next;
        for i in 0..n {
            p[i] = r[i] + beta * (p[i] - omega * v[i]);
        }
        pre.apply(&p, &mut y);
        apply_scalar(a, &y, &mut v);
        let rv = dot(&r_hat, &v);
        if rv == 0.0 || !rv.is_finite() {
            return Ok(converged);
        }
        alpha = rho / rv;
        for i in 0..n {
            x[i] += alpha * y[i];
            s[i] = r[i] - alpha * v[i];
        }
        let half = dot(&s, &s).sqrt();
        if half < polish {
            return Ok(Some((x, it)));
        }
        if half < stop {
            converged = Some((x.clone(), it));
        }
        pre.apply(&s, &mut z);
        apply_scalar(a, &z, &mut t);
        let tt = dot(&t, &t);
        if tt == 0.0 || !tt.is_finite() {
            return Ok(converged);
        }
        omega = dot(&t, &s) / tt;
        if omega == 0.0 {
            return Ok(converged);
        }
        for i in 0..n {
            x[i] += omega * z[i];
            r[i] = s[i] - omega * t[i];
        }
        let norm = dot(&r, &r).sqrt();
        if norm < polish {
            return Ok(Some((x, it)));
        }
        if norm < stop {
            converged = Some((x.clone(), it));
        }
        progress(norm)?;
    }
    Ok(converged)
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
/// [`RELATIVE_TOLERANCE`] × the targets' bounding-box diagonal; except where `roles[i]`
/// (`roles` empty: every vertex [`Role::Interpolate`]) says otherwise: a [`Role::Keep`]
/// vertex keeps `targets[i]` as its control point (its row of the system is the identity),
/// where the data leave a flat surface free (a flat cap's inside); a [`Role::Fair`] vertex
/// has no data, and its row is the control net's bending energy made stationary with respect
/// to it ([`bending`]; its target only serves the condition estimate's spacing).
/// Topology and tags are kept. Returns the fitted mesh, every vertex's limit position (the
/// targets, with the kept and faired vertices' limits in their place) and the report.
///
/// The report's condition estimate ([`FitReport::condition`]) is `κ × diagonal / spacing`:
/// `spacing` the smallest distance between the targets of two vertices joined by an edge,
/// `κ = ‖A‖∞ × max|x − c| / max|d − c|` (`c` the targets' box centre; the limit stencil rows
/// sum to 1, so centring makes it independent of translation) — the amplification this
/// solve showed, a lower estimate of the stencil matrix's condition number. Everything in
/// it is a ratio of lengths, unchanged by translation, rotation and uniform scaling.
///
/// `control` is polled after the spacing check, while the stencils are built (0–29 %) and
/// the system assembled (29–30 %) and while solving (30–100 %), and its memory budget
/// checked before the stencils are built.
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
    roles: &[Role],
    control: &Control,
) -> Result<(Mesh, Vec<DVec3>, FitReport)> {
    if targets.len() != mesh.num_vertices() || !(roles.is_empty() || roles.len() == targets.len()) {
        return Err(Error::invalid_argument(format!(
            "{} targets ({} roles) for a mesh of {} vertices",
            targets.len(),
            roles.len(),
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
    // The spacing check above is a pass over every edge: a poll before the stencils.
    control.report(0.0)?;
    let limit = limit_stencils_with(mesh, options, &control.stage(0.0, 0.29))?;
    let role = |i: usize| roles.get(i).copied().unwrap_or_default();
    let umbrella = roles
        .contains(&Role::Fair)
        .then(|| bending::Umbrella::new(mesh));
    let mut system = StencilTable::new();
    let mut rhs = targets.to_vec();
    let assembly = control.stage(0.29, 0.3);
    // With every vertex interpolated the limit stencils are the system: no copy.
    let assembled = roles.iter().any(|&r| r != Role::Interpolate);
    if assembled {
        for (i, rhs) in rhs.iter_mut().enumerate() {
            assembly.step(i, targets.len())?;
            let (a, b) = (limit.offsets[i] as usize, limit.offsets[i + 1] as usize);
            match (role(i), &umbrella) {
                // A kept vertex's row is the identity: it keeps its position as control
                // point.
                (Role::Keep, _) => {
                    system.indices.push(i as u32);
                    system.weights.push(1.0);
                }
                (Role::Fair, Some(u)) => {
                    // The bending energy of the net's offset from the data points (the
                    // design surface's samples): tangentially the control points stay where
                    // the layout put them, and the offset the interpolation needs spreads
                    // smoothly.
                    *rhs = DVec3::ZERO;
                    for (j, w) in u.energy_row(i) {
                        system.indices.push(j);
                        system.weights.push(w);
                        *rhs += targets[j as usize] * w;
                    }
                }
                _ => {
                    system.indices.extend_from_slice(&limit.indices[a..b]);
                    system.weights.extend_from_slice(&limit.weights[a..b]);
                }
            }
            system.offsets.push(system.indices.len() as u32);
        }
    }
    let tolerance = RELATIVE_TOLERANCE * diagonal;
    let a: CsrRef<'_> = if assembled {
        (&system).into()
    } else {
        (&limit).into()
    };
    // Solved for the offset from the data points: the residual starts at the
    // interpolation's small offsets instead of the model's size (fewer iterations, and a
    // start that moves with the data: the stencil rows sum to 1).
    let start = a.apply(targets);
    let offset_rhs: Vec<DVec3> = rhs.iter().zip(&start).map(|(r, s)| *r - *s).collect();
    let (y, mut report) = solve(a, &offset_rhs, tolerance, &control.stage(0.3, 1.0))?;
    let x: Vec<DVec3> = targets.iter().zip(&y).map(|(t, y)| *t + *y).collect();
    report.residual = residual(a, &x, &rhs);
    if report.residual.is_nan() || report.residual > tolerance {
        return Err(Error::NumericalFailure(format!(
            "interpolating fit reached residual {:e}, above the tolerance {tolerance:e}",
            report.residual
        )));
    }
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
        .map(|i| match role(i) {
            Role::Interpolate => targets[i],
            Role::Keep | Role::Fair => limits[i],
        })
        .collect();
    if let Some(i) = x.iter().position(|p| !p.is_finite()) {
        return Err(Error::NumericalFailure(format!(
            "the fit gave vertex {i} a non-finite control point"
        )));
    }
    // Only the positions change: the topology and tags were validated with `mesh`.
    Ok((mesh.with_positions(x), reached, report))
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

    /// A 60 × 60 grid (3,721 vertices: several ranges of limit stencils per thread) with a
    /// wavy height, a semi-sharp crease line, a kept and a faired vertex: the fit and its stencils on
    /// 2, 3 and 7 threads (and all cores) are those of one thread, bit for bit.
    #[test]
    fn the_fit_on_several_threads_is_the_fit_on_one() {
        let n = 60;
        let mut parts =
            crate::test_support::grid(n, |x, y| math::sin(0.3 * x) * math::cos(0.2 * y));
        parts.creases = (0..n as u32)
            .map(|i| crate::mesh::Crease {
                vertices: [30 * (n as u32 + 1) + i, 30 * (n as u32 + 1) + i + 1],
                sharpness: 2.5,
            })
            .collect();
        let mesh = Mesh::from_parts(parts).unwrap();
        let options = SubdivOptions::default();
        let targets = mesh.positions().to_vec();
        let mut roles = vec![Role::Interpolate; targets.len()];
        roles[100] = Role::Keep;
        roles[1500] = Role::Fair;
        let on = |threads: usize| Control::NONE.with_threads(threads);
        let one = fit_limit(&mesh, &options, &targets, &roles, &on(1)).unwrap();
        let stencils = limit_stencils_with(&mesh, &options, &on(1)).unwrap();
        assert!(one.2.residual <= one.2.tolerance && one.0.positions() != mesh.positions());
        for threads in [0, 2, 3, 7] {
            let many = fit_limit(&mesh, &options, &targets, &roles, &on(threads));
            assert_eq!(many.unwrap(), one, "{threads} threads");
            let table = limit_stencils_with(&mesh, &options, &on(threads)).unwrap();
            assert_eq!(table, stencils, "{threads} threads");
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
