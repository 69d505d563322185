//! Which axis points up in a written file.
//!
//! profsubd builds its models Z-up (surfaces of revolution turn about z), as CAD programs,
//! Blender and OpenSCAD expect. Y-up programs (glTF, Maya, many game engines, USD's default)
//! show a Z-up model lying on its side; [`UpAxis::Y`] writes `(x, y, z)` as `(x, z, -y)`, a
//! right-handed rotation by -90° about x, so the model stands up there. Reading a Y-up file
//! applies the inverse, `(x, y, z)` → `(x, -z, y)`; both are exact (a swap and a negation).

use glam::DVec3;

/// The up axis of a written file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum UpAxis {
    /// Z up: coordinates as they are (profsubd's convention).
    #[default]
    Z,
    /// Y up: `(x, y, z)` written as `(x, z, -y)`.
    Y,
}

impl UpAxis {
    /// A point or direction of the Z-up model in this file's axes.
    pub fn from_z_up(self, p: DVec3) -> DVec3 {
        match self {
            UpAxis::Z => p,
            UpAxis::Y => DVec3::new(p.x, p.z, -p.y),
        }
    }

    /// A point or direction of a file with this up axis in profsubd's Z-up axes.
    pub fn to_z_up(self, p: DVec3) -> DVec3 {
        match self {
            UpAxis::Z => p,
            UpAxis::Y => DVec3::new(p.x, -p.z, p.y),
        }
    }

    /// The name USD uses (`"Z"`, `"Y"`).
    pub fn name(self) -> &'static str {
        match self {
            UpAxis::Z => "Z",
            UpAxis::Y => "Y",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn y_up_is_a_rotation_and_reads_back_exactly() {
        let p = DVec3::new(0.1, -2.5, 3.75);
        let y = UpAxis::Y.from_z_up(p);
        assert_eq!(y, DVec3::new(0.1, 3.75, 2.5));
        assert_eq!(UpAxis::Y.to_z_up(y), p);
        // Right-handed: x × y = z still holds for the images.
        let (x, yy, z) = (
            UpAxis::Y.from_z_up(DVec3::X),
            UpAxis::Y.from_z_up(DVec3::Y),
            UpAxis::Y.from_z_up(DVec3::Z),
        );
        assert_eq!(x.cross(yy), z);
        assert_eq!(z, DVec3::Y);
        assert_eq!(UpAxis::Z.from_z_up(p), p);
    }
}
