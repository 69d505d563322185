//! `Evaluator::evaluate_primvar` on every OpenSubdiv regression shape: the positions as a
//! primvar of width 3 give the positions' limit bit for bit; a wider primvar gives each
//! component as the positions give it (whatever lane of the three-at-a-time pass it falls
//! in), an affine function of the positions as that function of their limit (Catmull-Clark
//! reproduces affine functions: every mask sums to one) and a constant as that constant.
#![allow(clippy::disallowed_methods)] // test data only, not compared across machines

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use profsubd::eval::{Evaluator, LimitSample};
use profsubd::io::obj::read_obj_file;
use profsubd::{Error, Mesh};

/// Points on every parametric face with a limit surface: corners (exact vertex limits),
/// inner points and points next to the far corner (deep in the quadtree).
fn points(ev: &Evaluator) -> (Vec<u32>, Vec<f64>, Vec<f64>) {
    let params = [(0.0, 0.0), (1.0 / 3.0, 0.7), (0.999, 0.999)];
    let (mut faces, mut us, mut vs) = (Vec::new(), Vec::new(), Vec::new());
    for face in 0..ev.num_parametric_faces() as u32 {
        if !ev.has_surface(face) {
            continue;
        }
        for &(u, v) in &params {
            faces.push(face);
            us.push(u);
            vs.push(v);
        }
    }
    (faces, us, vs)
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|x| x.to_bits()).collect()
}

/// Component `k` (0 = x) of every sample's position, du and dv.
fn component(samples: &[LimitSample], k: usize) -> [Vec<f64>; 3] {
    [
        samples.iter().map(|s| s.position[k]).collect(),
        samples.iter().map(|s| s.du[k]).collect(),
        samples.iter().map(|s| s.dv[k]).collect(),
    ]
}

/// Column `k` of a primvar result of width `dim`: values, du, dv.
fn column(p: &profsubd::eval::PrimvarSamples, k: usize) -> [Vec<f64>; 3] {
    [&p.values, &p.du, &p.dv].map(|a| a.iter().skip(k).step_by(p.dim).copied().collect())
}

#[test]
fn primvars_follow_the_positions_on_every_shape() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let rows = osd_shapes::index(&dir);
    assert_eq!(rows.len(), 87);
    let mut compared = 0usize;
    for row in &rows {
        let mesh = read_obj_file(&row.path).unwrap().mesh;
        let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
        let (faces, us, vs) = points(&ev);
        let samples = ev.evaluate_many(&faces, &us, &vs).unwrap();
        let what = &row.name;

        let xyz: Vec<f64> = mesh.positions().iter().flat_map(|p| p.to_array()).collect();
        let p3 = ev.evaluate_primvar(&xyz, 3, &faces, &us, &vs).unwrap();
        let flat = |pick: fn(&LimitSample) -> glam::DVec3| -> Vec<f64> {
            samples.iter().flat_map(|s| pick(s).to_array()).collect()
        };
        assert_eq!(bits(&p3.values), bits(&flat(|s| s.position)), "{what}");
        assert_eq!(bits(&p3.du), bits(&flat(|s| s.du)), "{what}");
        assert_eq!(bits(&p3.dv), bits(&flat(|s| s.dv)), "{what}");

        // Width 5: x, 2x - 3z + 1, y | z, 7 (two passes; y and z in other lanes than in the
        // positions).
        let affine = |p: glam::DVec3| 2.0 * p.x - 3.0 * p.z + 1.0;
        let data: Vec<f64> = mesh
            .positions()
            .iter()
            .flat_map(|p| [p.x, affine(*p), p.y, p.z, 7.0])
            .collect();
        let p5 = ev.evaluate_primvar(&data, 5, &faces, &us, &vs).unwrap();
        assert_eq!(p5.values.len(), 5 * faces.len());
        for (col, axis) in [(0, 0), (2, 1), (3, 2)] {
            let got = column(&p5, col);
            let want = component(&samples, axis);
            for k in 0..3 {
                assert_eq!(bits(&got[k]), bits(&want[k]), "{what} column {col}");
            }
        }
        let scale = mesh
            .positions()
            .iter()
            .fold(1.0f64, |m, p| m.max(p.abs().max_element()));
        let [a, adu, adv] = column(&p5, 1);
        let [c, cdu, cdv] = column(&p5, 4);
        for (i, s) in samples.iter().enumerate() {
            let tol = 1e-10 * scale * (1.0 + s.du.length() + s.dv.length());
            let want = [
                affine(s.position),
                2.0 * s.du.x - 3.0 * s.du.z,
                2.0 * s.dv.x - 3.0 * s.dv.z,
            ];
            for (g, w) in [a[i], adu[i], adv[i]].into_iter().zip(want) {
                assert!((g - w).abs() <= tol, "{what} point {i}: {g} vs {w}");
            }
            assert!(
                (c[i] - 7.0).abs() <= 1e-11,
                "{what} point {i}: constant {}",
                c[i]
            );
            assert!(
                cdu[i].abs() <= tol && cdv[i].abs() <= tol,
                "{what} point {i}"
            );
        }
        // One column alone: the same bits as inside the wider primvar.
        let alone: Vec<f64> = data.iter().skip(1).step_by(5).copied().collect();
        let p1 = ev.evaluate_primvar(&alone, 1, &faces, &us, &vs).unwrap();
        assert_eq!(
            column(&p1, 0).map(|c| bits(&c)),
            [a, adu, adv].map(|c| bits(&c)),
            "{what}"
        );
        compared += faces.len();
    }
    eprintln!("compared {compared} points");
}

