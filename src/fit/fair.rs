//! Fair data points: where only some vertices of a quad mesh carry data, place the others so
//! that the points minimize a discrete thin-plate (bending) energy, then fit as usual.
//!
//! The mesh lies over a plane: each vertex has a position `q_v` in it (for sketch curves, the
//! Coons map of the projected boundary). The energy is the thin-plate energy of the surface
//! as a function over that plane, `E = ∫ |ΔS|² dA ≈ Σ_v A_v |Δ_h S(v)|²` over the interior
//! vertices, `Δ_h` a finite-difference Laplacian in the plane from the vertex's ring (every
//! vertex of its faces): the weights of least norm that are exact for every quadratic
//! function of `q` (so exact for the planar parts of the points, which are linear in `q`),
//! `A_v` the squared mean ring distance. Applied to the limit positions of the control
//! vertices (the fit makes them these points) it is the discrete `∫ |ΔS|²` of the limit
//! surface. `∫ |ΔS|²` and the thin-plate `∫ S_xx² + 2 S_xy² + S_yy²` differ by a null
//! Lagrangian: their minimizers solve the same biharmonic equation inside; at a boundary
//! where only positions are given, the Laplacian form's natural condition is `ΔS = 0`, so
//! harmonic height fields (planes, the saddle `z = x² − y²`) are reproduced exactly from
//! their boundaries, which the thin-plate form's `S_nn = 0` does not do. The in-plane parts
//! of the minimizer are the `q_v` themselves (linear, zero energy): the fair surface is a
//! height field over the plane, the heights minimizing the energy.
//!
//! Minimizing over the free vertices with the others fixed is the sparse symmetric
//! positive-definite system `H_ff δ_f = −(Lᵀ L y₀)_f` (`y = y₀ + δ`, `y₀` the caller's
//! starting points: solving for the correction keeps the rounding relative to how far `y₀`
//! is from fair, so exactly planar data stay planar to rounding). It is factored by a banded
//! Cholesky decomposition after a reverse Cuthill–McKee ordering: plain scalar loops in a
//! fixed order, the same bits on every CPU, like the fit's solvers ([`super::solve`]).
//! The limit surface through the result is then [`super::fit_limit`]'s.

use std::collections::{BTreeMap, BTreeSet};

use glam::{DVec2, DVec3};

use crate::control::Control;
use crate::error::{Error, Result};

/// One row of the energy operator: `(vertex, weight)` pairs.
pub type EnergyRow = Vec<(u32, f64)>;

/// The energy rows of the quad mesh `faces` whose vertices lie at `plane` positions: one row
/// per interior vertex (every edge around it shared by two faces), in vertex order, `√A_v`
/// times its quadratic-exact Laplacian (module documentation).
///
/// Errors: [`Error::NumericalFailure`] if a vertex's ring determines no such Laplacian (its
/// ring's positions on one conic, e.g. all on a line).
pub fn laplacian_rows(faces: &[[u32; 4]], plane: &[DVec2]) -> Result<Vec<EnergyRow>> {
    let n = plane.len();
    let mut ring: Vec<BTreeSet<u32>> = vec![BTreeSet::new(); n];
    let mut edge_faces: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    for f in faces {
        for k in 0..4 {
            let (a, b) = (f[k], f[(k + 1) % 4]);
            *edge_faces.entry((a.min(b), a.max(b))).or_default() += 1;
            for &w in f {
                if w != f[k] {
                    ring[f[k] as usize].insert(w);
                }
            }
        }
    }
    let mut on_boundary = vec![false; n];
    for (&(a, b), &count) in &edge_faces {
        if count == 1 {
            on_boundary[a as usize] = true;
            on_boundary[b as usize] = true;
        }
    }
    let mut rows = Vec::new();
    for v in (0..n).filter(|&v| !on_boundary[v] && !ring[v].is_empty()) {
        let offsets: Vec<DVec2> = ring[v]
            .iter()
            .map(|&w| plane[w as usize] - plane[v])
            .collect();
        let r = offsets.iter().map(|d| d.length()).sum::<f64>() / offsets.len() as f64;
        let weights = quadratic_laplacian(&offsets, r).ok_or_else(|| {
            Error::NumericalFailure(format!(
                "fair points: the ring of vertex {v} determines no Laplacian (its neighbours' \
                 plane positions are degenerate)"
            ))
        })?;
        // Row = r × (weights for unit-scaled offsets) / r²: √A_v times the Laplacian.
        let total: f64 = weights.iter().sum();
        let mut row: EnergyRow = vec![(v as u32, -total / r)];
        row.extend(ring[v].iter().zip(&weights).map(|(&w, &c)| (w, c / r)));
        rows.push(row);
    }
    Ok(rows)
}

