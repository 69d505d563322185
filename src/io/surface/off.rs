//! OFF (Object File Format), text.

use std::fmt::Write;

use super::Polygons;
use crate::io::obj::Num;

/// `OFF`, the counts, one line per vertex, one per polygon (0-based indices).
pub(super) fn off(m: &Polygons) -> String {
    let mut out = String::from("OFF\n");
    let _ = writeln!(out, "{} {} 0", m.positions.len(), m.sizes.len());
    for p in m.positions {
        let _ = writeln!(out, "{} {} {}", Num(p.x), Num(p.y), Num(p.z));
    }
    for c in m.each() {
        let _ = write!(out, "{}", c.len());
        for v in c {
            let _ = write!(out, " {v}");
        }
        out.push('\n');
    }
    out
}
