use super::*;

/// `n + 1` points from `a` to `b` lifted by `f`.
fn line(a: [f64; 2], b: [f64; 2], n: usize, f: &dyn Fn(f64, f64) -> f64) -> Vec<[f64; 3]> {
    (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let (x, y) = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
            [x, y, f(x, y)]
        })
        .collect()
}

fn square(f: &dyn Fn(f64, f64) -> f64, n: usize) -> CurvesInput {
    CurvesInput::new(vec![
        line([-1.0, -1.0], [1.0, -1.0], n, f),
        line([1.0, -1.0], [1.0, 1.0], n, f),
        line([1.0, 1.0], [-1.0, 1.0], n, f),
        line([-1.0, 1.0], [-1.0, -1.0], n, f),
    ])
}

#[test]
fn blend_is_eq_8_on_four_sides_and_exact_on_them() {
    let input = square(&|x, y| x * x - y * y, 8);
    let b = input.blend(&Settings::default()).unwrap();
    let s = &b.boundary.sides;
    for &(u, v) in &[(0.3, 0.6), (0.5, 0.5), (0.9, 0.05)] {
        let want = {
            let w = [
                1.0 / (u * u),
                1.0 / ((1.0 - u) * (1.0 - u)),
                1.0 / (v * v),
                1.0 / ((1.0 - v) * (1.0 - v)),
            ];
            let p = [s[3].point(v), s[1].point(v), s[0].point(u), s[2].point(u)];
            let k: f64 = w.iter().sum();
            (0..4).map(|i| p[i] * (w[i] / k)).sum::<DVec3>()
        };
        let got = b.point(DVec2::new(u, v));
        assert!((got - want).length() < 1e-14, "{got} {want}");
    }
    // d = 0: the curve point.
    assert_eq!(b.point(DVec2::new(0.37, 0.0)), s[0].point(0.37));
    assert_eq!(b.point(DVec2::new(1.0, 0.61)), s[1].point(0.61));
}

use crate::eval::Evaluator;
use crate::mesh::validate::check;

/// Largest distance of the limit surface (5 × 5 points per face) from `f`, over the
/// diagonal, and the fitted result.
fn limit_error(fitted: &Fitted, f: &dyn Fn(DVec3) -> f64) -> f64 {
    let m = &fitted.mesh;
    let ev = Evaluator::new(m, &m.options().resolve()).unwrap();
    let mut worst = 0.0f64;
    for face in 0..m.num_faces() as u32 {
        for k in 0..25 {
            let (u, v) = ((k % 5) as f64 / 4.0, (k / 5) as f64 / 4.0);
            worst = worst.max(f(ev.evaluate(face, u, v).unwrap().position).abs());
        }
    }
    worst / m.bounding_box_diagonal()
}

/// Valid open manifold, one boundary loop, consistently oriented, normals along `normal`
/// (the projection plane's), no folds, fit within tolerance.
fn assert_valid(fitted: &Fitted, normal: DVec3) {
    let r = check(&fitted.mesh);
    assert!(
        r.is_manifold() && r.is_consistently_oriented() && !r.is_closed(),
        "{r:?}"
    );
    assert_eq!(r.num_boundary_loops, 1);
    assert!(fitted.fit.residual <= 1e-10 * fitted.mesh.bounding_box_diagonal());
    let report = fitted.surface_report().unwrap();
    assert_eq!(report.folded_faces, 0, "{report:?}");
    let m = &fitted.mesh;
    let ev = Evaluator::new(m, &m.options().resolve()).unwrap();
    for face in 0..m.num_faces() as u32 {
        let n = ev.evaluate(face, 0.5, 0.5).unwrap().normal();
        assert!(
            n.dot(normal) > 0.0,
            "face {face} normal {n} against {normal}"
        );
    }
}

#[test]
fn planar_quadrilateral_gives_a_planar_limit() {
    // A skew quadrilateral in a tilted plane, straight sides with uneven point spacing.
    let (o, e1, e2) = (
        DVec3::new(0.3, -0.2, 1.0),
        DVec3::new(2.0, 1.0, 0.5),
        DVec3::new(-0.4, 1.0, 1.5),
    );
    let at = |a: f64, b: f64| (o + e1 * a + e2 * b).to_array();
    let corners = [(0.0, 0.0), (1.0, 0.1), (1.2, 0.9), (-0.1, 1.1)];
    let side = |k: usize| -> Vec<[f64; 3]> {
        let (a, b) = (corners[k], corners[(k + 1) % 4]);
        [0.0, 0.2, 0.45, 1.0]
            .iter()
            .map(|&t| at(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)))
            .collect()
    };
    let mut input = CurvesInput::new((0..4).map(side).collect());
    input.samples = [12, 9];
    let fitted = build(&input, &Settings::default()).unwrap();
    let n = e1.cross(e2).normalize();
    let worst = limit_error(&fitted, &|p| (p - o).dot(n));
    assert!(worst <= 1e-12, "{worst}");
    assert_valid(&fitted, n);
    assert_eq!(fitted.mesh.num_faces(), 12 * 9);
    assert_eq!(fitted.mesh.corners().len(), 4);
}

/// `z = x² − y²` over [-1, 1]²: boundaries sampled from it.
fn saddle(n: usize, samples: usize) -> CurvesInput {
    let mut input = square(&|x, y| x * x - y * y, n);
    input.samples = [samples, samples];
    input
}

/// The cylinder `y² + z² = 1` over x ∈ [-1, 1], angle ∈ [-50°, 50°] from +z.
fn cylinder(n: usize, samples: usize) -> CurvesInput {
    let a = 50f64.to_radians();
    let arc = |x: f64, from: f64, to: f64| -> Vec<[f64; 3]> {
        (0..=n)
            .map(|i| {
                let t = from + (to - from) * i as f64 / n as f64;
                [x, crate::math::sin(t), crate::math::cos(t)]
            })
            .collect()
    };
    let straight = |t: f64, x0: f64, x1: f64| -> Vec<[f64; 3]> {
        (0..=n)
            .map(|i| {
                let x = x0 + (x1 - x0) * i as f64 / n as f64;
                [x, crate::math::sin(t), crate::math::cos(t)]
            })
            .collect()
    };
    let mut input = CurvesInput::new(vec![
        arc(-1.0, -a, a),
        straight(a, -1.0, 1.0),
        arc(1.0, a, -a),
        straight(-a, 1.0, -1.0),
    ]);
    input.samples = [samples, samples];
    input
}

#[test]
fn saddle_and_cylinder_errors_and_their_trend() {
    let mut lines = Vec::new();
    for samples in [8, 16, 32] {
        let f = build(&saddle(16, samples), &Settings::default()).unwrap();
        let e_saddle = limit_error(&f, &|p| p.z - (p.x * p.x - p.y * p.y));
        assert_valid(&f, DVec3::Z);
        let c = build(&cylinder(16, samples), &Settings::default()).unwrap();
        let e_cyl = limit_error(&c, &|p| (p.y * p.y + p.z * p.z).sqrt() - 1.0);
        // Its boundary runs clockwise seen from +z: the normal is -z.
        assert_valid(&c, -DVec3::Z);
        lines.push((samples, e_saddle, e_cyl));
        // The blend is neither the saddle nor the cylinder (a convex combination of boundary
        // points falls inside the cylinder): bounds, not convergence.
        assert!(
            e_saddle < 0.03 && e_cyl < 0.1,
            "{samples}: {e_saddle} {e_cyl}"
        );
    }
    for (s, a, b) in &lines {
        println!("samples {s}x{s}: saddle max error {a:.3e}, cylinder {b:.3e} (x diagonal)");
    }
}
