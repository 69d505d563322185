//! The common parameter `t ∈ [0, 1]` of the four silhouettes.
//!
//! The sweep equations need all four curves at one `t`; a feature (corner) drawn at the same
//! height in two views must land on one ring. So:
//!
//! 1. **Breakpoints.** Each curve's break points (corners; every point of a polyline) are
//!    grouped by height across curves (heights within 1e-4 of the model's height range form
//!    one group; within a group the k-th break of each curve goes together). Every group is
//!    one global breakpoint `T_j`, plus `T_0 = 0` (bottom ends) and `T_J = 1` (top ends). A
//!    curve without a break in a group takes its first point at that height between its
//!    neighbouring breaks (its own start/end if the height is never reached strictly inside).
//! 2. **Breakpoint values.** `T_{j+1} − T_j` is proportional to the mean chord length of the
//!    four curves between those breakpoints.
//! 3. **Inside a segment** `[T_j, T_{j+1}]`, with `u` the fraction of the segment: if every
//!    curve rises strictly in z over the segment, the curves are matched *by height*: the
//!    common height is the mean of the four curves' heights at chord fraction `u`, and each
//!    curve is taken at that height (rescaled to its own height range over the segment). This
//!    is what makes silhouettes of an ellipsoid blend back into the exact ellipsoid. Otherwise
//!    (a flat or overhanging part) each curve is taken at chord fraction `u`.

use glam::DVec2;

use super::silhouettes::{Silhouettes, NAMES};
use crate::curves::PlanarCurve;
use crate::error::{Error, Result};

/// Global breakpoints and the matching curve parameters.
#[derive(Debug, Clone)]
pub struct CommonParam {
    /// `T_0 = 0 < … < T_J = 1`.
    pub t: Vec<f64>,
    /// For each curve, its chord-length parameter at each `T_j`.
    pub s: [Vec<f64>; 4],
    /// For each `T_j`, whether each curve has a corner there.
    pub sharp: Vec<[bool; 4]>,
    /// For each segment, whether its curves are matched by height.
    pub by_height: Vec<bool>,
}

/// One break of one curve: height, chord parameter, corner or not.
#[derive(Debug, Clone, Copy)]
struct Break {
    z: f64,
    s: f64,
    sharp: bool,
    curve: usize,
}

