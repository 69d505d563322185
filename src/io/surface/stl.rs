//! STL, binary and ASCII.

use std::fmt::Write;

use glam::DVec3;

use crate::io::obj::Num;

/// Geometric unit normal of a triangle (zero for a degenerate one).
fn normal(p: &[DVec3], t: [u32; 3]) -> DVec3 {
    let [a, b, c] = t.map(|i| p[i as usize]);
    (b - a).cross(c - a).normalize_or_zero()
}

/// Binary STL: an 80-byte header that does not start with `solid` (so readers do not take it
/// for ASCII), the triangle count, and 50 bytes per triangle, little-endian `f32`.
pub(super) fn binary(p: &[DVec3], triangles: &[[u32; 3]]) -> Vec<u8> {
    let mut out = Vec::with_capacity(84 + 50 * triangles.len());
    let mut header =
        *b"binary STL written by profsubd: limit surface tessellation                      ";
    header[79] = b' ';
    out.extend_from_slice(&header);
    out.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
    for &t in triangles {
        let n = normal(p, t);
        for v in std::iter::once(n).chain(t.map(|i| p[i as usize])) {
            for x in v.to_array() {
                out.extend_from_slice(&(x as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    out
}

/// ASCII STL with shortest round-trip decimals.
pub(super) fn ascii(p: &[DVec3], triangles: &[[u32; 3]]) -> String {
    let mut out = String::from("solid profsubd\n");
    let v3 = |v: DVec3| format!("{} {} {}", Num(v.x), Num(v.y), Num(v.z));
    for &t in triangles {
        let _ = writeln!(out, "  facet normal {}\n    outer loop", v3(normal(p, t)));
        for i in t {
            let _ = writeln!(out, "      vertex {}", v3(p[i as usize]));
        }
        out.push_str("    endloop\n  endfacet\n");
    }
    out.push_str("endsolid profsubd\n");
    out
}