#[test]
fn primvar_results_do_not_depend_on_the_thread_count() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mesh = read_obj_file(&dir.join("catmark_car.obj")).unwrap().mesh;
    let mut ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
    let (faces, us, vs) = points(&ev);
    let data: Vec<f64> = (0..mesh.num_vertices() * 4)
        .map(|i| (i as f64 * 0.37).sin())
        .collect();
    ev.set_threads(1);
    let one = ev.evaluate_primvar(&data, 4, &faces, &us, &vs).unwrap();
    for threads in [2, 3, 8] {
        ev.set_threads(threads);
        let many = ev.evaluate_primvar(&data, 4, &faces, &us, &vs).unwrap();
        assert_eq!(bits(&many.values), bits(&one.values), "{threads} threads");
        assert_eq!(bits(&many.du), bits(&one.du), "{threads} threads");
        assert_eq!(bits(&many.dv), bits(&one.dv), "{threads} threads");
    }
}

#[test]
fn bad_primvars_are_refused() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let mesh: Mesh = read_obj_file(&dir.join("catmark_cube.obj")).unwrap().mesh;
    let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
    let nv = mesh.num_vertices();
    let good = vec![0.5; 2 * nv];
    let mut nan = good.clone();
    nan[5] = f64::NAN;
    let (f, u, v) = ([0u32], [0.5], [0.5]);
    let cases: [(&[f64], usize, &[u32], String); 5] = [
        (
            &good,
            0,
            &f,
            "primvar width (dim) must be at least 1".into(),
        ),
        (
            &good[1..],
            2,
            &f,
            format!(
                "{} primvar values given; {nv} vertices of width 2 need {}",
                2 * nv - 1,
                2 * nv
            ),
        ),
        (
            &nan,
            2,
            &f,
            "primvar value 5 (vertex 2, component 1) is not finite".into(),
        ),
        (&good, 2, &[999], "point 0: face 999 is out of range".into()),
        (
            &good,
            2,
            &[0, 0],
            "the three lists must have the same length".into(),
        ),
    ];
    for (data, dim, faces, message) in cases {
        match ev.evaluate_primvar(data, dim, faces, &u, &v) {
            Err(Error::InvalidArgument(m)) => assert!(m.contains(&message), "{m} / {message}"),
            other => panic!("{message}: {other:?}"),
        }
    }
    // A constant primvar on the cube is that constant everywhere.
    let p = ev.evaluate_primvar(&good, 2, &f, &u, &v).unwrap();
    assert!(
        p.values.iter().all(|&x| (x - 0.5).abs() < 1e-15),
        "{:?}",
        p.values
    );
}
