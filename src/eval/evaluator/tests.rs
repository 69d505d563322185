//! Tests of [`super::evaluator`] against analytic surfaces.

use crate::math;
use glam::DVec3;

use crate::eval::bspline::BicubicPatch;
use crate::eval::evaluator::Evaluator;
use crate::mesh::{Crease, Mesh, MeshParts};
use crate::options::{BoundaryInterpolation, SubdivOptions};
use crate::test_support::grid;

fn bumpy(x: f64, y: f64) -> f64 {
    math::sin(0.7 * x) * math::cos(0.4 * y + 0.3) + 0.05 * x * y
}

#[test]
fn interior_face_of_a_grid_is_the_bicubic_b_spline() {
    let n = 5;
    let parts = grid(n, bumpy);
    let mesh = Mesh::from_parts(parts.clone()).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    // Face (2, 2): control points (1..=4, 1..=4).
    let pts: [DVec3; 16] =
        std::array::from_fn(|k| parts.positions[(1 + k / 4) * (n + 1) + 1 + k % 4]);
    let patch = BicubicPatch::with_boundary(pts, 0);
    for &(u, v) in &[
        (0.0, 0.0),
        (0.3, 0.8),
        (1.0, 0.5),
        (0.5, 1.0),
        (0.123, 0.987),
    ] {
        let got = ev.evaluate((2 * n + 2) as u32, u, v).unwrap();
        let (p, du, dv) = patch.evaluate(u, v);
        assert!((got.position - p).length() < 1e-15, "{u} {v}");
        assert!((got.du - du).length() < 1e-14);
        assert!((got.dv - dv).length() < 1e-14);
        // B-splines reproduce the linear x and y of the grid.
        assert!((got.position.x - (2.0 + u)).abs() < 1e-14);
        assert!((got.position.y - (2.0 + v)).abs() < 1e-14);
        assert!((got.du.x - 1.0).abs() < 1e-14 && got.du.y.abs() < 1e-14);
    }
}