impl CommonParam {
    /// Build the common parameter of `sil`.
    pub fn new(sil: &Silhouettes) -> Result<CommonParam> {
        let curves: Vec<&PlanarCurve> = sil.curves.iter().map(|c| &c.curve).collect();
        let (zmin, zmax) = curves
            .iter()
            .flat_map(|c| c.points())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.y), b.max(p.y))
            });
        let tol_h = 1e-4 * (zmax - zmin);
        let mut breaks = Vec::new();
        for (i, c) in sil.curves.iter().enumerate() {
            let mut prev: Option<Break> = None;
            for &k in &c.breaks {
                let b = Break {
                    z: c.curve.points()[k].y,
                    s: c.curve.knots()[k],
                    sharp: c.sharp.contains(&k),
                    curve: i,
                };
                if let Some(p) = prev {
                    if b.z < p.z - tol_h {
                        return Err(Error::invalid_argument(format!(
                            "{} point {k} (z = {}) is a corner below the previous one (z = {}); \
                             corners must rise from bottom to top",
                            NAMES[i], b.z, p.z
                        )));
                    }
                }
                prev = Some(b);
                breaks.push(b);
            }
        }
        // Sorting is stable, so each curve's breaks stay in curve order within a height.
        breaks.sort_by(|a, b| a.z.total_cmp(&b.z));
        let mut groups: Vec<Vec<Break>> = Vec::new();
        for b in breaks {
            match groups.last_mut() {
                Some(g) if b.z - g[0].z <= tol_h => g.push(b),
                _ => groups.push(vec![b]),
            }
        }
        // Global breakpoints: per curve Option<s>, filled below where a curve has none.
        let mut rows: Vec<([Option<f64>; 4], [bool; 4], f64)> = Vec::new();
        rows.push((
            [Some(0.0); 4],
            [false; 4],
            f64::NAN, // heights of end rows are never used
        ));
        for g in &groups {
            let count = |i: usize| g.iter().filter(|b| b.curve == i).count();
            let width = (0..4).map(count).max().unwrap_or(0);
            for j in 0..width {
                let mut s = [None; 4];
                let mut sharp = [false; 4];
                for (i, (si, shi)) in s.iter_mut().zip(sharp.iter_mut()).enumerate() {
                    let mine: Vec<&Break> = g.iter().filter(|b| b.curve == i).collect();
                    if let Some(b) = mine.get(j.min(mine.len().saturating_sub(1))) {
                        *si = Some(b.s);
                        *shi = j < mine.len() && b.sharp;
                    }
                }
                rows.push((s, sharp, g[0].z));
            }
        }
        let lengths: Vec<f64> = curves.iter().map(|c| c.length()).collect();
        let ends: [Option<f64>; 4] = std::array::from_fn(|i| Some(lengths[i]));
        rows.push((ends, [false; 4], f64::NAN));
        let nrows = rows.len();
        let mut s: [Vec<f64>; 4] = Default::default();
        for i in 0..4 {
            let c = curves[i];
            let mut col = vec![0.0; nrows];
            for r in 0..nrows {
                col[r] = match rows[r].0[i] {
                    Some(v) => v,
                    None => {
                        let lo = col[r - 1];
                        let hi = (r + 1..nrows)
                            .find_map(|q| rows[q].0[i])
                            .unwrap_or(lengths[i]);
                        first_at_height(c, lo, hi, rows[r].2)
                    }
                };
            }
            s[i] = col;
        }
        let mut t = vec![0.0; nrows];
        for r in 1..nrows {
            let mean = (0..4).map(|i| s[i][r] - s[i][r - 1]).sum::<f64>() / 4.0;
            t[r] = t[r - 1] + mean;
        }
        let total = t[nrows - 1];
        for v in &mut t {
            *v /= total;
        }
        let by_height = (0..nrows - 1)
            .map(|r| (0..4).all(|i| rises(curves[i], s[i][r], s[i][r + 1])))
            .collect();
        Ok(CommonParam {
            t,
            s,
            sharp: rows.iter().map(|r| r.1).collect(),
            by_height,
        })
    }

    /// Number of segments `J`.
    pub fn segments(&self) -> usize {
        self.t.len() - 1
    }

    /// Points `(w, z)` of the four curves at common parameter `t`.
    pub fn points(&self, sil: &Silhouettes, t: f64) -> [DVec2; 4] {
        let j = (self.t.partition_point(|&v| v <= t).max(1) - 1).min(self.segments() - 1);
        let (ta, tb) = (self.t[j], self.t[j + 1]);
        let u = ((t - ta) / (tb - ta)).clamp(0.0, 1.0);
        let c = |i: usize| &sil.curves[i].curve;
        let lerp_s = |i: usize, u: f64| self.s[i][j] + u * (self.s[i][j + 1] - self.s[i][j]);
        if !self.by_height[j] {
            return std::array::from_fn(|i| c(i).eval(lerp_s(i, u)));
        }
        let z = |i: usize, u: f64| c(i).eval(lerp_s(i, u)).y;
        let mean = |u: f64| (0..4).map(|i| z(i, u)).sum::<f64>() / 4.0;
        let (h0, h1, h) = (mean(0.0), mean(1.0), mean(u));
        let f = ((h - h0) / (h1 - h0)).clamp(0.0, 1.0);
        std::array::from_fn(|i| {
            let (za, zb) = (z(i, 0.0), z(i, 1.0));
            let target = za + f * (zb - za);
            let (mut lo, mut hi) = (self.s[i][j], self.s[i][j + 1]);
            if f <= 0.0 {
                return c(i).eval(lo);
            }
            if f >= 1.0 {
                return c(i).eval(hi);
            }
            // z rises strictly on [lo, hi]: bisection to the last bit.
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if c(i).eval(mid).y < target {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let (pl, ph) = (c(i).eval(lo), c(i).eval(hi));
            if (target - pl.y).abs() <= (ph.y - target).abs() {
                pl
            } else {
                ph
            }
        })
    }
}

/// Samples per span for the monotonicity test and the height search.
const PROBES: usize = 32;

/// Probe parameters covering `[lo, hi]`: the curve's knots inside and `PROBES` per span.
fn probes(c: &PlanarCurve, lo: f64, hi: f64) -> Vec<f64> {
    let mut out = vec![lo];
    let k = c.knots();
    for w in k.windows(2) {
        let (a, b) = (w[0].max(lo), w[1].min(hi));
        // A sliver of a span (`lo` a rounding error short of a knot, as the height search
        // gives) would repeat `lo` PROBES times: equal heights, so a rising segment would
        // count as not rising, and the same shape scaled would be matched otherwise.
        if b - a <= 1e-9 * (hi - lo) {
            continue;
        }
        for q in 1..=PROBES {
            out.push(a + (b - a) * q as f64 / PROBES as f64);
        }
    }
    out
}

/// Whether `z` rises strictly over `[lo, hi]` (on a dense sampling).
fn rises(c: &PlanarCurve, lo: f64, hi: f64) -> bool {
    if hi <= lo {
        return false;
    }
    let z: Vec<f64> = probes(c, lo, hi).iter().map(|&s| c.eval(s).y).collect();
    z.windows(2).all(|w| w[1] > w[0])
}

/// First parameter in `[lo, hi]` where the curve reaches height `h` (bisection on the first
/// bracketing probe interval); `lo` if it starts at or above `h`, `hi` if it never gets there.
fn first_at_height(c: &PlanarCurve, lo: f64, hi: f64, h: f64) -> f64 {
    let p = probes(c, lo, hi);
    if c.eval(lo).y >= h {
        return lo;
    }
    for w in p.windows(2) {
        let (mut a, mut b) = (w[0], w[1]);
        if c.eval(b).y >= h {
            for _ in 0..100 {
                let m = 0.5 * (a + b);
                if c.eval(m).y < h {
                    a = m;
                } else {
                    b = m;
                }
            }
            return b;
        }
    }
    hi
}
