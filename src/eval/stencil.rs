//! Stencil tables: each limit point as a weighted sum of control vertices.
//!
//! A [`StencilTable`] is stored in compressed sparse rows (CSR), the layout of OpenSubdiv's
//! `Far::StencilTable`: row `i` holds the weights `weights[offsets[i]..offsets[i + 1]]` on
//! the control vertices `indices[offsets[i]..offsets[i + 1]]`. Build once, apply to any
//! number of primvar sets. A row with no entries marks a point without limit surface (see
//! [`super::surface`]): applying it gives NaN, never a made-up point.

use glam::DVec3;

use crate::error::{Error, Result};

/// Sparse rows of weights on control vertices, in CSR form.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StencilTable {
    /// Row start offsets into `indices` and `weights`, one per row plus the total at the end.
    pub offsets: Vec<u32>,
    /// Control vertex of each entry.
    pub indices: Vec<u32>,
    /// Weight of each entry.
    pub weights: Vec<f64>,
}

impl StencilTable {
    /// An empty table (no rows).
    pub fn new() -> StencilTable {
        StencilTable {
            offsets: vec![0],
            indices: Vec::new(),
            weights: Vec::new(),
        }
    }

    /// Append one row given as `(control vertex, weight)` entries.
    pub fn push_row(&mut self, entries: impl IntoIterator<Item = (u32, f64)>) {
        if self.offsets.is_empty() {
            self.offsets.push(0);
        }
        for (i, w) in entries {
            self.indices.push(i);
            self.weights.push(w);
        }
        self.offsets.push(self.indices.len() as u32);
    }

    /// Number of rows.
    pub fn num_rows(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }

    /// Total number of (index, weight) entries.
    pub fn num_entries(&self) -> usize {
        self.indices.len()
    }

    /// Row `i` as parallel slices of control vertices and weights. Panics if out of range.
    pub fn row(&self, i: usize) -> (&[u32], &[f64]) {
        let (a, b) = (self.offsets[i] as usize, self.offsets[i + 1] as usize);
        (&self.indices[a..b], &self.weights[a..b])
    }

    /// Whether row `i` has no entries: a point without limit surface. Panics if out of range.
    pub fn is_empty_row(&self, i: usize) -> bool {
        self.offsets[i] == self.offsets[i + 1]
    }

    /// Weighted sum of `points` for row `i`; NaN for an empty row (no limit surface). Panics
    /// if out of range.
    pub fn apply_row(&self, i: usize, points: &[DVec3]) -> DVec3 {
        let (idx, w) = self.row(i);
        if idx.is_empty() {
            return DVec3::NAN;
        }
        idx.iter()
            .zip(w)
            .fold(DVec3::ZERO, |acc, (&j, &wj)| acc + points[j as usize] * wj)
    }

    /// Apply every row to `points` (one point per control vertex); empty rows give NaN.
    ///
    /// Errors ([`Error::InvalidArgument`]): a stencil refers to a control vertex that
    /// `points` does not have.
    pub fn apply(&self, points: &[DVec3]) -> Result<Vec<DVec3>> {
        if let Some(&j) = self.indices.iter().find(|&&j| j as usize >= points.len()) {
            return Err(Error::invalid_argument(format!(
                "stencil refers to control vertex {j}, but only {} points were given",
                points.len()
            )));
        }
        Ok((0..self.num_rows())
            .map(|i| self.apply_row(i, points))
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_apply_as_weighted_sums() {
        let mut t = StencilTable::new();
        t.push_row([(0, 0.5), (2, 0.5)]);
        t.push_row([(1, 1.0)]);
        t.push_row([]);
        assert_eq!(t.num_rows(), 3);
        assert_eq!(t.num_entries(), 3);
        assert_eq!(t.offsets, vec![0, 2, 3, 3]);
        assert!(!t.is_empty_row(1) && t.is_empty_row(2));
        let p = [DVec3::X, DVec3::Y, DVec3::new(3.0, 0.0, 4.0)];
        let got = t.apply(&p).unwrap();
        assert_eq!(got[..2], [DVec3::new(2.0, 0.0, 2.0), DVec3::Y]);
        assert!(got[2].is_nan(), "an empty row is a point without surface");
        assert!(matches!(t.apply(&p[..2]), Err(Error::InvalidArgument(_))));
    }
}
