//! Points without limit surface and the Bfr domain, on OpenSubdiv's regression shapes:
//! - the control vertices without surface are exactly those named in issue 9 (isolated
//!   vertices, vertex 12 of catmark_hole_test2, the boundary of catmark_edgenone), and every
//!   API marks them the same way: `vertices_with_surface`, empty stencil rows, NaN samples,
//!   `Evaluator::vertex_limits` `None`, `nan` lines from the CLI, `--strict` failing;
//! - a vertex has a surface exactly when one of its faces has (the evaluator's face rule);
//! - `(face, u, v)` in Bfr's domain evaluates to the Ptex point with derivatives times 2 on
//!   sub-faces, and the Ptex -> Bfr -> Ptex round trip is the identity.
//!
//! OpenSubdiv's side of the same rules is checked in `cpp_tests/conformance_no_surface.cpp`.

#[path = "support/cli.rs"]
mod cli;
#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use cli::{assert_refused, profsubd, stdout};
use profsubd::eval::{
    limit_stencils, limit_vertex_samples, vertices_with_surface, Domain, Evaluator,
};
use profsubd::io::obj::read_obj_file;
use profsubd::{BoundaryInterpolation, CreaseMethod, SubdivOptions};

const NAMED: [&str; 5] = [
    "catmark_nonman_bareverts",
    "catmark_hole_test2",
    "catmark_edgenone",
    "catmark_val2_nonman",
    "catmark_nonman_verts",
];

fn without_surface(mask: &[bool]) -> Vec<usize> {
    (0..mask.len()).filter(|&v| !mask[v]).collect()
}

#[test]
fn the_named_shapes_mark_exactly_their_vertices_without_surface() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mut want: Vec<Vec<usize>> = vec![
        (0..5).chain(20..25).collect(), // bareverts: the 10 isolated vertices
        vec![12],                       // hole_test2: all four faces of vertex 12 are holes
        Vec::new(),                     // edgenone: filled below (its 28 boundary vertices, 5 more)
        vec![11],                       // val2_nonman: isolated
        vec![48],                       // nonman_verts: isolated
    ];
    for (name, want) in NAMED.iter().zip(&mut want) {
        let path = dir.join(format!("{name}.obj"));
        let mesh = read_obj_file(&path).unwrap().mesh;
        let options = mesh.options().resolve();
        let mask = vertices_with_surface(&mesh, &options);
        if *name == "catmark_edgenone" {
            // Boundary rule none: the faces at the boundary are holes, so every boundary
            // vertex (and any vertex whose faces all touch it) has no surface.
            assert_eq!(options.boundary, BoundaryInterpolation::None);
            *want = without_surface(&mask);
            assert_eq!(want.len(), 33, "{want:?}");
        }
        assert_eq!(&without_surface(&mask), want, "{name}");
        // Every API marks the same vertices.
        let table = limit_stencils(&mesh, &options).unwrap();
        let samples = limit_vertex_samples(&mesh, &options).unwrap();
        let ev = Evaluator::new(&mesh, &options).unwrap();
        let limits = ev.vertex_limits().unwrap();
        for v in 0..mesh.num_vertices() {
            assert_eq!(table.is_empty_row(v), !mask[v], "{name} vertex {v}");
            assert_eq!(samples[v].has_surface(), mask[v], "{name} vertex {v}");
            assert_eq!(limits[v].is_some(), mask[v], "{name} vertex {v}");
            if !mask[v] {
                let s = samples[v];
                assert!(s.position.is_nan() && s.du.is_nan() && s.dv.is_nan());
            }
        }
        // The CLI prints `nan nan nan` there and the same numbers elsewhere; --strict fails.
        let o = profsubd(&["limit", path.to_str().unwrap()]);
        assert!(o.status.success());
        let text = stdout(&o);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), mesh.num_vertices());
        for (v, line) in lines.iter().enumerate() {
            assert_eq!(
                *line == "nan nan nan",
                !mask[v],
                "{name} vertex {v}: {line}"
            );
        }
        let o = profsubd(&["limit", path.to_str().unwrap(), "--strict"]);
        let says = format!("vertex {} has no limit surface", want[0]);
        assert_refused(&o, &says, &[], name);
    }
}

#[test]
fn vertices_have_a_surface_exactly_when_one_of_their_faces_has() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mut marked = 0usize;
    for row in osd_shapes::index(&dir) {
        if row.verts > 2000 {
            continue; // catmark_car, pole360...: slow to build, nothing new
        }
        let mesh = read_obj_file(&row.path).unwrap().mesh;
        for boundary in BoundaryInterpolation::ALL {
            let options = SubdivOptions {
                boundary,
                crease_method: CreaseMethod::Uniform,
                ..mesh.options().resolve()
            };
            let ev = Evaluator::new(&mesh, &options).unwrap();
            let ptex = ev.ptex_faces();
            let mut expect = vec![false; mesh.num_vertices()];
            for f in 0..mesh.num_faces() {
                let first = ptex.first_of(f);
                let count = ptex.first_of(f + 1) - first;
                let has = ev.has_surface(first);
                // A face has a surface as a whole, never per sub-face.
                assert!((first..first + count).all(|p| ev.has_surface(p) == has));
                if has {
                    for &v in mesh.face(f) {
                        expect[v as usize] = true;
                    }
                }
                // The point API marks it: None, not an error, in both domains.
                let p = ev.evaluate_in(Domain::Ptex, first, 0.5, 0.5).unwrap();
                let b = ev.evaluate_in(Domain::Bfr, f as u32, 0.25, 0.25).unwrap();
                assert_eq!(p.is_some(), has, "{} face {f}", row.name);
                assert_eq!(b.is_some(), has, "{} face {f}", row.name);
            }
            let mask = vertices_with_surface(&mesh, &options);
            assert_eq!(mask, expect, "{} {boundary:?}", row.name);
            marked += mask.iter().filter(|&&m| !m).count();
        }
    }
    assert!(marked > 100, "{marked}");
}

#[test]
fn bfr_points_evaluate_as_their_ptex_points_with_derivatives_times_two() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mut compared = 0usize;
    for row in osd_shapes::index(&dir) {
        if row.verts > 2000 || !row.notes.contains("face sizes") {
            continue; // N-gon shapes only
        }
        let mesh = read_obj_file(&row.path).unwrap().mesh;
        let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
        let ptex = ev.ptex_faces();
        for pf in 0..ev.num_parametric_faces() as u32 {
            let (face, sub) = ptex.locate(pf).unwrap();
            for (u, v) in [
                (0.0, 0.0),
                (0.375, 0.625),
                (1.0, 1.0),
                (0.5, 0.0),
                (0.0, 1.0),
            ] {
                let (f, bu, bv) = ptex.to_bfr(pf, u, v).unwrap();
                assert_eq!(f, face);
                let a = ev.evaluate_in(Domain::Ptex, pf, u, v).unwrap();
                let b = ev.evaluate_in(Domain::Bfr, f, bu, bv).unwrap();
                let (Some(a), Some(b)) = (a, b) else {
                    assert_eq!(a.is_none(), b.is_none());
                    continue;
                };
                let k = if sub.is_some() { 2.0 } else { 1.0 };
                assert_eq!(a.position, b.position, "{} {pf} ({u}, {v})", row.name);
                assert_eq!(a.du * k, b.du, "{} {pf} ({u}, {v})", row.name);
                assert_eq!(a.dv * k, b.dv, "{} {pf} ({u}, {v})", row.name);
                compared += 1;
            }
        }
    }
    assert!(compared > 1000, "{compared}");
}
