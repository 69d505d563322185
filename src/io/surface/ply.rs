//! PLY, binary little-endian, with per-vertex normals.

use glam::DVec3;

use super::Polygons;

/// Header, then per vertex `x y z nx ny nz` as `double`, per polygon a `uchar` count and
/// `uint` indices.
pub(super) fn ply(m: &Polygons, normals: &[DVec3]) -> Vec<u8> {
    let header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment written by profsubd: limit surface \
         tessellation\nelement vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         property double nx\nproperty double ny\nproperty double nz\nelement face {}\n\
         property list uchar uint vertex_indices\nend_header\n",
        m.positions.len(),
        m.sizes.len()
    );
    let mut out = header.into_bytes();
    for (p, n) in m.positions.iter().zip(normals) {
        for x in p.to_array().into_iter().chain(n.to_array()) {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    for c in m.each() {
        out.push(c.len() as u8);
        for v in c {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    out
}