/// Weights `w` of least norm with `Σ w_k f(d_k / r) = Δf(0)` for every quadratic `f` with
/// `f(0) = 0` (the five conditions on `x, y, x², xy, y²`); `None` if they are dependent.
fn quadratic_laplacian(offsets: &[DVec2], r: f64) -> Option<Vec<f64>> {
    let basis = |d: DVec2| {
        let d = d / r;
        [d.x, d.y, d.x * d.x, d.x * d.y, d.y * d.y]
    };
    let rows: Vec<[f64; 5]> = offsets.iter().map(|&d| basis(d)).collect();
    // w = Mᵀ (M Mᵀ)⁻¹ b, with M's columns the offsets' basis values.
    let mut g = [[0.0; 6]; 5];
    for (i, gi) in g.iter_mut().enumerate() {
        for j in 0..5 {
            gi[j] = rows.iter().map(|b| b[i] * b[j]).sum();
        }
    }
    for (i, gi) in g.iter_mut().enumerate() {
        gi[5] = [0.0, 0.0, 2.0, 0.0, 2.0][i];
    }
    let scale = (0..5).map(|i| g[i][i]).fold(0.0, f64::max);
    for k in 0..5 {
        let p = (k..5).max_by(|&a, &b| g[a][k].abs().total_cmp(&g[b][k].abs()))?;
        let pivot = g[p][k].abs();
        if pivot.is_nan() || pivot <= 1e-12 * scale {
            return None;
        }
        g.swap(k, p);
        let top = g[k];
        for row in g.iter_mut().skip(k + 1) {
            let l = row[k] / top[k];
            for (x, y) in row[k..].iter_mut().zip(&top[k..]) {
                *x -= l * y;
            }
        }
    }
    let mut lambda = [0.0; 5];
    for i in (0..5).rev() {
        let mut sum = g[i][5];
        for j in i + 1..5 {
            sum -= g[i][j] * lambda[j];
        }
        lambda[i] = sum / g[i][i];
    }
    Some(
        rows.iter()
            .map(|b| (0..5).map(|i| b[i] * lambda[i]).sum())
            .collect(),
    )
}

/// Estimated bytes of [`minimize`] for `free` unknowns of a band `band` wide.
fn band_bytes(free: usize, band: usize) -> u64 {
    8 * free as u64 * (band as u64 + 1)
}

/// The points minimizing `Σ_rows |Σ_k w_k y_k|²` with the vertices flagged in `fixed` kept at
/// `start` (the module documentation); the free vertices start from `start` too (only the
/// rounding depends on it). `control` is polled at every column of the factorization and its
/// memory budget checked before the band is allocated.
///
/// Errors: [`Error::InvalidArgument`] for mismatched sizes or a row naming a missing vertex;
/// [`Error::NumericalFailure`] if the energy does not determine some free vertex (a free
/// vertex in no row, or a group of free vertices the rows leave undetermined);
/// [`Error::Cancelled`], [`Error::LimitExceeded`] from `control`.
pub fn minimize(
    rows: &[EnergyRow],
    fixed: &[bool],
    start: &[DVec3],
    control: &Control,
) -> Result<Vec<DVec3>> {
    let n = start.len();
    if fixed.len() != n || rows.iter().flatten().any(|&(v, _)| v as usize >= n) {
        return Err(Error::invalid_argument(format!(
            "fair points: {} fixed flags and energy rows for {n} vertices",
            fixed.len()
        )));
    }
    // Free vertices numbered in their order, then re-ordered to a narrow band.
    let mut index = vec![usize::MAX; n];
    let free: Vec<usize> = (0..n).filter(|&v| !fixed[v]).collect();
    for (k, &v) in free.iter().enumerate() {
        index[v] = k;
    }
    let m = free.len();
    if m == 0 {
        return Ok(start.to_vec());
    }
    let mut graph: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); m];
    for row in rows {
        for &(a, _) in row {
            for &(b, _) in row {
                let (a, b) = (index[a as usize], index[b as usize]);
                if a != usize::MAX && b != usize::MAX && a != b {
                    graph[a].insert(b);
                }
            }
        }
    }
    let order = reverse_cuthill_mckee(&graph);
    let mut position = vec![0usize; m];
    for (p, &k) in order.iter().enumerate() {
        position[k] = p;
    }
    let band = (0..m)
        .flat_map(|a| graph[a].iter().map(move |&b| (a, b)))
        .map(|(a, b)| position[a].abs_diff(position[b]))
        .max()
        .unwrap_or(0);
    control.check_memory(
        &format!("the banded factor of {m} fair points (band {band})"),
        band_bytes(m, band),
    )?;
    // Lower band: entry (i, j), j ≤ i, at i * (band + 1) + (band − (i − j)).
    let width = band + 1;
    let mut h = vec![0.0; m * width];
    let mut rhs = vec![DVec3::ZERO; m];
    for row in rows {
        let residual: DVec3 = row.iter().map(|&(v, w)| start[v as usize] * w).sum();
        for &(a, wa) in row {
            let ia = index[a as usize];
            if ia == usize::MAX {
                continue;
            }
            let pa = position[ia];
            rhs[pa] -= residual * wa;
            for &(b, wb) in row {
                let ib = index[b as usize];
                if ib == usize::MAX {
                    continue;
                }
                let pb = position[ib];
                if pb <= pa {
                    h[pa * width + band - (pa - pb)] += wa * wb;
                }
            }
        }
    }
    cholesky_band(&mut h, m, band, control)?;
    let delta = solve_band(&h, m, band, rhs);
    let mut out = start.to_vec();
    for (k, &v) in free.iter().enumerate() {
        out[v] += delta[position[k]];
    }
    Ok(out)
}

