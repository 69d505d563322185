use glam::DVec3;

use super::*;
use crate::mesh::{Crease, Mesh, MeshParts};
use crate::options::SubdivOptions;
use crate::test_support::unit_cube;

/// A triangular prism: two triangles and three quads, closed.
fn prism() -> Mesh {
    let mut positions = Vec::new();
    for z in [0.0, 1.0] {
        for k in 0..3 {
            let a = k as f64 * std::f64::consts::TAU / 3.0;
            positions.push(DVec3::new(crate::math::cos(a), crate::math::sin(a), z));
        }
    }
    Mesh::from_parts(MeshParts {
        positions,
        face_sizes: vec![3, 3, 4, 4, 4],
        face_indices: vec![0, 2, 1, 3, 4, 5, 0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5],
        ..Default::default()
    })
    .unwrap()
}

/// Every polygon corner's position equals the evaluator at the corner's (face, u, v), and
/// every vertex the evaluator at its recorded point.
fn assert_on_limit(ev: &Evaluator, t: &Tessellation) {
    let tol = 1e-12 * ev.mesh().bounding_box_diagonal();
    for (i, p) in t.points.iter().enumerate() {
        let s = ev.evaluate(p.face, p.u, p.v).unwrap();
        assert!(s.position.distance(t.positions[i]) <= tol);
    }
    let mut start = 0;
    for (k, &size) in t.face_sizes.iter().enumerate() {
        for c in start..start + size as usize {
            let [u, v] = t.corner_uv[c];
            let s = ev.evaluate(t.face_ptex[k], u, v).unwrap();
            let d = s
                .position
                .distance(t.positions[t.face_vertices[c] as usize]);
            assert!(d <= tol, "corner {c} of polygon {k} is {d} off");
        }
        start += size as usize;
    }
}

fn opts(rate: Rate, quads: bool) -> TessellateOptions {
    TessellateOptions {
        rate,
        quads,
        ..TessellateOptions::default()
    }
}

#[test]
fn uniform_cube_is_a_closed_grid_on_the_limit() {
    let ev = Evaluator::new(&unit_cube(vec![]), &SubdivOptions::default()).unwrap();
    for n in 1..5u32 {
        let t = tessellate(&ev, &opts(Rate::Uniform(n), true)).unwrap();
        let n = n as usize;
        assert_eq!(t.num_vertices(), 6 * n * n + 2);
        assert_eq!(t.face_sizes, vec![4; 6 * n * n]);
        let r = t.edge_report();
        assert!(r.is_closed_oriented_manifold(), "{r:?}");
        assert_eq!(r.euler_characteristic(), 2);
        assert_eq!(t.normals.len(), t.num_vertices());
        assert_on_limit(&ev, &t);
        // Outward normals: the cube is centred at 0.5.
        for (p, n) in t.positions.iter().zip(&t.vertex_normals) {
            assert!((*p - DVec3::splat(0.5)).dot(*n) > 0.0);
        }
    }
}

#[test]
fn n_gons_go_through_their_sub_faces_and_stay_closed() {
    let ev = Evaluator::new(&prism(), &SubdivOptions::default()).unwrap();
    for n in 1..6 {
        let t = tessellate(&ev, &opts(Rate::Uniform(n), false)).unwrap();
        let r = t.edge_report();
        assert!(r.is_closed_oriented_manifold(), "rate {n}: {r:?}");
        assert_eq!(r.euler_characteristic(), 2);
        assert!(t.face_sizes.iter().all(|&s| s == 3));
        assert_on_limit(&ev, &t);
    }
}

#[test]
fn infinitely_sharp_creases_split_normals() {
    // The four edges around the top face (4 5 7 6) infinitely sharp.
    let creases = [(4, 5), (5, 7), (7, 6), (6, 4)]
        .map(|(a, b)| Crease {
            vertices: [a, b],
            sharpness: 10.0,
        })
        .to_vec();
    let ev = Evaluator::new(&unit_cube(creases), &SubdivOptions::default()).unwrap();
    let n = 4;
    let t = tessellate(&ev, &opts(Rate::Uniform(n), true)).unwrap();
    assert!(t.edge_report().is_closed_oriented_manifold());
    // Points on the crease loop: 4 corners (3 faces each: 2 normals more) and 4 (n - 1)
    // edge points (2 faces: 1 more).
    assert_eq!(
        t.normals.len(),
        t.num_vertices() + 4 * 2 + 4 * (n as usize - 1)
    );
    // Across the crease the two normals differ by a right angle or so.
    let mut start = 0;
    for &size in &t.face_sizes {
        for c in start..start + size as usize {
            let n = t.normals[t.face_normals[c] as usize];
            assert!((n.length() - 1.0).abs() < 1e-12);
        }
        start += size as usize;
    }
}

#[test]
fn adaptive_rates_meet_the_tolerance_without_t_junctions() {
    let ev = Evaluator::new(&prism(), &SubdivOptions::default()).unwrap();
    let tol = 1e-3;
    let t = tessellate(&ev, &opts(Rate::Tolerance(tol), false)).unwrap();
    let r = t.edge_report();
    assert!(r.is_closed_oriented_manifold(), "{r:?}");
    assert_eq!(r.euler_characteristic(), 2);
    assert_on_limit(&ev, &t);
    // Dense barycentric samples of every triangle.
    let mut bary = Vec::new();
    let m = 8;
    for i in 0..=m {
        for j in 0..=m - i {
            let (a, b) = (i as f64 / m as f64, j as f64 / m as f64);
            bary.push([a, b, 1.0 - a - b]);
        }
    }
    let mut start = 0;
    let mut worst: f64 = 0.0;
    for (k, &size) in t.face_sizes.iter().enumerate() {
        worst =
            worst.max(chordal_error(&ev, &t, start, size as usize, t.face_ptex[k], &bary).unwrap());
        start += size as usize;
    }
    assert!(worst <= tol, "{worst}");
    // A coarser tolerance gives fewer triangles.
    let coarse = tessellate(&ev, &opts(Rate::Tolerance(1e-2), false)).unwrap();
    assert!(coarse.num_faces() < t.num_faces());
}

#[test]
fn bad_rates_and_tolerances_are_errors() {
    let ev = Evaluator::new(&unit_cube(vec![]), &SubdivOptions::default()).unwrap();
    for rate in [
        Rate::Uniform(0),
        Rate::Uniform(MAX_RATE + 1),
        Rate::Tolerance(0.0),
        Rate::Tolerance(f64::NAN),
    ] {
        let e = tessellate(&ev, &opts(rate, false)).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument(_)), "{e}");
    }
}
