//! Incomplete LU factors of the fit's stencil matrix on its own sparsity pattern (ILU(0)),
//! BiCGSTAB's preconditioner ([`super::krylov`]).
//!
//! On the regular part of a cage the limit stencil matrix is the tensor product of the cubic
//! B-spline's `(1, 4, 1) / 6` along rings and meridians, whose exact LU factors (products of
//! bidiagonal ones) lie inside the matrix's own 9-point pattern when the vertices are
//! numbered ring by ring: ILU(0) is then nearly the exact inverse, and BiCGSTAB needs a few
//! iterations where the diagonal (Jacobi) preconditioner needed dozens. Both the
//! factorization and the triangular solves are scalar loops in a fixed order, so the result
//! has the same bits on every machine and thread count.

use super::CsrRef;

/// Smallest accepted pivot relative to the largest entry of its row: below it the
/// factorization is refused (the caller falls back to the diagonal preconditioner).
const MIN_PIVOT: f64 = 1e-8;

/// ILU(0) factors: `L` (unit diagonal, not stored) strictly below and `U` on and above the
/// diagonal, in the positions of the matrix's entries.
pub(super) struct Ilu0<'a> {
    a: CsrRef<'a>,
    values: Vec<f64>,
    /// Position of each row's diagonal entry.
    diagonal: Vec<usize>,
    /// `1 / U_ii`.
    inv_pivot: Vec<f64>,
}

