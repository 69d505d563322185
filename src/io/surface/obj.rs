//! OBJ with vertex normals.

use std::fmt::Write;

use glam::DVec3;

use super::Polygons;
use crate::io::obj::Num;

/// `v` lines, `vn` lines, then `f v//vn` lines (1-based).
pub(super) fn obj(m: &Polygons, normals: &[DVec3], corner_normals: &[u32]) -> String {
    let mut out = String::from("# limit surface tessellation written by profsubd\n");
    for p in m.positions {
        let _ = writeln!(out, "v {} {} {}", Num(p.x), Num(p.y), Num(p.z));
    }
    for n in normals {
        let _ = writeln!(out, "vn {} {} {}", Num(n.x), Num(n.y), Num(n.z));
    }
    let mut k = 0;
    for c in m.each() {
        out.push('f');
        for v in c {
            let _ = write!(out, " {}//{}", v + 1, corner_normals[k] + 1);
            k += 1;
        }
        out.push('\n');
    }
    out
}
