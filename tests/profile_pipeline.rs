//! The profile pipeline end to end: fitted limit surfaces against exact shapes, and the fit
//! residual checked with an independently built stencil table.
// Reference geometry for tolerance checks: the platform's libm is fine here.
#![allow(clippy::disallowed_methods)]

use glam::DVec3;
use profsubd::eval::{limit_stencils, Evaluator};
use profsubd::profile::shapes::{double_cone, ellipsoid};
use profsubd::profile::{build, build_cage, default_model, EndKind};
use profsubd::SubdivOptions;
use profsubd::{Fitted, ProfileInput, Settings};

/// Largest of `dist(p)` over `k × k` interior samples and the corners of every face.
/// The end kinds of the model of `input` (its cage's).
fn ends(input: &ProfileInput) -> [EndKind; 2] {
    build_cage(input, &Settings::default()).unwrap().ends
}

fn max_over_limit(model: &Fitted, k: usize, dist: impl Fn(DVec3) -> f64) -> f64 {
    let ev = Evaluator::new(&model.mesh, &SubdivOptions::default()).unwrap();
    let mut worst: f64 = 0.0;
    for f in 0..model.mesh.num_faces() as u32 {
        for i in 0..=k {
            for j in 0..=k {
                let (u, v) = (i as f64 / k as f64, j as f64 / k as f64);
                let p = ev.evaluate(f, u, v).unwrap().position;
                worst = worst.max(dist(p));
            }
        }
    }
    worst
}

/// Largest distance between each vertex's limit position (a fresh stencil table) and its
/// target, relative to the targets' bounding-box diagonal.
fn relative_residual(model: &Fitted) -> f64 {
    let table = limit_stencils(&model.mesh, &SubdivOptions::default()).unwrap();
    let pos = model.mesh.positions();
    let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    let mut worst: f64 = 0.0;
    for (i, t) in model.targets.iter().enumerate() {
        lo = lo.min(*t);
        hi = hi.max(*t);
        let (idx, w) = table.row(i);
        let p: DVec3 = idx.iter().zip(w).map(|(&j, &w)| pos[j as usize] * w).sum();
        worst = worst.max((p - *t).length());
    }
    worst / (hi - lo).length()
}

/// Largest distance between the fitted limit surface of the ellipsoid with semi-axes
/// `(a, b, c)` (silhouettes of 400 points) and the ellipsoid, over its size, at each sampling.
fn ellipsoid_errors(a: f64, b: f64, c: f64, samplings: &[(u32, u32)]) -> Vec<f64> {
    let size = 2.0 * a.max(b).max(c);
    // First-order distance to the quadric: |f| / |∇f|.
    let dist = |p: DVec3| {
        let f = (p.x / a).powi(2) + (p.y / b).powi(2) + (p.z / c).powi(2) - 1.0;
        let g = DVec3::new(
            2.0 * p.x / (a * a),
            2.0 * p.y / (b * b),
            2.0 * p.z / (c * c),
        );
        f.abs() / g.length()
    };
    samplings
        .iter()
        .map(|&(around, along)| {
            let mut input = ellipsoid(a, b, c, 400);
            input.around = around;
            input.along = along;
            let model = build(&input, &Settings::default()).unwrap();
            assert_eq!(ends(&input), [EndKind::Smooth, EndKind::Smooth]);
            assert!(relative_residual(&model) <= 1e-10);
            let e = max_over_limit(&model, 4, dist) / size;
            println!(
                "ellipsoid ({a}, {b}, {c}) {around} x {along}: max distance / size = {e:.3e}, \
                 fit residual {:.3e}",
                model.fit.residual
            );
            e
        })
        .collect()
}

