//! Ring placement: `along` ring intervals shared among the segments between breakpoints.
//!
//! Each segment `[T_j, T_{j+1}]` gets intervals in proportion to its length (largest
//! deficit first), at least one. Inside a segment rings are uniform in the
//! curvature-weighted length of the four curves (`crate::construct::equidistribute`); a
//! ring passes through every breakpoint.
//!
//! A smooth pole's grid cap replaces the innermost rings of its segment (`cap_depths`):
//! as many as its concentric squares (`around / 8`), so that the cap's cells are as large as
//! the faces around it, but never the segment's last ring
//! (`crate::construct::pole_cap::cap_depths`).

use super::param::CommonParam;
use super::silhouettes::{EndKind, Silhouettes};
use crate::construct::equidistribute::ring_parameters;
use crate::construct::pole_cap::cap_depths;
use crate::error::{Error, Result};

/// The rings of a profile model.
#[derive(Debug, Clone)]
pub struct Rings {
    /// Common parameter of each ring, bottom (0) to top (`along`).
    pub t: Vec<f64>,
    /// Ring index of each global breakpoint `T_j`.
    pub ring_of_break: Vec<usize>,
    /// Rings replaced by the grid cap at each end (bottom, top); 0 unless a smooth pole.
    pub cap_depth: [usize; 2],
}

impl Rings {
    /// Place `along` ring intervals; a smooth pole's cap replaces up to `cap_squares` of them
    /// (`cap_depths`), at least one.
    ///
    /// Errors ([`Error::InvalidArgument`]): `along` too small for the segments and caps; the
    /// curves crossing the axis at a ring.
    pub fn new(
        sil: &Silhouettes,
        param: &CommonParam,
        along: usize,
        cap_squares: usize,
    ) -> Result<Rings> {
        // The least a cap replaces; the checks below need room for that much.
        let cap_rings = 1;
        let segs = param.segments();
        let mut min = vec![1usize; segs];
        if sil.ends[0] == EndKind::Smooth {
            min[0] = min[0].max(cap_rings);
        }
        if sil.ends[1] == EndKind::Smooth {
            min[segs - 1] = if segs == 1 && sil.ends[0] == EndKind::Smooth {
                2 * cap_rings
            } else {
                min[segs - 1].max(cap_rings)
            };
        }
        let need: usize = min.iter().sum();
        if need > along {
            return Err(Error::invalid_argument(format!(
                "along = {along} is too small: the {segs} segment(s) between corners need one \
                 ring interval each and each smooth pole's cap {cap_rings}; use along >= {need}"
            )));
        }
        // Both ends closed by caps or tips need distinct rings: closing one ring from both
        // sides would leave vertices of valence 2.
        let depth = |e: EndKind| match e {
            EndKind::Smooth => cap_rings,
            EndKind::Tip => 1,
            EndKind::Open | EndKind::Flat => 0,
        };
        let [bottom, top] = sil.ends;
        let closed_need = depth(bottom) + depth(top) + 1;
        if !sil.ends.contains(&EndKind::Open) && along < closed_need {
            return Err(Error::invalid_argument(format!(
                "along = {along} is too small: the caps or tips closing both ends would meet on \
                 one ring (vertices of valence 2); use along >= {closed_need}"
            )));
        }
        let mut count = min;
        // A smooth pole's segment first gets room for its cap and one interval outside it
        // (`cap_depths`), as far as `along` allows: a cap squeezed into one ring folds.
        let mut used = need;
        for (end, seg) in [(0, 0), (1, segs - 1)] {
            if sil.ends[end] != EndKind::Smooth {
                continue;
            }
            let want = if segs == 1 && sil.ends == [EndKind::Smooth; 2] {
                2 * cap_squares + 1
            } else if segs == 1 && sil.ends.contains(&EndKind::Tip) {
                cap_squares + 2
            } else {
                cap_squares + 1
            };
            while count[seg] < want && used < along {
                count[seg] += 1;
                used += 1;
            }
        }
        let ideal: Vec<f64> = (0..segs)
            .map(|j| along as f64 * (param.t[j + 1] - param.t[j]))
            .collect();
        for _ in used..along {
            let j = (0..segs)
                .max_by(|&a, &b| {
                    (ideal[a] - count[a] as f64).total_cmp(&(ideal[b] - count[b] as f64))
                })
                .unwrap_or(0);
            count[j] += 1;
        }
        let mut t = Vec::with_capacity(along + 1);
        let mut ring_of_break = Vec::with_capacity(segs + 1);
        for (j, (w, &c)) in param.t.windows(2).zip(&count).enumerate() {
            ring_of_break.push(t.len());
            let poles = [
                j == 0 && sil.ends[0] == EndKind::Smooth,
                j + 1 == segs && sil.ends[1] == EndKind::Smooth,
            ];
            let rings = ring_parameters([w[0], w[1]], c, poles, |t| param.points(sil, t));
            t.extend_from_slice(&rings[..c]);
        }
        ring_of_break.push(t.len());
        t.push(1.0);
        let tol = 1e-9 * sil.size;
        for (r, &tr) in t.iter().enumerate() {
            let c = param.points(sil, tr);
            let (wx, wy) = (c[0].x - c[2].x, c[1].x - c[3].x);
            if wx < -tol || wy < -tol {
                return Err(Error::invalid_argument(format!(
                    "the curves cross the axis at ring {r} (z ≈ {:.6}): c1 − c3 = {wx:.3e}, \
                     c2 − c4 = {wy:.3e}; a profile must stay on its side of the axis (with a \
                     spline, add points where it overshoots or use \"interpolation\": \
                     \"polyline\")",
                    (c[0].y + c[1].y + c[2].y + c[3].y) / 4.0
                )));
            }
        }
        let cap_depth = cap_depths(
            sil.ends.map(|e| e == EndKind::Smooth),
            sil.ends.map(|e| e == EndKind::Tip),
            &count,
            cap_squares,
        );
        Ok(Rings {
            t,
            ring_of_break,
            cap_depth,
        })
    }

    /// Parameter at fractional ring depth `depth` from end `end` (0 bottom, 1 top), linear
    /// between rings: where a grid cap's inner squares lie.
    pub fn cap_t(&self, end: usize, depth: f64) -> f64 {
        let last = self.t.len() - 1;
        let x = if end == 0 { depth } else { last as f64 - depth };
        let i = (x.floor() as usize).min(last.saturating_sub(1));
        let f = x - i as f64;
        self.t[i] + f * (self.t[i + 1] - self.t[i])
    }
}
