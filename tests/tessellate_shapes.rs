//! Tessellations of every example and of every OpenSubdiv regression shape: closed, manifold
//! and consistently oriented where the control mesh is (Euler characteristic as the control
//! mesh's), every vertex on the limit surface at each polygon corner's (face, u, v), holes
//! and faces without surface left out, and adaptive tessellations within their tolerance at
//! dense samples of every triangle.

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use std::path::{Path, PathBuf};

use profsubd::catmark::Rule;
use profsubd::eval::Evaluator;
use profsubd::io::obj::read_obj_file;
use profsubd::tessellate::{
    chordal_error, tessellate, EdgeReport, Rate, TessellateOptions, Tessellation,
};
use profsubd::topology::Level;

fn examples() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut out = Vec::new();
    for dir in ["meshes", "profiles", "sweeps"] {
        for e in std::fs::read_dir(root.join(dir)).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "obj") {
                out.push(p);
            }
        }
    }
    out.sort();
    assert!(out.len() >= 10, "examples: {out:?}");
    out
}

/// Every polygon corner is the limit at its (face, u, v) within `1e-12 × diagonal`; every
/// polygon lies on a face with surface.
fn assert_on_limit(ev: &Evaluator, t: &Tessellation, name: &str) {
    let tol = 1e-12 * ev.mesh().bounding_box_diagonal();
    let mut start = 0;
    for (k, &size) in t.face_sizes.iter().enumerate() {
        assert!(
            ev.has_surface(t.face_ptex[k]),
            "{name}: polygon on a face without surface"
        );
        for c in start..start + size as usize {
            let [u, v] = t.corner_uv[c];
            let s = ev.evaluate(t.face_ptex[k], u, v).unwrap();
            let d = s
                .position
                .distance(t.positions[t.face_vertices[c] as usize]);
            assert!(
                d <= tol,
                "{name}: corner {c} of polygon {k} is {d} off the limit"
            );
        }
        start += size as usize;
    }
}

struct Outcome {
    closed: bool,
    worst_ratio: f64,
}

/// Checks one mesh; `closed` is whether the control mesh is a closed oriented manifold
/// without holes.
fn check(path: &Path, rate: u32, tol_rel: f64) -> Outcome {
    let name = path.file_stem().unwrap().to_string_lossy().to_string();
    let mesh = read_obj_file(path).unwrap().mesh;
    let options = mesh.options().resolve();
    let subdiv = options;
    let ev = Evaluator::new(&mesh, &options).unwrap();
    let control = EdgeReport::new(mesh.face_sizes(), mesh.face_indices());
    let all_faces = (0..ev.num_parametric_faces() as u32).all(|p| ev.has_surface(p));
    let closed = control.is_closed_oriented_manifold() && all_faces;
    let tol = tol_rel * mesh.bounding_box_diagonal();
    let mut worst_ratio: f64 = 0.0;
    // The valence-360 poles cost most of the run in adaptive mode (every check point near
    // the pole refines its 360-face neighbourhood): uniform only there.
    let rates = if name.contains("pole360") {
        vec![Rate::Uniform(rate)]
    } else {
        vec![Rate::Uniform(rate), Rate::Tolerance(tol)]
    };
    for r in rates {
        // A lower cap than the default keeps the run short; faces that reach it are
        // checked below.
        let options = TessellateOptions {
            rate: r,
            max_rate: 24,
            ..TessellateOptions::default()
        };
        let t = tessellate(&ev, &options).unwrap();
        assert!(t.num_faces() > 0, "{name}");
        let report = t.edge_report();
        if closed {
            assert!(
                report.is_closed_oriented_manifold(),
                "{name} {r:?}: {report:?}"
            );
            assert_eq!(
                report.euler_characteristic(),
                control.euler_characteristic(),
                "{name} {r:?}"
            );
        }
        if control.non_manifold_edges == 0 && control.misoriented_edges == 0 {
            // Open manifolds stay manifold, with the same orientation and topology.
            assert_eq!(
                report.non_manifold_edges + report.misoriented_edges,
                0,
                "{name} {r:?}: {report:?}"
            );
            if all_faces {
                assert_eq!(
                    report.euler_characteristic(),
                    control.euler_characteristic(),
                    "{name} {r:?}"
                );
            }
        }
        assert_on_limit(&ev, &t, &name);
        if let Rate::Tolerance(tol) = r {
            let mut bary = Vec::new();
            let m = 5;
            for i in 0..=m {
                for j in 0..=m - i {
                    let (a, b) = (i as f64 / m as f64, j as f64 / m as f64);
                    bary.push([a, b, 1.0 - a - b]);
                }
            }
            let mut start = 0;
            // Faces at the maximum rate that still miss are named, and each touches an
            // extraordinary vertex or a corner, where the parameterization is singular.
            let level = Level::from_mesh_with_options(&mesh, &subdiv);
            for &p in &t.unmet {
                let (f, _) = ev.ptex_faces().locate(p).unwrap();
                let special = level.face_vertices(f as usize).iter().any(|&v| {
                    let v = v as usize;
                    level.valence(v) != 4 || level.vertex_rule(v) == Rule::Corner
                });
                assert!(
                    special,
                    "{name}: face {p} misses the tolerance at the maximum rate"
                );
            }
            for (k, &size) in t.face_sizes.iter().enumerate() {
                if t.unmet.contains(&t.face_ptex[k]) {
                    start += size as usize;
                    continue;
                }
                let e =
                    chordal_error(&ev, &t, start, size as usize, t.face_ptex[k], &bary).unwrap();
                worst_ratio = worst_ratio.max(e / tol);
                start += size as usize;
            }
        }
    }
    Outcome {
        closed,
        worst_ratio,
    }
}

#[test]
fn examples_tessellate_watertight_on_the_limit_within_tolerance() {
    let mut closed = 0;
    for path in examples() {
        let o = check(&path, 3, 2e-3);
        assert!(
            o.worst_ratio <= 1.0,
            "{}: {} x tolerance",
            path.display(),
            o.worst_ratio
        );
        eprintln!(
            "{}: closed {}, worst error / tolerance {:.3}",
            path.display(),
            o.closed,
            o.worst_ratio
        );
        closed += usize::from(o.closed);
    }
    assert!(closed >= 5, "only {closed} closed examples");
}

#[test]
fn opensubdiv_shapes_tessellate_watertight_on_the_limit_within_tolerance() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mut closed = Vec::new();
    for row in osd_shapes::index(&dir) {
        let o = check(&row.path, 3, 3e-3);
        assert!(
            o.worst_ratio <= 1.0,
            "{}: {} x tolerance",
            row.name,
            o.worst_ratio
        );
        if o.closed {
            closed.push(row.name);
        }
    }
    eprintln!(
        "closed manifold shapes ({}): {}",
        closed.len(),
        closed.join(" ")
    );
    assert!(closed.len() >= 20, "{closed:?}");
}