#[test]
fn ellipsoid_limit_surface_converges_to_the_ellipsoid() {
    // The caps replace `grid_cap_depth` rings at each pole (`construct::pole_cap`; rings
    // graded towards the poles gave fourth order but folded there), so the error next to
    // their valence-3 corners falls like h², and rings equidistribute a curvature-weighted
    // length (`construct::equidistribute`), so a sharply turning rim gets more of them.
    // Measured (32 × 16, rates per doubling): 5.9e-4 (4.04, 4.02) for (2, 1, 1.5); 8.2e-4
    // (4.06, 4.03) for the sphere; 2.2e-4 (4.12, 4.05) for the oblate (3, 2, 0.75); 3.6e-4
    // (3.60, 3.78) for the tall (1, 1, 5).
    for (a, b, c) in [
        (2.0, 1.0, 1.5),
        (1.0, 1.0, 1.0),
        (1.0, 1.0, 3.0),
        (2.0, 2.0, 1.0),
        (3.0, 2.0, 0.75),
        (1.0, 1.0, 0.3),
        (1.0, 1.0, 5.0),
    ] {
        let errors = ellipsoid_errors(a, b, c, &[(32, 16), (64, 32), (128, 64)]);
        let rates = [errors[0] / errors[1], errors[1] / errors[2]];
        println!(
            "ellipsoid ({a}, {b}, {c}) convergence rate per doubling: {:.2}, {:.2}",
            rates[0], rates[1]
        );
        assert!(errors[0] < 1e-3, "({a}, {b}, {c}): {errors:?}");
        assert!(
            rates.iter().all(|&r| r >= 3.5),
            "({a}, {b}, {c}): rates {rates:?}"
        );
    }
}

#[test]
fn double_cone_limit_surface_stays_near_the_cone() {
    let mut input = double_cone(1.0, 1.0, 8);
    input.around = 32;
    input.along = 16;
    let model = build(&input, &Settings::default()).unwrap();
    assert_eq!(ends(&input), [EndKind::Tip, EndKind::Tip]);
    assert_eq!(model.mesh.creases().len(), 32);
    assert!(relative_residual(&model) <= 1e-10);
    // Distance to the cone r = 1 - |z| (perpendicular: the slant is 45°).
    let e = max_over_limit(&model, 4, |p| {
        ((p.truncate().length() - (1.0 - p.z.abs())) / 2f64.sqrt()).abs()
    }) / 2.0;
    println!("double cone 32 x 16: max distance / size = {e:.3e}");
    assert!(e < 5e-3, "{e}");
}

/// `(u, v)` of corner `i` of a quad (OpenSubdiv's parameterization).
fn corner_uv(i: usize) -> (f64, f64) {
    [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][i]
}

#[test]
fn semi_sharp_model_interpolates_at_every_face_corner() {
    // Fitted on limitv's stencils; checked here with the (face, u, v) evaluator at every
    // corner of every face, a separate code path.
    let mut input = double_cone(1.0, 1.0, 6);
    let settings = Settings {
        crease_sharpness: 2.5,
        ..Settings::default()
    };
    input.around = 12;
    input.along = 8;
    let model = build(&input, &settings).unwrap();
    assert!(model.mesh.creases().iter().all(|c| c.sharpness == 2.5));
    let ev = Evaluator::new(&model.mesh, &SubdivOptions::default()).unwrap();
    let tol = 1e-10 * model.mesh.bounding_box_diagonal();
    for f in 0..model.mesh.num_faces() {
        for (i, &v) in model.mesh.face(f).iter().enumerate() {
            let (u, w) = corner_uv(i);
            let p = ev.evaluate(f as u32, u, w).unwrap().position;
            let t = model.targets[v as usize];
            assert!((p - t).length() <= tol, "face {f} corner {i}: {p} vs {t}");
        }
    }
}