impl<'a> Ilu0<'a> {
    /// The factors of `a`, or `None` if a row's columns are not strictly increasing, a
    /// diagonal entry is missing, or a pivot is small or not finite.
    pub(super) fn new(a: CsrRef<'a>) -> Option<Ilu0<'a>> {
        let n = a.offsets.len().checked_sub(1)?;
        let row = |i: usize| a.offsets[i] as usize..a.offsets[i + 1] as usize;
        let mut diagonal = Vec::with_capacity(n);
        for i in 0..n {
            let cols = &a.indices[row(i)];
            if cols.windows(2).any(|w| w[0] >= w[1]) {
                return None;
            }
            diagonal.push(a.offsets[i] as usize + cols.binary_search(&(i as u32)).ok()?);
        }
        let mut values = a.weights.to_vec();
        let mut inv_pivot = vec![0.0; n];
        // Where each column of the current row sits (usize::MAX: not in the pattern).
        let mut at = vec![usize::MAX; n];
        for i in 0..n {
            for k in row(i) {
                at[a.indices[k] as usize] = k;
            }
            for k in row(i).start..diagonal[i] {
                let j = a.indices[k] as usize;
                let l = values[k] * inv_pivot[j];
                values[k] = l;
                for m in diagonal[j] + 1..a.offsets[j + 1] as usize {
                    let p = at[a.indices[m] as usize];
                    if p != usize::MAX {
                        values[p] -= l * values[m];
                    }
                }
            }
            let largest = values[row(i)].iter().fold(0.0f64, |m, w| m.max(w.abs()));
            let pivot = values[diagonal[i]];
            if !pivot.is_finite() || pivot.abs() <= MIN_PIVOT * largest {
                return None;
            }
            inv_pivot[i] = 1.0 / pivot;
            for k in row(i) {
                at[a.indices[k] as usize] = usize::MAX;
            }
        }
        Some(Ilu0 {
            a,
            values,
            diagonal,
            inv_pivot,
        })
    }

    /// `out = (L U)⁻¹ r`: forward then backward substitution.
    pub(super) fn solve(&self, r: &[f64], out: &mut [f64]) {
        let (idx, val) = (self.a.indices, &self.values);
        for i in 0..r.len() {
            let mut sum = r[i];
            let s = self.a.offsets[i] as usize;
            for (&j, &w) in idx[s..self.diagonal[i]]
                .iter()
                .zip(&val[s..self.diagonal[i]])
            {
                sum -= w * out[j as usize];
            }
            out[i] = sum;
        }
        for i in (0..r.len()).rev() {
            let mut sum = out[i];
            let (s, e) = (self.diagonal[i] + 1, self.a.offsets[i + 1] as usize);
            for (&j, &w) in idx[s..e].iter().zip(&val[s..e]) {
                sum -= w * out[j as usize];
            }
            out[i] = sum * self.inv_pivot[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The factors of a tridiagonal matrix are its exact LU: the solve inverts it.
    #[test]
    fn factors_of_a_tridiagonal_matrix_are_exact() {
        let n = 40usize;
        let (mut offsets, mut indices, mut weights) = (vec![0u32], vec![], vec![]);
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                indices.push(j as u32);
                weights.push(if i == j {
                    4.0 / 6.0
                } else {
                    1.0 / 6.0 + 0.01 * i as f64
                });
            }
            offsets.push(indices.len() as u32);
        }
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        let x: Vec<f64> = (0..n).map(|i| crate::math::sin(i as f64 * 0.37)).collect();
        let mut b = vec![0.0; n];
        super::super::apply_scalar(a, &x, &mut b);
        let mut y = vec![0.0; n];
        Ilu0::new(a).unwrap().solve(&b, &mut y);
        for (x, y) in x.iter().zip(&y) {
            assert!((x - y).abs() < 1e-14, "{x} vs {y}");
        }
    }

    /// The tensor product of two tridiagonal B-spline matrices on an `n × n` grid numbered
    /// row by row (the limit stencils of a regular patch of quads, open ends): its exact LU
    /// factors lie in its 9-point pattern, so ILU(0) solves it to rounding.
    #[test]
    fn factors_of_a_tensor_product_spline_matrix_are_exact() {
        let n = 12usize;
        let b = |i: usize, k: usize| match i.abs_diff(k) {
            0 => 4.0 / 6.0,
            1 => 1.0 / 6.0,
            _ => 0.0,
        };
        let (mut offsets, mut indices, mut weights) = (vec![0u32], vec![], vec![]);
        for (i, j) in (0..n).flat_map(|i| (0..n).map(move |j| (i, j))) {
            for k in i.saturating_sub(1)..(i + 2).min(n) {
                for l in j.saturating_sub(1)..(j + 2).min(n) {
                    indices.push((k * n + l) as u32);
                    weights.push(b(i, k) * b(j, l));
                }
            }
            offsets.push(indices.len() as u32);
        }
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        let x: Vec<f64> = (0..n * n)
            .map(|i| crate::math::cos(i as f64 * 0.61) + 0.01 * i as f64)
            .collect();
        let mut rhs = vec![0.0; n * n];
        super::super::apply_scalar(a, &x, &mut rhs);
        let mut y = vec![0.0; n * n];
        Ilu0::new(a).unwrap().solve(&rhs, &mut y);
        for (x, y) in x.iter().zip(&y) {
            assert!((x - y).abs() < 1e-13, "{x} vs {y}");
        }
    }

    #[test]
    fn refuses_unsorted_rows_missing_diagonals_and_zero_pivots() {
        let offsets = [0u32, 2, 3];
        let weights = [1.0, 1.0, 1.0];
        let unsorted = [1u32, 0, 1];
        let no_diagonal = [1u32, 1, 0];
        for indices in [&unsorted[..], &no_diagonal[..]] {
            let a = CsrRef {
                offsets: &offsets,
                indices,
                weights: &weights,
            };
            assert!(Ilu0::new(a).is_none());
        }
        // [[1, 1], [1, 1]]: the second pivot is 0.
        let offsets = [0u32, 2, 4];
        let indices = [0u32, 1, 0, 1];
        let weights = [1.0; 4];
        let a = CsrRef {
            offsets: &offsets,
            indices: &indices,
            weights: &weights,
        };
        assert!(Ilu0::new(a).is_none());
    }
}