#[test]
fn boundary_and_corner_faces_follow_the_crease_rules() {
    // Under edge-and-corner interpolation the boundary is the cubic B-spline of the boundary
    // vertices, interpolating the corners; a planar grid stays exactly linear.
    let n = 4;
    let mesh = Mesh::from_parts(grid(n, |x, y| 0.25 * x * x - 0.1 * y * y * y)).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let corner = ev.evaluate(0, 0.0, 0.0).unwrap();
    assert!((corner.position - DVec3::ZERO).length() < 1e-15);
    // Along the bottom boundary y = 0, heights 0.25 x²: the B-spline of x² samples with the
    // end rule reproduces x² + 1/3·(B-spline offset) away from the ends; at the limit point
    // of vertex (2, 0) it is (P1 + 4 P2 + P3) / 6.
    let p = ev.evaluate(1, 1.0, 0.0).unwrap().position;
    let want = (0.25 * 1.0 + 4.0 * 0.25 * 4.0 + 0.25 * 9.0) / 6.0;
    assert!((p - DVec3::new(2.0, 0.0, want)).length() < 1e-15, "{p}");
    // x and y stay linear everywhere, boundary faces included.
    for f in [0u32, 1, 3, 4, 15] {
        let (i, j) = ((f % 4) as f64, (f / 4) as f64);
        let s = ev.evaluate(f, 0.25, 0.75).unwrap();
        assert!((s.position.x - (i + 0.25)).abs() < 1e-14, "face {f}");
        assert!((s.position.y - (j + 0.75)).abs() < 1e-14, "face {f}");
        assert!((s.du.x - 1.0).abs() < 1e-14 && (s.dv.y - 1.0).abs() < 1e-14);
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let mesh = Mesh::from_parts(grid(4, bumpy)).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let h = 1e-6;
    for f in 0..16u32 {
        let (u, v) = (0.37, 0.61);
        let s = ev.evaluate(f, u, v).unwrap();
        let fu = (ev.evaluate(f, u + h, v).unwrap().position
            - ev.evaluate(f, u - h, v).unwrap().position)
            / (2.0 * h);
        let fv = (ev.evaluate(f, u, v + h).unwrap().position
            - ev.evaluate(f, u, v - h).unwrap().position)
            / (2.0 * h);
        assert!((s.du - fu).length() < 1e-8, "face {f}");
        assert!((s.dv - fv).length() < 1e-8, "face {f}");
    }
}

#[test]
fn infinitely_sharp_crease_splits_the_grid_into_two_boundary_patches() {
    // A crease along x = 2 makes both sides boundary patches: the crease curve is the
    // B-spline of the crease vertices alone, whatever the heights beside it.
    let mut parts = grid(4, |x, y| {
        if x == 2.0 {
            0.1 * y * y
        } else {
            math::sin(x * y)
        }
    });
    for j in 0..4u32 {
        parts.creases.push(Crease {
            vertices: [j * 5 + 2, (j + 1) * 5 + 2],
            sharpness: 10.0,
        });
    }
    let mesh = Mesh::from_parts(parts).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    // Face (1, 1) has its right edge on the crease; at (1, 0) it is the crease's limit at
    // vertex (2, 1): (z(2,0) + 4 z(2,1) + z(2,2)) / 6.
    let left = ev.evaluate(5, 1.0, 0.0).unwrap().position;
    let right = ev.evaluate(6, 0.0, 0.0).unwrap().position;
    let want = DVec3::new(2.0, 1.0, (0.0 + 4.0 * 0.1 + 0.4) / 6.0);
    assert!((left - want).length() < 1e-15, "{left}");
    assert!((right - want).length() < 1e-15, "{right}");
}

#[test]
fn bad_input_is_rejected_with_a_reason() {
    let mut parts = grid(3, bumpy);
    parts.holes.push(4);
    let mesh = Mesh::from_parts(parts).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let msg = |r: crate::Result<_>| format!("{}", r.unwrap_err());
    assert!(msg(ev.evaluate(9, 0.5, 0.5)).contains("out of range"));
    assert!(msg(ev.evaluate(0, 1.5, 0.5)).contains("outside [0, 1]"));
    assert!(msg(ev.evaluate(0, 0.5, f64::NAN)).contains("outside [0, 1]"));
    assert!(msg(ev.evaluate(4, 0.5, 0.5)).contains("hole"));
    let none = SubdivOptions {
        boundary: BoundaryInterpolation::None,
        ..Default::default()
    };
    let ev = Evaluator::new(&mesh, &none).unwrap();
    assert!(msg(ev.evaluate(0, 0.5, 0.5)).contains("no limit surface"));
    assert!(ev.evaluate_many(&[0, 1], &[0.5], &[0.5, 0.5]).is_err());
}

/// The level-`level` face whose corner 0 is at `(i, j) / 2^level` of Ptex face `ptex` (for
/// a non-quad's sub-face, itself a level-1 face, at `(i, j) / 2^(level - 1)`), for
/// Far's child face order (children of face `f` start at the sum of the sizes of the faces
/// before it; a quad's child `q` is its quadrant `q`, with corner 0 at the lower left).
fn descendant(mesh: &Mesh, ptex: u32, i: u32, j: u32, level: u32) -> u32 {
    let p = crate::eval::ptex::PtexFaces::new(mesh).unwrap();
    let (f, sub) = p.locate(ptex).unwrap();
    let offset = mesh.face_offsets()[f as usize];
    let quadrant = |b: u32| {
        let (r, t) = ((i >> b) & 1, (j >> b) & 1);
        [[0, 3], [1, 2]][r as usize][t as usize]
    };
    let (mut idx, mut bits) = match sub {
        Some(k) => (offset + k, level - 1),
        None => (offset + quadrant(level - 1), level - 1),
    };
    while bits > 0 {
        bits -= 1;
        idx = idx * 4 + quadrant(bits);
    }
    idx
}

/// The limit of a smooth valence-4 vertex: `(16 w + 4 Σ edge ends + Σ diagonals) / 36`.
fn smooth_limit(refined: &Mesh, w: u32) -> DVec3 {
    let nb =
        crate::eval::patch_topology::Neighbourhood::from_mesh(refined, &SubdivOptions::default());
    let faces = nb.vertex_faces(w);
    assert_eq!(faces.len(), 4, "vertex {w} is not regular");
    let p = refined.positions();
    let mut sum = 16.0 * p[w as usize];
    for &g in faces {
        let face = nb.face(g);
        assert_eq!(face.len(), 4);
        let k = face.iter().position(|&x| x == w).unwrap();
        // Each edge end is seen from two faces: 4 · e counted as 2 · e twice.
        sum += 2.0 * (p[face[(k + 1) % 4] as usize] + p[face[(k + 3) % 4] as usize]);
        sum += p[face[(k + 2) % 4] as usize];
    }
    sum / 36.0_f64
}

fn cube() -> MeshParts {
    let positions = (0..8)
        .map(|k| DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64))
        .map(|p| p + DVec3::new(0.1 * p.y * p.z, -0.2 * p.x * p.z, 0.05 * p.x))
        .collect();
    MeshParts {
        positions,
        face_sizes: vec![4; 6],
        face_indices: vec![
            0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
        ],
        ..Default::default()
    }
}

