//! Small dense linear algebra for vertex neighbourhoods (a few dozen unknowns).

use crate::error::{Error, Result};

/// The left eigenvector `l` of eigenvalue 1 of the row-stochastic matrix `s` (`m × m`,
/// row-major), normalized so that its entries sum to 1: the limit mask of a subdivision
/// matrix.
///
/// Solves `(Sᵀ − I) l = 0` with one equation replaced by `Σ l = 1` (the rows of `Sᵀ − I`
/// sum to zero, so any one is redundant when the eigenvalue is simple), by Gaussian
/// elimination with partial pivoting.
///
/// Errors ([`Error::NumericalFailure`]): eigenvalue 1 is not simple (singular system).
pub(crate) fn stationary_left_eigenvector(s: &[f64], m: usize) -> Result<Vec<f64>> {
    let mut a = vec![0.0; m * m];
    for r in 0..m {
        for c in 0..m {
            a[r * m + c] = s[c * m + r] - if r == c { 1.0 } else { 0.0 };
        }
    }
    let mut b = vec![0.0; m];
    for c in 0..m {
        a[(m - 1) * m + c] = 1.0;
    }
    b[m - 1] = 1.0;
    solve_in_place(&mut a, &mut b, m)?;
    Ok(b)
}

/// Solve `a x = b` in place (`b` becomes `x`).
fn solve_in_place(a: &mut [f64], b: &mut [f64], m: usize) -> Result<()> {
    for k in 0..m {
        let p = (k..m)
            .max_by(|&i, &j| a[i * m + k].abs().total_cmp(&a[j * m + k].abs()))
            .unwrap();
        if a[p * m + k].abs() < 1e-14 {
            return Err(Error::NumericalFailure(
                "vertex subdivision matrix has a repeated eigenvalue 1".into(),
            ));
        }
        if p != k {
            for c in 0..m {
                a.swap(p * m + c, k * m + c);
            }
            b.swap(p, k);
        }
        for i in k + 1..m {
            let f = a[i * m + k] / a[k * m + k];
            if f != 0.0 {
                for c in k..m {
                    a[i * m + c] -= f * a[k * m + c];
                }
                b[i] -= f * b[k];
            }
        }
    }
    for k in (0..m).rev() {
        let mut x = b[k];
        for c in k + 1..m {
            x -= a[k * m + c] * b[c];
        }
        b[k] = x / a[k * m + k];
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_bspline_point_limit_is_one_four_one() {
        // The 1-D cubic B-spline subdivision of (left, centre, right).
        let s = [0.5, 0.5, 0.0, 0.125, 0.75, 0.125, 0.0, 0.5, 0.5];
        let l = stationary_left_eigenvector(&s, 3).unwrap();
        for (x, e) in l.iter().zip([1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0]) {
            assert!((x - e).abs() < 1e-15, "{l:?}");
        }
    }

    #[test]
    fn reducible_matrix_is_reported() {
        let s = [1.0, 0.0, 0.0, 1.0];
        assert!(matches!(
            stationary_left_eigenvector(&s, 2),
            Err(Error::NumericalFailure(_))
        ));
    }
}
