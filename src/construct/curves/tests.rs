use super::preimage::crossings;
use super::*;

/// `n + 1` points from `a` to `b` lifted by `f`.
pub(super) fn line(
    a: [f64; 2],
    b: [f64; 2],
    n: usize,
    f: &dyn Fn(f64, f64) -> f64,
) -> Vec<[f64; 3]> {
    (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let (x, y) = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
            [x, y, f(x, y)]
        })
        .collect()
}

pub(super) fn square(f: &dyn Fn(f64, f64) -> f64, n: usize) -> CurvesInput {
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

use crate::eval::folds::{find_folds, FoldSettings};
use crate::eval::Evaluator;
use crate::mesh::validate::check;

/// Largest distance of the limit surface (5 × 5 points per face) from `f`, over the
/// diagonal, and the fitted result.
pub(super) fn limit_error(fitted: &Fitted, f: &dyn Fn(DVec3) -> f64) -> f64 {
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

/// Valid open manifold (see [`assert_manifold`]), no folds, every face's normal along
/// `normal` (the projection plane's).
pub(super) fn assert_valid(fitted: &Fitted, normal: DVec3) {
    assert_manifold(fitted);
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

/// Valid open manifold, one boundary loop, consistently oriented, fit within tolerance.
pub(super) fn assert_manifold(fitted: &Fitted) {
    let r = check(&fitted.mesh);
    assert!(
        r.is_manifold() && r.is_consistently_oriented() && !r.is_closed(),
        "{r:?}"
    );
    assert_eq!(r.num_boundary_loops, 1);
    assert!(fitted.fit.residual <= 1e-10 * fitted.mesh.bounding_box_diagonal());
}

/// The point `o + a e1 + b e2` of the tilted plane of [`tilted_quadrilateral`].
pub(super) fn tilted_plane(a: f64, b: f64) -> [f64; 3] {
    let (o, e1, e2) = TILTED;
    (o + e1 * a + e2 * b).to_array()
}

/// Origin and spanning vectors of the tilted plane.
pub(super) const TILTED: (DVec3, DVec3, DVec3) = (
    DVec3::new(0.3, -0.2, 1.0),
    DVec3::new(2.0, 1.0, 0.5),
    DVec3::new(-0.4, 1.0, 1.5),
);

/// A skew quadrilateral in a tilted plane, straight sides with uneven point spacing, 12 × 9.
pub(super) fn tilted_quadrilateral() -> CurvesInput {
    let corners = [(0.0, 0.0), (1.0, 0.1), (1.2, 0.9), (-0.1, 1.1)];
    let side = |k: usize| -> Vec<[f64; 3]> {
        let (a, b) = (corners[k], corners[(k + 1) % 4]);
        [0.0, 0.2, 0.45, 1.0]
            .iter()
            .map(|&t| tilted_plane(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)))
            .collect()
    };
    let mut input = CurvesInput::new((0..4).map(side).collect());
    input.samples = [12, 9];
    input
}

#[test]
fn planar_quadrilateral_gives_a_planar_limit() {
    let input = tilted_quadrilateral();
    let fitted = build(&input, &Settings::default()).unwrap();
    let (o, e1, e2) = TILTED;
    let n = e1.cross(e2).normalize();
    let worst = limit_error(&fitted, &|p| (p - o).dot(n));
    assert!(worst <= 1e-12, "{worst}");
    assert_valid(&fitted, n);
    assert_eq!(fitted.mesh.num_faces(), 12 * 9);
    assert_eq!(fitted.mesh.corners().len(), 4);
}

/// `z = x² − y²` over [-1, 1]²: boundaries sampled from it.
pub(super) fn saddle(n: usize, samples: usize) -> CurvesInput {
    let mut input = square(&|x, y| x * x - y * y, n);
    input.samples = [samples, samples];
    input
}

/// The cylinder `y² + z² = 1` over x ∈ [-1, 1], angle ∈ [-50°, 50°] from +z.
pub(super) fn cylinder(n: usize, samples: usize) -> CurvesInput {
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
pub(super) fn saddle_and_cylinder_errors_and_their_trend() {
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

/// The bonnet-like design surface of the tests and the example.
pub(super) fn bonnet_z(x: f64, y: f64) -> f64 {
    0.3 * (1.0 - x * x / 4.0) + 0.15 * (1.0 - y * y)
}

/// A bonnet-like patch over [-1.5, 1.5] × [-1, 1] with two raised character lines along x at
/// y ≈ ±0.5, one inside the boundary, one crossing it.
pub(super) fn bonnet(samples: usize) -> CurvesInput {
    let mut input = square(&bonnet_z, 12);
    for c in input.boundary.iter_mut() {
        for p in c.iter_mut() {
            p[0] *= 1.5;
            p[2] = bonnet_z(p[0], p[1]);
        }
    }
    let character = |y0: f64, x0: f64, x1: f64| -> Vec<[f64; 3]> {
        (0..=10)
            .map(|i| {
                let x = x0 + (x1 - x0) * i as f64 / 10.0;
                let y = y0 - 0.05 * x;
                [x, y, bonnet_z(x, y) + 0.04]
            })
            .collect()
    };
    input.interior = vec![character(0.5, -1.2, 1.2), character(-0.5, -1.8, 1.3)];
    input.samples = [samples, samples];
    input
}

/// Closest distance from `p` to the limit surface of `faces` of `ev`, by Gauss–Newton from
/// each face's centre, kept inside the face.
/// The limit surface at grid vertex `v`: a corner of the first face holding it.
pub(super) fn limit_at_grid_vertex(ev: &Evaluator, faces: &[[u32; 4]], v: usize) -> DVec3 {
    let f = faces.iter().position(|q| q.contains(&(v as u32))).unwrap();
    let corner = faces[f].iter().position(|&w| w == v as u32).unwrap();
    let (u, w) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][corner];
    ev.evaluate(f as u32, u, w).unwrap().position
}

pub(super) fn distance_to_surface(ev: &Evaluator, faces: &[u32], p: DVec3) -> f64 {
    let mut best = f64::INFINITY;
    for &f in faces {
        let mut uv = DVec2::splat(0.5);
        for _ in 0..30 {
            let s = ev.evaluate(f, uv.x, uv.y).unwrap();
            let r = s.position - p;
            let (a, b, c) = (s.du.dot(s.du), s.du.dot(s.dv), s.dv.dot(s.dv));
            let (g0, g1) = (s.du.dot(r), s.dv.dot(r));
            let det = a * c - b * b;
            if det <= 0.0 {
                break;
            }
            let step = DVec2::new((c * g0 - b * g1) / det, (a * g1 - b * g0) / det);
            uv = (uv - step).clamp(DVec2::ZERO, DVec2::ONE);
        }
        best = best.min(ev.evaluate(f, uv.x, uv.y).unwrap().position.distance(p));
    }
    best
}

#[test]
fn interior_curves_lie_on_the_limit_surface() {
    let mut rates = Vec::new();
    for samples in [8, 16, 32] {
        let input = bonnet(samples);
        let settings = Settings::default();
        let blend = input.blend(&settings).unwrap();
        let grid = input.grid(&blend);
        // Unguarded: `build` refuses the folded 16 x 16 and 32 x 32 fits, measured here.
        let fitted = fit_unguarded(&input);
        let m = &fitted.mesh;
        let diagonal = m.bounding_box_diagonal();
        let ev = Evaluator::new(m, &m.options().resolve()).unwrap();
        // Interior curves fold the blend's surface as the samples grow (README): counted.
        assert_manifold(&fitted);
        let folds = fitted.surface_report().unwrap().folded_faces;
        // Vertices on an interior pre-image: their data point is the curve point, and the limit
        // there is it.
        let mut on_curve = vec![0usize; 2];
        for (v, &uv) in grid.uv.iter().enumerate() {
            for (c, curve) in blend.interior.iter().enumerate() {
                for piece in &curve.pieces {
                    let mut found = Vec::new();
                    crossings(piece, 0, uv.x, &mut found);
                    crossings(piece, 1, uv.y, &mut found);
                    if let Some(&(_, s, _)) = found.iter().find(|h| h.0 == uv.y || h.0 == uv.x) {
                        on_curve[c] += 1;
                        assert!(fitted.targets[v].distance(curve.point(s)) <= 1e-15 * diagonal);
                        let p = limit_at_grid_vertex(&ev, &grid.faces, v);
                        assert!(p.distance(curve.point(s)) <= 1e-10 * diagonal);
                    }
                }
            }
        }
        // Each character line runs across more than half the columns.
        assert!(on_curve.iter().all(|&n| 2 * n >= samples), "{on_curve:?}");
        // Between the interpolated points: dense samples of each curve's pre-image.
        let mut worst = 0.0f64;
        for curve in &blend.interior {
            for (uv, p) in dense_samples(curve) {
                let near: Vec<u32> = (0..grid.faces.len() as u32)
                    .filter(|&f| {
                        let c = grid.faces[f as usize].map(|v| grid.uv[v as usize]);
                        let lo = c.iter().fold(DVec2::INFINITY, |a, b| a.min(*b));
                        let hi = c.iter().fold(DVec2::NEG_INFINITY, |a, b| a.max(*b));
                        uv.cmpge(lo - 0.5 / samples as f64).all()
                            && uv.cmple(hi + 0.5 / samples as f64).all()
                    })
                    .collect();
                worst = worst.max(distance_to_surface(&ev, &near, p));
            }
        }
        rates.push((samples, worst / diagonal, on_curve, folds));
    }
    for (s, w, n, folds) in &rates {
        println!("bonnet {s}x{s}: vertices on the interior curves {n:?}; max distance of the curves from the limit between them {w:.3e} x diagonal; folded faces {folds}");
    }
    assert!(rates[2].1 < rates[0].1);
}

/// Four points per piece segment of an interior curve: (pre-image, curve point).
pub(super) fn dense_samples(curve: &Interior) -> Vec<(DVec2, DVec3)> {
    let mut out = Vec::new();
    for piece in &curve.pieces {
        for w in piece.windows(2) {
            for k in 0..4 {
                let t = k as f64 / 4.0;
                let uv = w[0].uv.lerp(w[1].uv, t);
                out.push((uv, curve.point(w[0].s + t * (w[1].s - w[0].s))));
            }
        }
    }
    out
}

/// A dome z = 1 − (x² + y²)/4 over the triangle of circumradius 1.5 with a corner on +y.
pub(super) fn dome(x: f64, y: f64) -> f64 {
    1.0 - 0.25 * (x * x + y * y)
}

/// Three straight sides of [`dome`]'s triangle, 8 points each, as a 3-sided input.
pub(super) fn dome_triangle() -> CurvesInput {
    let corner = |k: usize| {
        let a = (90.0 + 120.0 * k as f64).to_radians();
        [1.5 * crate::math::cos(a), 1.5 * crate::math::sin(a)]
    };
    CurvesInput::new(
        (0..3)
            .map(|k| line(corner(k), corner((k + 1) % 3), 8, &dome))
            .collect(),
    )
}

#[test]
fn three_sided_open_corners_crossing_and_inside_curves_give_valid_surfaces() {
    let tri = CurvesInput {
        samples: [10, 10],
        ..dome_triangle()
    };
    let f = build(&tri, &Settings::default()).unwrap();
    assert_valid(&f, DVec3::Z);
    // 3 quads of 5 × 5, the centroid of valence 3, the triangle's corners tagged.
    assert_eq!(f.mesh.num_faces(), 75);
    assert_eq!(f.mesh.corners().len(), 3);
    let r = check(&f.mesh);
    assert!(r.valences.get(&3).copied().unwrap_or(0) >= 1);
    // The triangle's corners are the curves' corners.
    for &c in f.mesh.corners().iter().map(|c| &c.vertex) {
        let p = f.targets[c as usize];
        assert!(
            (0..3).any(|k| DVec3::from(tri.boundary[k][0]).distance(p) < 1e-14),
            "{p}"
        );
    }

    // Open corners: each saddle side shortened by 10 % at both ends.
    let mut open = saddle(16, 12);
    // The best-fit plane of the shortened saddle sides is not the xy plane: give it.
    open.projection = Projection::Normal([0.0, 0.0, 1.0]);
    for c in open.boundary.iter_mut() {
        let (a, b) = (DVec3::from(c[0]), DVec3::from(c[c.len() - 1]));
        let (a2, b2) = (a.lerp(b, 0.1), a.lerp(b, 0.9));
        *c = line([a2.x, a2.y], [b2.x, b2.y], 10, &|x, y| x * x - y * y);
    }
    let f = build(&open, &Settings::default()).unwrap();
    assert_valid(&f, DVec3::Z);
    // The corner data point is the middle of the gap.
    let mid =
        (DVec3::from(open.boundary[0][0]) + DVec3::from(*open.boundary[3].last().unwrap())) * 0.5;
    assert!(f.targets[0].distance(mid) < 1e-14, "{} {mid}", f.targets[0]);

    // One interior curve crossing the boundary (clipped), one inside.
    let mut crossing = saddle(16, 12);
    crossing.projection = Projection::Normal([0.0, 0.0, 1.0]);
    crossing.interior = vec![
        line([-1.6, -0.3], [0.4, 0.5], 8, &|x, y| x * x - y * y + 0.1),
        line([-0.3, -0.6], [0.5, 0.2], 6, &|x, y| x * x - y * y - 0.05),
    ];
    let b = crossing.blend(&Settings::default()).unwrap();
    // The crossing curve is clipped at u = 0 (the left side).
    let first = b.interior[0].pieces[0][0];
    assert!(first.uv.x.abs() < 1e-6, "{first:?}");
    let f = fit_unguarded(&crossing);
    assert_manifold(&f);
    let folded = f.surface_report().unwrap().folded_faces;
    println!("saddle 12x12 with a crossing and an inside curve: folded faces {folded}");
    // Folded, so `build` refuses it.
    assert!(folded > 0);
    assert!(fold_refusal(&crossing).contains(&format!("would fold in {folded} faces")));
}

/// The fit `build` makes, without its fold guard.
pub(super) fn fit_unguarded(input: &CurvesInput) -> Fitted {
    let settings = Settings::default();
    let (parts, design) = input.cage(&settings).unwrap();
    Fitted::fit(parts, &settings, design).unwrap()
}

/// The message with which `build` refuses `input`'s folded surface.
fn fold_refusal(input: &CurvesInput) -> String {
    match build(input, &Settings::default()) {
        Err(Error::InvalidArgument(m)) if m.contains("would fold") => m,
        other => panic!("expected a fold refusal, got {:?}", other.map(|_| ())),
    }
}

#[test]
fn folded_blends_are_refused_naming_the_faces() {
    // The bonnet at tau = 2, 8 x 8: fold-free, returned.
    assert_valid(&build(&bonnet(8), &Settings::default()).unwrap(), DVec3::Z);
    // 16 x 16: the unguarded fit folds; build names its folded faces, where, and what to do.
    let input = bonnet(16);
    let f = fit_unguarded(&input);
    let ev = Evaluator::new(&f.mesh, &f.mesh.options().resolve()).unwrap();
    let folds = find_folds(&ev, &FoldSettings::default()).unwrap();
    let faces = folds.folded_face_indices();
    assert!(!faces.is_empty());
    let m = fold_refusal(&input);
    assert!(
        m.starts_with(&format!(
            "curves (2 interior, tau = 2, 16 x 16 samples): the fitted limit surface would \
             fold in {} faces ({}",
            faces.len(),
            faces[0]
        )),
        "{m}"
    );
    let (face, ..) = folds.worst_at.unwrap();
    assert!(m.contains(&format!("in face {face}, near (")), "{m}");
    assert!(m.ends_with("; fewer samples or another tau give another layout"));
}

fn message(f: &dyn Fn(&mut CurvesInput)) -> String {
    let mut input = saddle(4, 4);
    f(&mut input);
    match build(&input, &Settings::default()) {
        Err(Error::InvalidArgument(m)) => m,
        other => panic!(
            "expected an error, got {:?}",
            other.map(|f| f.targets.len())
        ),
    }
}

#[test]
fn bad_input_gives_specific_errors() {
    assert!(message(&|i| {
        i.boundary.pop();
        i.boundary.pop();
    })
    .contains("3 or 4 curves"));
    assert!(message(&|i| i.boundary[1] = vec![[1.0, 0.0, 0.0]])
        .contains("boundary 1: an open curve needs at least 2 points"));
    assert!(message(&|i| i.interior = vec![vec![[0.0, 0.0, 0.0]]])
        .contains("interior 0: an open curve needs at least 2"));
    assert!(message(&|i| i.boundary[2][1][2] = f64::NAN).contains("not finite"));
    assert!(message(&|i| i.tau = -1.0).contains("tau = -1"));
    assert!(message(&|i| i.samples = [0, 4]).contains("samples = [0, 4]"));
    // All curves on one line: no plane.
    assert!(message(&|i| {
        for (k, c) in i.boundary.iter_mut().enumerate() {
            *c = vec![
                [k as f64, 2.0 * k as f64, 0.0],
                [k as f64 + 0.5, 2.0 * k as f64 + 1.0, 0.0],
            ];
        }
    })
    .contains("no plane"));
    // A boundary whose projection crosses itself (a bow tie).
    assert!(message(&|i| {
        i.boundary[1] = line([1.0, -1.0], [-1.0, 1.0], 4, &|_, _| 0.0);
        i.boundary[2] = line([-1.0, 1.0], [1.0, 1.0], 4, &|_, _| 0.0);
        i.boundary[3] = line([1.0, 1.0], [-1.0, -1.0], 4, &|_, _| 0.0);
    })
    .contains("folds over itself"));
    // Projected along a direction in its plane: no area.
    assert!(message(&|i| i.projection = Projection::Normal([0.0, 1.0, 0.0])).contains("no area"));
    assert!(
        message(&|i| i.interior = vec![line([3.0, 3.0], [4.0, 3.0], 3, &|_, _| 0.0)])
            .contains("no part")
    );
    let p = Path::new("in.json");
    let (i, s) = CurvesInput::from_json(
        r#"{"boundary": [[[0,0,0],[1,0,0]],[[1,0,0],[1,1,0]],[[1,1,0],[0,0,0]]], "projection": [0,0,1], "tau": 1.5, "interpolation": "polyline"}"#,
        p,
    )
    .unwrap();
    assert_eq!(i.projection, Projection::Normal([0.0, 0.0, 1.0]));
    assert_eq!(
        (i.tau, s.interpolation),
        (1.5, crate::curves::Interpolation::Polyline)
    );
    let e = CurvesInput::from_json(r#"{"boundary": [], "projection": "up"}"#, p).unwrap_err();
    assert!(e.to_string().contains("\"auto\" or a normal"), "{e}");
    let e =
        CurvesInput::from_json(r#"{"boundary": [], "samples": 4, "curves": []}"#, p).unwrap_err();
    assert!(matches!(e, Error::Parse { .. }));
}