/// A square pyramid (a quad and four triangles) with an extra pentagon-topped side: mixed
/// face sizes and extraordinary vertices of valence 3, 4 and 5.
fn mixed() -> MeshParts {
    MeshParts {
        positions: vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.1),
            DVec3::new(1.2, 1.0, 0.0),
            DVec3::new(0.0, 1.1, -0.1),
            DVec3::new(0.5, 0.5, 1.0),
            DVec3::new(-0.6, 0.5, 0.4),
        ],
        face_sizes: vec![4, 3, 3, 3, 3, 3],
        face_indices: vec![0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 5, 4, 5, 0, 4],
        ..Default::default()
    }
}

fn check_against_refinement(parts: MeshParts, options: SubdivOptions, what: &str) {
    let mesh = Mesh::from_parts(parts).unwrap();
    let ev = Evaluator::new(&mesh, &options).unwrap();
    let scale = mesh.bounding_box_diagonal();
    for level in 2..=4u32 {
        let refined = crate::refine::refine_uniform(&mesh, &options, level).unwrap();
        for ptex in 0..ev.num_parametric_faces() as u32 {
            let sub = ev.ptex_faces().locate(ptex).unwrap().1.is_some();
            let n = 1u32 << (level - u32::from(sub));
            for (i, j) in [
                (1, 1),
                (n - 1, 1),
                (n / 2, n - 1),
                (1, (n / 2 + 1).min(n - 1)),
                (n - 1, n - 1),
            ] {
                let f = descendant(&mesh, ptex, i, j, level);
                let w = refined.face(f as usize)[0];
                let want = smooth_limit(&refined, w);
                let got = ev
                    .evaluate(
                        ptex,
                        f64::from(i) / f64::from(n),
                        f64::from(j) / f64::from(n),
                    )
                    .unwrap()
                    .position;
                assert!(
                    (got - want).length() <= 1e-13 * scale,
                    "{what}: face {ptex} ({i}, {j})/{n}: {got} vs {want}"
                );
            }
        }
    }
}

#[test]
fn extraordinary_vertices_agree_with_deep_refinement() {
    check_against_refinement(cube(), SubdivOptions::default(), "cube");
    check_against_refinement(mixed(), SubdivOptions::default(), "mixed");
}

#[test]
fn semi_sharp_features_agree_with_deep_refinement() {
    for method in [crate::CreaseMethod::Uniform, crate::CreaseMethod::Chaikin] {
        let mut parts = cube();
        for (a, b, s) in [(0, 2, 2.5f32), (2, 3, 1.25), (3, 1, 3.0), (0, 4, 0.5)] {
            parts.creases.push(Crease {
                vertices: [a, b],
                sharpness: s,
            });
        }
        parts.corners.push(crate::Corner {
            vertex: 7,
            sharpness: 1.75,
        });
        let options = SubdivOptions {
            crease_method: method,
            ..Default::default()
        };
        check_against_refinement(parts, options, "creased cube");
    }
}

