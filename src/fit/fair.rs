//! Fair data points: where only some vertices of a quad mesh carry data, place the others so
//! that the points minimize a discrete bending energy, then fit as usual.
//!
//! The energy is `E(y) = Σ_v |L y_v|²` over the mesh's interior vertices, `L` the umbrella
//! Laplacian scaled to a unit grid, `(4/k) Σ_{w ~ v} (y_w − y_v)` for a vertex of valence `k`
//! (at a regular vertex the 5-point Laplacian `y_uu + y_vv` with unit spacing). Applied to the
//! limit positions of the control vertices it is the discrete `∫ |ΔS|²` of the limit surface
//! in the mesh's own parameterization (every quad a unit square). That functional and the
//! thin-plate `∫ |S_uu|² + 2|S_uv|² + |S_vv|²` differ by a null Lagrangian (their minimizers
//! solve the same biharmonic equation inside); at a boundary where only positions are given
//! the Laplacian form's natural condition is `ΔS = 0`, so harmonic surfaces (planes, the
//! saddle `z = x² − y²` on a square grid) are reproduced exactly from their boundaries, which
//! the thin-plate form's `S_nn = 0` does not do.
//!
//! Minimizing over the free vertices with the others fixed is the sparse symmetric
//! positive-definite system `H_ff δ_f = −(Lᵀ L y₀)_f` (`y = y₀ + δ`, `y₀` the caller's
//! starting points: solving for the correction keeps the rounding relative to how far `y₀`
//! is from fair, so exactly planar data stay planar to rounding). It is factored by a banded
//! Cholesky decomposition after a reverse Cuthill–McKee ordering: plain scalar loops in a
//! fixed order, the same bits on every CPU, like the fit's solvers ([`super::solve`]).
//! The limit surface through the result is then [`super::fit_limit`]'s.

use std::collections::BTreeSet;

use glam::DVec3;

use crate::control::Control;
use crate::error::{Error, Result};

/// One row of the energy operator: `(vertex, weight)` pairs.
pub type EnergyRow = Vec<(u32, f64)>;

/// The umbrella Laplacian rows of the quad mesh `faces` over `num_vertices` vertices: one row
/// per interior vertex (every edge around it shared by two faces), in vertex order.
pub fn laplacian_rows(faces: &[[u32; 4]], num_vertices: usize) -> Vec<EnergyRow> {
    let mut neighbours: Vec<BTreeSet<u32>> = vec![BTreeSet::new(); num_vertices];
    let mut edge_faces: std::collections::BTreeMap<(u32, u32), usize> = Default::default();
    for f in faces {
        for k in 0..4 {
            let (a, b) = (f[k], f[(k + 1) % 4]);
            neighbours[a as usize].insert(b);
            neighbours[b as usize].insert(a);
            *edge_faces.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let mut on_boundary = vec![false; num_vertices];
    for (&(a, b), &n) in &edge_faces {
        if n == 1 {
            on_boundary[a as usize] = true;
            on_boundary[b as usize] = true;
        }
    }
    (0..num_vertices)
        .filter(|&v| !on_boundary[v] && !neighbours[v].is_empty())
        .map(|v| {
            let w = 4.0 / neighbours[v].len() as f64;
            std::iter::once((v as u32, -4.0))
                .chain(neighbours[v].iter().map(|&n| (n, w)))
                .collect()
        })
        .collect()
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
                if !(sum > 1e-13 * scale) {
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
            .flat_map(|j| (0..n).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]))
            .collect()
    }

    #[test]
    fn reproduces_a_harmonic_saddle_from_its_boundary() {
        // z = x² − y² has a zero 5-point Laplacian on a square grid: zero energy, so the
        // minimizer from its boundary values alone is the saddle itself at every vertex.
        let n = 12;
        let faces = grid(n);
        let at = |v: usize| {
            let (x, y) = ((v % (n + 1)) as f64 / n as f64, (v / (n + 1)) as f64 / n as f64);
            DVec3::new(x, y, x * x - y * y)
        };
        let count = (n + 1) * (n + 1);
        let fixed: Vec<bool> = (0..count)
            .map(|v| v % (n + 1) == 0 || v % (n + 1) == n || v / (n + 1) == 0 || v / (n + 1) == n)
            .collect();
        let start: Vec<DVec3> = (0..count)
            .map(|v| if fixed[v] { at(v) } else { DVec3::new(0.3, -0.2, 5.0) })
            .collect();
        let rows = laplacian_rows(&faces, count);
        assert_eq!(rows.len(), (n - 1) * (n - 1));
        let y = minimize(&rows, &fixed, &start, &Control::NONE).unwrap();
        let worst = (0..count).map(|v| (y[v] - at(v)).length()).fold(0.0, f64::max);
        assert!(worst < 1e-12, "{worst:e}");
    }

    #[test]
    fn a_free_vertex_no_row_reaches_is_refused() {
        let faces = grid(2);
        let mut fixed = vec![true; 9];
        fixed[0] = false; // a corner: the only interior vertex (the centre) is not its neighbour
        let rows = laplacian_rows(&faces, 9);
        match minimize(&rows, &fixed, &[DVec3::ZERO; 9], &Control::NONE) {
            Err(Error::NumericalFailure(m)) => assert!(m.contains("does not determine"), "{m}"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn orders_a_grid_to_a_band_of_about_one_row() {
        let n = 10;
        let faces = grid(n);
        let rows = laplacian_rows(&faces, (n + 1) * (n + 1));
        let count = (n + 1) * (n + 1);
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
        // The Laplacian-squared stencil reaches two grid rows away: at most ~3 rows' width.
        assert!(band <= 3 * (n + 1), "{band}");
    }
}
