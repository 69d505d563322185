//! One evaluated point of the limit surface.

use glam::DVec3;

/// Limit position and first derivatives at one point of the limit surface.
///
/// `du` and `dv` are derivatives with respect to the (u, v) parameterization of a face as
/// OpenSubdiv's `Bfr::Surface` reports them: for a quad, corner 0 at (0,0), corner 1 at
/// (1,0), corner 2 at (1,1), corner 3 at (0,1); for other faces, per sub-face of
/// OpenSubdiv's quadrangulation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LimitSample {
    /// Limit position.
    pub position: DVec3,
    /// Derivative with respect to u.
    pub du: DVec3,
    /// Derivative with respect to v.
    pub dv: DVec3,
}

impl LimitSample {
    /// The marker of a point without limit surface (see [`super::surface`]) in functions
    /// that return plain samples: every coordinate NaN.
    pub const NO_SURFACE: LimitSample = LimitSample {
        position: DVec3::NAN,
        du: DVec3::NAN,
        dv: DVec3::NAN,
    };

    /// False for [`LimitSample::NO_SURFACE`] (a NaN position), true for a point of the
    /// limit surface.
    pub fn has_surface(&self) -> bool {
        !self.position.x.is_nan()
    }

    /// Unit normal `normalize(du × dv)`, or the zero vector where the derivatives are
    /// parallel (a degenerate parameterization).
    pub fn normal(&self) -> DVec3 {
        self.du.cross(self.dv).normalize_or_zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_is_unit_and_right_handed() {
        let s = LimitSample {
            position: DVec3::ZERO,
            du: DVec3::new(2.0, 0.0, 0.0),
            dv: DVec3::new(0.0, 3.0, 0.0),
        };
        assert_eq!(s.normal(), DVec3::Z);
        let flat = LimitSample {
            du: DVec3::X,
            dv: DVec3::X * -2.0,
            ..s
        };
        assert_eq!(flat.normal(), DVec3::ZERO);
        assert!(s.has_surface() && !LimitSample::NO_SURFACE.has_surface());
        assert!(LimitSample::NO_SURFACE.du.is_nan() && LimitSample::NO_SURFACE.dv.is_nan());
    }
}