/// Reverse Cuthill–McKee ordering of a symmetric graph (each component from a vertex of
/// least degree, neighbours by increasing degree then index): `order[p]` is the vertex put at
/// position `p`.
fn reverse_cuthill_mckee(graph: &[BTreeSet<usize>]) -> Vec<usize> {
    let m = graph.len();
    let mut seen = vec![false; m];
    let mut order = Vec::with_capacity(m);
    let mut by_degree: Vec<usize> = (0..m).collect();
    by_degree.sort_by_key(|&v| (graph[v].len(), v));
    for &root in &by_degree {
        if seen[root] {
            continue;
        }
        seen[root] = true;
        let mut head = order.len();
        order.push(root);
        while head < order.len() {
            let v = order[head];
            head += 1;
            let mut next: Vec<usize> = graph[v].iter().copied().filter(|&w| !seen[w]).collect();
            next.sort_by_key(|&w| (graph[w].len(), w));
            for w in next {
                seen[w] = true;
                order.push(w);
            }
        }
    }
    order.reverse();
    order
}

/// In-place Cholesky `H = G Gᵀ` of the lower band (layout of [`minimize`]).
fn cholesky_band(h: &mut [f64], m: usize, band: usize, control: &Control) -> Result<()> {
    let width = band + 1;
    // Scale of the diagonal, to tell a vanishing pivot from a small one.
    let scale = (0..m).map(|i| h[i * width + band]).fold(0.0, f64::max);
    for i in 0..m {
        control.step(i, m)?;
        let first = i.saturating_sub(band);
        for j in first..=i {
            // (G Gᵀ)_ij over k < j: G_ik G_jk.
            let mut sum = h[i * width + band - (i - j)];
            let lo = first.max(j.saturating_sub(band));
            for k in lo..j {
                sum -= h[i * width + band - (i - k)] * h[j * width + band - (j - k)];
            }
            if j < i {
                h[i * width + band - (i - j)] = sum / h[j * width + band];
            } else {
                if sum.is_nan() || sum <= 1e-13 * scale {
                    return Err(Error::NumericalFailure(format!(
                        "fair points: the bending energy does not determine free point {i} of \
                         {m} (pivot {sum:e}): free vertices without data around them"
                    )));
                }
                h[i * width + band] = sum.sqrt();
            }
        }
    }
    control.report(1.0)
}

