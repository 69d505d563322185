//! The Bézier crust of one face (Wang & Cheng 2014): the bi-quintic Bernstein patch whose
//! 6 × 6 coefficients are the face's four corner vectors, each repeated over the 3 × 3
//! block at its corner.
//!
//! `D(u, v) = Σᵢ Σⱼ b_{i,5}(u) b_{j,5}(v) ∇P_{ij}` with `∇P_{ij}` = the vector of corner 0
//! for `i, j ∈ [0, 2]` (u = 0, v = 0), corner 1 for `i ∈ [3, 5], j ∈ [0, 2]`, corner 2 for
//! `i, j ∈ [3, 5]`, corner 3 for `i ∈ [0, 2], j ∈ [3, 5]` (Ptex corner order). Along the
//! side `v = 0` the crust is `(1 − h(u)) d₀ + h(u) d₁` with `h = b₃ + b₄ + b₅`, which
//! depends on that side's two corners only, and `∂D/∂v`, `∂²D/∂v²` vanish there (the
//! blocks make the first three coefficient rows equal): so the crust adds nothing to the
//! surface's jumps across an edge, and the offset is as smooth as the surface.

use glam::DVec3;

/// The weights of the low block (`i ∈ [0, 2]`) and the high block (`i ∈ [3, 5]`) at `t`,
/// and their derivatives: the high block's `b₃ + b₄ + b₅ = t³ (10 − 15 t + 6 t²)`, with
/// derivative `30 t² (1 − t)²` (the unit tests check both against the Bernstein sums).
#[inline]
fn blocks(t: f64) -> ([f64; 2], [f64; 2]) {
    let s = 1.0 - t;
    let t2 = t * t;
    let high = t2 * t * (10.0 + t * (-15.0 + 6.0 * t));
    let dhigh = 30.0 * t2 * s * s;
    ([1.0 - high, high], [-dhigh, dhigh])
}

/// The crust of one face, ready to evaluate: with the block weights `U = b₃ + b₄ + b₅`
/// at `u` and `V` at `v`, `D = d₀ (1 − U)(1 − V) + d₁ U (1 − V) + d₂ U V + d₃ (1 − U) V`
/// is bilinear in `(U, V)`: `D = a + b U + c V + e U V`. Built once per face, so a point
/// costs two quintic polynomials and three vector multiply-adds.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Crust {
    a: DVec3,
    b: DVec3,
    c: DVec3,
    e: DVec3,
}

impl Crust {
    /// The crust of a face with corner vectors `d` (Ptex corner order).
    pub fn new(d: &[DVec3; 4]) -> Crust {
        Crust {
            a: d[0],
            b: d[1] - d[0],
            c: d[3] - d[0],
            e: d[2] - d[3] - d[1] + d[0],
        }
    }

    /// The corner vector at Ptex corner `k`.
    pub fn corner(&self, k: usize) -> DVec3 {
        match k {
            0 => self.a,
            1 => self.a + self.b,
            2 => self.a + self.b + self.c + self.e,
            _ => self.a + self.c,
        }
    }

    /// The crust at `(u, v)` and its derivatives with respect to `u` and `v`.
    #[inline]
    pub fn evaluate(&self, u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
        let ([_, cu], [_, dcu]) = blocks(u);
        let ([_, cv], [_, dcv]) = blocks(v);
        let along_u = self.b + self.e * cv;
        let along_v = self.c + self.e * cu;
        (
            self.a + along_u * cu + self.c * cv,
            along_u * dcu,
            along_v * dcv,
        )
    }
}