#[test]
fn open_meshes_agree_with_deep_refinement_under_each_boundary_rule() {
    // The mixed mesh without its base quad: an open cup with a boundary of 4 edges.
    let mut parts = mixed();
    parts.face_sizes.remove(0);
    parts.face_indices.drain(0..4);
    for boundary in [
        BoundaryInterpolation::EdgeOnly,
        BoundaryInterpolation::EdgeAndCorner,
    ] {
        let options = SubdivOptions {
            boundary,
            ..Default::default()
        };
        check_against_refinement(parts.clone(), options, "cup");
    }
}

#[test]
fn derivatives_near_extraordinary_vertices_match_finite_differences() {
    let mesh = Mesh::from_parts(mixed()).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let h = 1e-7;
    for ptex in 0..ev.num_parametric_faces() as u32 {
        for &(u, v) in &[(0.01, 0.02), (0.3, 0.001), (0.97, 0.99), (0.5, 0.25)] {
            let s = ev.evaluate(ptex, u, v).unwrap();
            let p = |u, v| ev.evaluate(ptex, u, v).unwrap().position;
            let fu = (p(u + h, v) - p(u - h, v)) / (2.0 * h);
            let fv = (p(u, v + h) - p(u, v - h)) / (2.0 * h);
            let tol = 1e-6 * (1.0 + s.du.length() + s.dv.length());
            assert!(
                (s.du - fu).length() < tol,
                "face {ptex} ({u}, {v}): {} vs {fu}",
                s.du
            );
            assert!(
                (s.dv - fv).length() < tol,
                "face {ptex} ({u}, {v}): {} vs {fv}",
                s.dv
            );
        }
    }
}

/// Two triangles sharing an edge in opposite directions (as in OpenSubdiv's
/// `catmark_val2_nonman`): the edge is non-manifold, hence an infinitely sharp crease, and
/// each of its refined edge points is a regular crease vertex on either side (Far gives an
/// edge's child vertex no topological sharpening). The derivative at points exactly on the
/// crease must be the one-sided derivative of the positions next to it.
#[test]
fn derivatives_on_a_non_manifold_crease_are_one_sided_limits() {
    let mesh = Mesh::from_parts(MeshParts {
        positions: vec![
            DVec3::new(0.3, 0.0, -0.7),
            DVec3::new(0.7, 0.05, -0.7),
            DVec3::new(0.3, -0.2, -0.9),
            DVec3::new(0.78, -0.25, -0.93),
        ],
        face_sizes: vec![3, 3],
        face_indices: vec![2, 3, 0, 2, 3, 1],
        ..Default::default()
    })
    .unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let h = 1e-4;
    // Sub-face 1 of face 0 (Ptex face 1) has the crease half at vertex 3 as its u = 0 side,
    // sub-face 0 (Ptex face 0) the half at vertex 2 as its v = 0 side.
    for &(face, u, v, along_u) in &[
        (1u32, 0.0, 1.0, true),
        (1, 0.0, 0.5, true),
        (0, 0.5, 0.0, false),
        (0, 0.25, 0.0, false),
    ] {
        let at = |s: f64| {
            let (pu, pv) = if along_u { (u + s, v) } else { (u, v + s) };
            ev.evaluate(face, pu, pv).unwrap().position
        };
        // Second-order one-sided difference into the face.
        let fd = (-3.0 * at(0.0) + 4.0 * at(h) - at(2.0 * h)) / (2.0 * h);
        let got = ev.evaluate(face, u, v).unwrap();
        let d = if along_u { got.du } else { got.dv };
        assert!(
            (d - fd).length() < 1e-6 * fd.length(),
            "face {face} ({u}, {v}): {d} vs finite difference {fd}"
        );
        // And continuous: the same a hair inside the face.
        let (pu, pv) = if along_u {
            (u + 1e-12, v)
        } else {
            (u, v + 1e-12)
        };
        let near = ev.evaluate(face, pu, pv).unwrap();
        let dn = if along_u { near.du } else { near.dv };
        assert!((d - dn).length() < 1e-9 * d.length(), "{d} vs {dn}");
    }
}