/// `H⁻¹ rhs` from the band factor of [`cholesky_band`].
fn solve_band(g: &[f64], m: usize, band: usize, mut x: Vec<DVec3>) -> Vec<DVec3> {
    let width = band + 1;
    for i in 0..m {
        let mut sum = x[i];
        for k in i.saturating_sub(band)..i {
            sum -= x[k] * g[i * width + band - (i - k)];
        }
        x[i] = sum / g[i * width + band];
    }
    for i in (0..m).rev() {
        let mut sum = x[i];
        for k in i + 1..(i + band + 1).min(m) {
            sum -= x[k] * g[k * width + band - (k - i)];
        }
        x[i] = sum / g[i * width + band];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An `n × n` grid of quads on `(n + 1)²` vertices, row by row.
    fn grid(n: usize) -> Vec<[u32; 4]> {
        let id = |i: usize, j: usize| (j * (n + 1) + i) as u32;
        (0..n)
            .flat_map(|j| {
                (0..n).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
            })
            .collect()
    }

    #[test]
    fn reproduces_a_harmonic_saddle_from_its_boundary() {
        // z = x² − y² is harmonic and quadratic: the stencils give it zero energy, so the
        // minimizer from its boundary values alone is the saddle itself at every vertex.
        let n = 12;
        let faces = grid(n);
        let warp = |t: f64| t + 0.2 * t * (1.0 - t);
        let at = |v: usize| {
            let (x, y) = (
                warp((v % (n + 1)) as f64 / n as f64),
                warp((v / (n + 1)) as f64 / n as f64),
            );
            DVec3::new(x, y, x * x - y * y)
        };
        let count = (n + 1) * (n + 1);
        let fixed: Vec<bool> = (0..count)
            .map(|v| v % (n + 1) == 0 || v % (n + 1) == n || v / (n + 1) == 0 || v / (n + 1) == n)
            .collect();
        let start: Vec<DVec3> = (0..count)
            .map(|v| {
                if fixed[v] {
                    at(v)
                } else {
                    DVec3::new(0.3, -0.2, 5.0)
                }
            })
            .collect();
        // Columns and rows spaced unevenly: a tensor grid of the plane.
        let plane: Vec<DVec2> = (0..count)
            .map(|v| {
                DVec2::new(
                    warp((v % (n + 1)) as f64 / n as f64),
                    warp((v / (n + 1)) as f64 / n as f64),
                )
            })
            .collect();
        let rows = laplacian_rows(&faces, &plane).unwrap();
        assert_eq!(rows.len(), (n - 1) * (n - 1));
        let y = minimize(&rows, &fixed, &start, &Control::NONE).unwrap();
        let worst = (0..count)
            .map(|v| (y[v] - at(v)).length())
            .fold(0.0, f64::max);
        assert!(worst < 1e-12, "{worst:e}");
    }

    #[test]
    fn a_free_vertex_in_no_row_is_refused() {
        // Two quads side by side: no interior vertex, so no row reaches the free vertex 1.
        let faces = [[0, 1, 4, 3], [1, 2, 5, 4]];
        let plane: Vec<DVec2> = (0..6)
            .map(|v| DVec2::new((v % 3) as f64, (v / 3) as f64))
            .collect();
        let rows = laplacian_rows(&faces, &plane).unwrap();
        assert!(rows.is_empty());
        let mut fixed = vec![true; 6];
        fixed[1] = false;
        match minimize(&rows, &fixed, &[DVec3::ZERO; 6], &Control::NONE) {
            Err(Error::NumericalFailure(m)) => assert!(m.contains("does not determine"), "{m}"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn orders_a_grid_to_a_band_of_about_one_row() {
        let n = 10;
        let faces = grid(n);
        let count = (n + 1) * (n + 1);
        let plane: Vec<DVec2> = (0..count)
            .map(|v| DVec2::new((v % (n + 1)) as f64, (v / (n + 1)) as f64))
            .collect();
        let rows = laplacian_rows(&faces, &plane).unwrap();
        let mut graph: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); count];
        for row in &rows {
            for &(a, _) in row {
                for &(b, _) in row {
                    if a != b {
                        graph[a as usize].insert(b as usize);
                    }
                }
            }
        }
        let order = reverse_cuthill_mckee(&graph);
        let mut sorted = order.clone();
        sorted.sort();
        assert_eq!(sorted, (0..count).collect::<Vec<_>>());
        let mut pos = vec![0; count];
        for (p, &v) in order.iter().enumerate() {
            pos[v] = p;
        }
        let band = (0..count)
            .flat_map(|a| graph[a].iter().map(move |&b| (a, b)))
            .map(|(a, b)| pos[a].abs_diff(pos[b]))
            .max()
            .unwrap();
        // A row couples vertices two grid rows apart: at most ~4 rows' width.
        assert!(band <= 4 * (n + 1), "{band}");
    }
}