/// The crust at `(u, v)` of a face with corner vectors `d` (Ptex corner order), and its
/// derivatives with respect to `u` and `v` ([`Crust`] for many points of one face).
pub fn crust(d: &[DVec3; 4], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    Crust::new(d).evaluate(u, v)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Binomial coefficients of degree 5.
    const BINOMIAL: [f64; 6] = [1.0, 5.0, 10.0, 10.0, 5.0, 1.0];

    /// The quintic Bernstein values `b_{i,5}(t)` and their derivatives.
    fn bernstein5(t: f64) -> ([f64; 6], [f64; 6]) {
        let s = 1.0 - t;
        let mut tp = [1.0; 6];
        let mut sp = [1.0; 6];
        for k in 1..6 {
            tp[k] = tp[k - 1] * t;
            sp[k] = sp[k - 1] * s;
        }
        let b = std::array::from_fn(|i| BINOMIAL[i] * tp[i] * sp[5 - i]);
        // b'_{i,5} = 5 (b_{i-1,4} − b_{i,4}).
        let b4 = |i: usize| -> f64 {
            const BIN4: [f64; 5] = [1.0, 4.0, 6.0, 4.0, 1.0];
            if i > 4 {
                0.0
            } else {
                BIN4[i] * tp[i] * sp[4 - i]
            }
        };
        let db = std::array::from_fn(|i| {
            let prev = if i == 0 { 0.0 } else { b4(i - 1) };
            5.0 * (prev - b4(i))
        });
        (b, db)
    }

    /// The literal 6 × 6 Bernstein sum of the issue, coefficient by coefficient.
    fn literal(d: &[DVec3; 4], u: f64, v: f64) -> DVec3 {
        let (bu, _) = bernstein5(u);
        let (bv, _) = bernstein5(v);
        let mut sum = DVec3::ZERO;
        for (i, bi) in bu.iter().enumerate() {
            for (j, bj) in bv.iter().enumerate() {
                let corner = match (i >= 3, j >= 3) {
                    (false, false) => 0,
                    (true, false) => 1,
                    (true, true) => 2,
                    (false, true) => 3,
                };
                sum += d[corner] * (bi * bj);
            }
        }
        sum
    }

    fn corners() -> [DVec3; 4] {
        [
            DVec3::new(0.1, 0.2, 1.0),
            DVec3::new(-0.3, 0.1, 0.9),
            DVec3::new(0.2, -0.4, 1.1),
            DVec3::new(0.05, 0.3, 0.8),
        ]
    }

    #[test]
    fn block_weights_are_the_bernstein_sums() {
        for t in [0.0, 0.1, 0.25, 0.5, 0.77, 1.0] {
            let (b, db) = bernstein5(t);
            let ([low, high], [dlow, dhigh]) = blocks(t);
            assert!((low - (b[0] + b[1] + b[2])).abs() < 1e-15);
            assert!((high - (b[3] + b[4] + b[5])).abs() < 1e-15);
            assert!((dlow - (db[0] + db[1] + db[2])).abs() < 1e-13);
            assert!((dhigh - (db[3] + db[4] + db[5])).abs() < 1e-13);
        }
    }

    #[test]
    fn blocks_are_the_literal_bernstein_sum_and_its_derivatives() {
        let d = corners();
        let h = 1e-6;
        for &(u, v) in &[(0.0, 0.0), (0.3, 0.7), (0.5, 0.5), (1.0, 0.25), (0.9, 1.0)] {
            let (value, du, dv) = crust(&d, u, v);
            assert!((value - literal(&d, u, v)).length() < 1e-15);
            // Central differences of the literal sum (one-sided at the ends).
            let (a, b) = ((u - h).max(0.0), (u + h).min(1.0));
            let fd = (literal(&d, b, v) - literal(&d, a, v)) / (b - a);
            assert!((du - fd).length() < 1e-8, "{du} {fd}");
            let (a, b) = ((v - h).max(0.0), (v + h).min(1.0));
            let fd = (literal(&d, u, b) - literal(&d, u, a)) / (b - a);
            assert!((dv - fd).length() < 1e-8, "{dv} {fd}");
        }
        // The corners are interpolated.
        for (k, (u, v)) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .into_iter()
            .enumerate()
        {
            assert!((crust(&d, u, v).0 - d[k]).length() < 1e-15);
        }
    }

    /// The block form term by term: corner k weighted by its block weights.
    fn by_blocks(d: &[DVec3; 4], u: f64, v: f64) -> DVec3 {
        let ([u0, u1], _) = blocks(u);
        let ([v0, v1], _) = blocks(v);
        d[0] * (u0 * v0) + d[1] * (u1 * v0) + d[2] * (u1 * v1) + d[3] * (u0 * v1)
    }

    #[test]
    fn the_bilinear_form_is_the_block_sum_and_keeps_the_corners() {
        let d = corners();
        let c = Crust::new(&d);
        for (k, dk) in d.iter().enumerate() {
            assert!((c.corner(k) - *dk).length() < 1e-15);
        }
        for &(u, v) in &[(0.0, 0.0), (0.2, 0.9), (0.5, 0.5), (0.61, 0.13), (1.0, 1.0)] {
            assert!((c.evaluate(u, v).0 - by_blocks(&d, u, v)).length() < 1e-15);
        }
    }

    #[test]
    fn a_side_depends_on_its_two_corners_only_with_flat_cross_derivatives() {
        let d = corners();
        let mut other = d;
        other[2] = DVec3::new(5.0, 5.0, 5.0);
        other[3] = DVec3::new(-5.0, 1.0, 0.0);
        for u in [0.1, 0.37, 0.5, 0.81] {
            let (a, da_u, da_v) = crust(&d, u, 0.0);
            let (b, db_u, db_v) = crust(&other, u, 0.0);
            assert_eq!(a, b);
            assert_eq!(da_u, db_u);
            assert_eq!(da_v, DVec3::ZERO);
            assert_eq!(db_v, DVec3::ZERO);
            // Second cross derivative by differences of the first.
            let h = 1e-6;
            let second = (crust(&other, u, h).2 - crust(&other, u, 0.0).2) / h;
            assert!(second.length() < 1e-3, "{second}");
        }
    }
}
