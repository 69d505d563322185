//! Random revolution profiles for property tests: `mod random_profile;` via
//! `#[path = "support/random_profile.rs"]`. One seeded generator, so the tests that share it
//! draw the same profiles.

/// A seeded xorshift64 stream of numbers in [0, 1) (six decimals), and the profiles drawn from it.
pub struct RandomProfiles {
    seed: u64,
}

impl RandomProfiles {
    /// The stream every profile test starts from.
    pub fn new() -> Self {
        RandomProfiles { seed: 12345 }
    }

    /// The next number in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.seed ^= self.seed << 13;
        self.seed ^= self.seed >> 7;
        self.seed ^= self.seed << 17;
        (self.seed % 1_000_000) as f64 / 1_000_000.0
    }

    /// 2 to 7 points `(r, z)`, z rising by 0.2 to 1 a point, r in [0.2, 2.2); each end is
    /// moved onto the axis with probability 0.4.
    pub fn profile(&mut self) -> Vec<[f64; 2]> {
        let n = 2 + (self.next() * 6.0) as usize;
        let mut pts: Vec<[f64; 2]> = (0..n)
            .map(|i| [0.2 + 2.0 * self.next(), i as f64 + 0.8 * self.next()])
            .collect();
        if self.next() < 0.4 {
            pts[0][0] = 0.0;
        }
        if self.next() < 0.4 {
            pts[n - 1][0] = 0.0;
        }
        pts
    }
}