#[test]
fn bottle_limit_surface_keeps_its_crease_rings() {
    let (input, settings) = default_model();
    let model = build(&input, &settings).unwrap();
    let m = &model.mesh;
    let ev = Evaluator::new(m, &SubdivOptions::default()).unwrap();
    // Across every crease edge the limit surface is continuous but its normal jumps. Per
    // crease ring (grouped by height), the jump reaches the profile's turning angle where the
    // kinked silhouette lies, and stays clearly non-zero all round.
    let mut rings: Vec<(f64, f64, f64)> = Vec::new(); // (z, smallest, largest turn)
    for c in m.creases() {
        let mut sides = Vec::new();
        for f in 0..m.num_faces() {
            let face = m.face(f);
            for i in 0..4 {
                let (a, b) = (face[i], face[(i + 1) % 4]);
                if (a, b) == (c.vertices[0], c.vertices[1])
                    || (b, a) == (c.vertices[0], c.vertices[1])
                {
                    let ((u0, v0), (u1, v1)) = (corner_uv(i), corner_uv((i + 1) % 4));
                    let s = ev
                        .evaluate(f as u32, (u0 + u1) / 2.0, (v0 + v1) / 2.0)
                        .unwrap();
                    sides.push(s);
                }
            }
        }
        assert_eq!(sides.len(), 2);
        assert!((sides[0].position - sides[1].position).length() < 1e-12);
        let turn = sides[0]
            .normal()
            .dot(sides[1].normal())
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees();
        let z = model.targets[c.vertices[0] as usize].z;
        match rings.iter_mut().find(|r| (r.0 - z).abs() < 1e-9) {
            Some(r) => {
                r.1 = r.1.min(turn);
                r.2 = r.2.max(turn);
            }
            None => rings.push((z, turn, turn)),
        }
    }
    assert_eq!(rings.len(), 4);
    for (z, lo, hi) in &rings {
        println!("bottle crease ring z = {z}: normal turn {lo:.1}° to {hi:.1}°");
        assert!(*hi > 40.0 && *lo > 5.0, "ring z = {z}: {lo} to {hi}");
    }
    let smallest_turn = rings.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
    println!("bottle: smallest normal turn across a crease edge {smallest_turn:.1}°");
}

/// Valence of every vertex of a mesh.
fn valences(m: &profsubd::Mesh) -> Vec<usize> {
    let mut edges = std::collections::HashSet::new();
    for f in 0..m.num_faces() {
        let face = m.face(f);
        for i in 0..face.len() {
            let (a, b) = (face[i], face[(i + 1) % face.len()]);
            edges.insert((a.min(b), a.max(b)));
        }
    }
    let mut val = vec![0; m.num_vertices()];
    for (a, b) in edges {
        val[a as usize] += 1;
        val[b as usize] += 1;
    }
    val
}

#[test]
fn both_ends_closed_need_two_rings() {
    // A lens (arcs meeting the axis at 45°: tip at both ends, one segment) and an ellipsoid
    // (smooth poles): with too few rings both ends would close on one ring, leaving vertices
    // of valence 2; the smallest accepted `along` gives valences 3 to 5 except at tips.
    let arc: Vec<[f64; 2]> = (0..=16)
        .map(|i| {
            let t = -std::f64::consts::FRAC_PI_4 * (1.0 - i as f64 / 8.0);
            [2f64.sqrt() * t.cos() - 1.0, 2f64.sqrt() * t.sin()]
        })
        .collect();
    let mut lens = profsubd::construct::profile::ProfileInput::new(arc.clone(), arc);
    lens.around = 8;
    let mut sphere = ellipsoid(1.0, 1.0, 1.0, 16);
    sphere.around = 8;
    for (name, mut input, ends) in [
        ("lens", lens, [EndKind::Tip, EndKind::Tip]),
        ("sphere", sphere, [EndKind::Smooth, EndKind::Smooth]),
    ] {
        input.along = 2;
        let e = build(&input, &Settings::default()).unwrap_err().to_string();
        assert!(
            e.contains("valence 2") && e.contains("along >= 3"),
            "{name}: {e}"
        );
        input.along = 3;
        let model = build(&input, &Settings::default()).unwrap();
        assert_eq!(self::ends(&input), ends, "{name}");
        let tips: Vec<u32> = model.mesh.corners().iter().map(|c| c.vertex).collect();
        for (v, n) in valences(&model.mesh).into_iter().enumerate() {
            assert!(
                tips.contains(&(v as u32)) || (3..=5).contains(&n),
                "{name}: vertex {v} has valence {n}"
            );
        }
    }
}
