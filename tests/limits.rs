//! Documented ceilings on sizes a caller controls, checked before allocating: absurd
//! requests to the mesh constructor, the refiner and the OBJ reader are refused with a
//! specific error and message (and, through the C API, no output), without allocating what
//! they ask for (a test that tried would run out of memory instead of passing).

use std::ptr;

use profsubd::ffi::error::last_error;
use profsubd::ffi::evaluator::{profsubd_evaluator_free, profsubd_evaluator_new};
use profsubd::ffi::mesh::{profsubd_mesh, profsubd_mesh_desc, profsubd_mesh_new};
use profsubd::ffi::mesh_io::profsubd_mesh_read_obj;
use profsubd::ffi::refine::profsubd_refine_uniform;
use profsubd::ffi::status::profsubd_status::*;
use profsubd::ffi::tessellate::profsubd_tessellation_new_uniform;
use profsubd::io::obj::{read_obj_file, MAX_OBJ_BYTES};
use profsubd::refine::{refine_uniform, MAX_LEVEL, MAX_REFINED_FACE_INDICES};
use profsubd::tessellate::{tessellate, Rate, TessellateOptions, MAX_CELLS, MAX_RATE};
use profsubd::{Error, Evaluator, Mesh, MeshParts, SubdivOptions};

/// An `n` x `n` grid of quads.
fn grid(n: u32) -> Mesh {
    let positions = (0..=n)
        .flat_map(|j| (0..=n).map(move |i| glam::DVec3::new(i as f64, j as f64, 0.0)))
        .collect();
    let mut face_indices = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let v = j * (n + 1) + i;
            face_indices.extend([v, v + 1, v + n + 2, v + n + 1]);
        }
    }
    Mesh::from_parts(MeshParts {
        positions,
        face_sizes: vec![4; (n * n) as usize],
        face_indices,
        ..Default::default()
    })
    .unwrap()
}

#[test]
fn refinement_above_its_ceilings_is_refused_before_allocating() {
    let options = SubdivOptions::default();
    // 4096 quads: level 7 would need 4096 * 4^7 * 4 = 2^28 face indices (2^26 allowed).
    let mesh = grid(64);
    for level in [7, MAX_LEVEL] {
        match refine_uniform(&mesh, &options, level) {
            Err(Error::InvalidArgument(m)) => assert!(m.contains("face"), "{m}"),
            other => panic!("level {level}: {other:?}"),
        }
    }
    assert!(matches!(
        refine_uniform(&grid(1), &options, MAX_LEVEL + 1),
        Err(Error::InvalidArgument(_))
    ));
    // The largest allowed stays allowed: one quad at level 8 is 2^18 face indices.
    const { assert!(4 << (2 * MAX_LEVEL) <= MAX_REFINED_FACE_INDICES) };
    assert_eq!(
        refine_uniform(&grid(1), &options, MAX_LEVEL)
            .unwrap()
            .num_faces(),
        1 << (2 * MAX_LEVEL)
    );
    // Through the C API: a status, a message, and no output.
    let handle = profsubd::ffi::mesh::new_mesh_handle(mesh);
    let mut out: *mut profsubd_mesh = ptr::null_mut();
    let s = unsafe { profsubd_refine_uniform(handle, ptr::null(), 8, &mut out) };
    assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
    assert!(out.is_null() && !last_error().is_empty());
    unsafe { profsubd::ffi::mesh::profsubd_mesh_free(handle) };
}

/// A tessellation whose rates add up to more than `MAX_CELLS` cells: refused before building
/// (four quads at the largest rate would be 2^26 cells, gigabytes), through Rust and C.
#[test]
fn a_tessellation_above_its_cell_ceiling_is_refused_before_building() {
    let mesh = grid(2);
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    const { assert!(4 * (MAX_RATE as u64).pow(2) > MAX_CELLS) };
    let options = TessellateOptions {
        rate: Rate::Uniform(MAX_RATE),
        ..TessellateOptions::default()
    };
    let t0 = std::time::Instant::now();
    match tessellate(&ev, &options) {
        Err(Error::InvalidArgument(m)) => assert!(m.contains("cells"), "{m}"),
        other => panic!("{:?}", other.map(|t| t.num_vertices())),
    }
    println!("4 quads at rate {MAX_RATE}: refused in {:?}", t0.elapsed());
    // The same request through C: a status, a message, and no output.
    let m = profsubd::ffi::mesh::new_mesh_handle(mesh);
    let mut handle = ptr::null_mut();
    assert_eq!(
        unsafe { profsubd_evaluator_new(m, ptr::null(), &mut handle) },
        PROFSUBD_OK
    );
    let mut out = ptr::null_mut();
    let s = unsafe { profsubd_tessellation_new_uniform(handle, MAX_RATE, 0, &mut out) };
    assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT);
    assert!(out.is_null() && last_error().contains("cells"));
    unsafe {
        profsubd_evaluator_free(handle);
        profsubd::ffi::mesh::profsubd_mesh_free(m);
    }
}

#[test]
fn mesh_counts_above_int32_max_are_refused_before_reading_the_arrays() {
    // Tiny arrays with absurd counts: the library must refuse from the counts alone.
    let positions = [0.0f64; 3];
    let sizes = [3u32];
    let indices = [0u32; 3];
    for (nv, nf, ni) in [
        (usize::MAX, 1, 3),
        (1, 1usize << 40, 3),
        (1, 1, i32::MAX as usize + 1),
    ] {
        let desc = profsubd_mesh_desc {
            struct_size: std::mem::size_of::<profsubd_mesh_desc>(),
            positions: positions.as_ptr(),
            num_vertices: nv,
            face_sizes: sizes.as_ptr(),
            num_faces: nf,
            face_indices: indices.as_ptr(),
            num_face_indices: ni,
            crease_vertices: ptr::null(),
            crease_sharpness: ptr::null(),
            num_creases: 0,
            corner_vertices: ptr::null(),
            corner_sharpness: ptr::null(),
            num_corners: 0,
            hole_faces: ptr::null(),
            num_holes: 0,
        };
        let mut out: *mut profsubd_mesh = ptr::null_mut();
        let s = unsafe { profsubd_mesh_new(&desc, &mut out) };
        assert_eq!(s, PROFSUBD_ERROR_INVALID_ARGUMENT, "{nv} {nf} {ni}");
        assert!(out.is_null());
        assert!(
            last_error().contains("the limit is 2147483647"),
            "{}",
            last_error()
        );
    }
}

#[test]
fn an_obj_file_above_the_ceiling_is_refused_without_reading_it() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.obj");
    // A sparse file: no disk space, and reading it would take a GiB of memory.
    std::fs::File::create(&path)
        .unwrap()
        .set_len(MAX_OBJ_BYTES + 1)
        .unwrap();
    match read_obj_file(&path) {
        Err(Error::Parse { message, .. }) => assert!(message.contains("limit"), "{message}"),
        other => panic!("{other:?}"),
    }
    let c_path = std::ffi::CString::new(path.to_str().unwrap()).unwrap();
    let mut out: *mut profsubd_mesh = ptr::null_mut();
    let s = unsafe { profsubd_mesh_read_obj(c_path.as_ptr(), &mut out) };
    assert_eq!(s, PROFSUBD_ERROR_PARSE);
    assert!(out.is_null() && last_error().contains("limit"));
}

/// Curve point counts above `MAX_CURVE_POINTS`: refused through Rust and, before the
/// caller's array is read, through C; and a memory budget on every construction, the
/// evaluator and the refiner, refused before allocating (the time printed, not asserted).
#[test]
fn curve_points_and_the_memory_budget_are_refused_before_allocating() {
    use profsubd::curves::curve::MAX_CURVE_POINTS;
    use profsubd::ffi::revolve::profsubd_revolve;
    use profsubd::{revolve, Control, RevolveInput, Settings};

    let too_many: Vec<[f64; 2]> = (0..=MAX_CURVE_POINTS).map(|i| [1.0, i as f64]).collect();
    match revolve::build(&RevolveInput::new(too_many), &Settings::default()) {
        Err(Error::LimitExceeded(m)) => assert!(m.contains("above the limit of 1048576"), "{m}"),
        other => panic!("{:?}", other.map(|f| f.fit)),
    }
    // A 2-point array announced as 2^40 points: refused without reading past it.
    let two = [1.0, 0.0, 1.0, 1.0];
    let mut out = ptr::null_mut();
    let s = unsafe { profsubd_revolve(two.as_ptr(), 1 << 40, ptr::null(), &mut out) };
    assert_eq!(s, PROFSUBD_ERROR_LIMIT_EXCEEDED);
    assert!(out.is_null());
    assert!(
        last_error().contains("1099511627776 points"),
        "{}",
        last_error()
    );

    // A 1 MiB budget against a 1024 x 1024 revolution (about 170 MB to fit).
    let mut big = RevolveInput::new(vec![[1.0, 0.0], [1.4, 0.8], [1.3, 2.0], [0.9, 3.0]]);
    (big.samples_profile, big.samples_around) = (1024, 1024);
    let settings = Settings {
        control: Control::NONE.with_memory_budget(Some(1 << 20)),
        ..Settings::default()
    };
    let t = std::time::Instant::now();
    match revolve::build(&big, &settings) {
        Err(Error::LimitExceeded(m)) => {
            assert!(
                m.contains("the fit of 1024 × 1024 samples needs about"),
                "{m}"
            )
        }
        other => panic!("{:?}", other.map(|f| f.fit)),
    }
    println!("1024 x 1024 revolution refused in {:?}", t.elapsed());
    // Evaluator and refinement of a 256 x 256 grid under 1 MiB.
    let mesh = grid(256);
    let control = Control::NONE.with_memory_budget(Some(1 << 20));
    let t = std::time::Instant::now();
    match profsubd::Evaluator::with_control(&mesh, &SubdivOptions::default(), &control) {
        Err(Error::LimitExceeded(m)) => {
            assert!(m.contains("the evaluator of a mesh of 65536 faces"), "{m}")
        }
        other => panic!("{:?}", other.map(drop)),
    }
    let e = t.elapsed();
    let t = std::time::Instant::now();
    match profsubd::refine::refine_uniform_with(
        &mesh,
        &SubdivOptions::default(),
        2,
        profsubd::refine::VertexOrder::VerticesFirst,
        &control,
    ) {
        Err(Error::LimitExceeded(m)) => assert!(m.contains("refining 65536 faces 2 times"), "{m}"),
        other => panic!("{:?}", other.map(drop)),
    }
    println!(
        "evaluator refused in {e:?}, refinement in {:?}",
        t.elapsed()
    );
}

/// Every construction's sizes above their ceilings (`MAX_SAMPLES` per direction,
/// `MAX_SAMPLE_PRODUCT` together, a blend's GBS level, a shell's crust level): refused with
/// `InvalidArgument` naming the size, before sampling (a 10^5 × 10^5 request would need
/// terabytes; the time printed, not asserted).
#[test]
fn every_construction_refuses_sizes_above_its_ceilings() {
    use profsubd::construct::blend::{self, BlendInput};
    use profsubd::construct::settings::parse_json;
    use profsubd::construct::shell::{self, OffsetSettings, ShellInput};
    use profsubd::construct::{curves, profile, revolve, sweep};
    use profsubd::{CurvesInput, Fitted, ProfileInput, RevolveInput, Settings, SweepInput};
    use std::path::Path;

    let example = |p: &str| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("examples")
            .join(p);
        (std::fs::read_to_string(&path).unwrap(), path)
    };
    let huge = 100_000;
    let refused = |what: &str, result: Result<Fitted, Error>, words: &str| match result {
        Err(Error::InvalidArgument(m)) => assert!(m.contains(words), "{what}: {m}"),
        other => panic!("{what}: {:?}", other.map(|f| f.fit)),
    };
    let t = std::time::Instant::now();
    let (text, path) = example("profiles/bottle.json");
    let (mut i, s) = ProfileInput::from_json(&text, &path).unwrap();
    i.along = huge;
    refused(
        "profile",
        profile::build(&i, &s),
        "along = 100000 must be between 1 and 4096",
    );
    (i.along, i.around) = (4096, 4096);
    refused(
        "profile",
        profile::build(&i, &s),
        "4096 × 4096 exceeds 4000000",
    );
    let (text, path) = example("sweeps/wine_glass.json");
    let (mut i, s) = RevolveInput::from_json(&text, &path).unwrap();
    (i.samples_profile, i.samples_around) = (huge as usize, huge as usize);
    refused(
        "revolve",
        revolve::build(&i, &s),
        "samples_profile = 100000",
    );
    let (text, path) = example("sweeps/handrail.json");
    let (mut i, s) = SweepInput::from_json(&text, &path).unwrap();
    i.samples_trajectory = huge as usize;
    refused("sweep", sweep::build(&i, &s), "samples_trajectory = 100000");
    let (text, path) = example("curves/bonnet.json");
    let (mut i, s) = CurvesInput::from_json(&text, &path).unwrap();
    i.samples = [2000, 2001];
    refused("curves", curves::build(&i, &s), "samples = [2000, 2001]");
    let (text, path) = example("blends/tee.json");
    let (mut i, s): (BlendInput, Settings) = parse_json(&text, &path).unwrap();
    i.gbs_level = 1000;
    refused("blend", blend::build(&i, &s), "gbs_level 1000 is outside");
    let mesh =
        read_obj_file(&Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/profiles/vase.obj"))
            .unwrap()
            .mesh;
    let mut offset = OffsetSettings::new(0.01);
    offset.level = 1000;
    let input = ShellInput {
        mesh,
        offset,
        tolerance: None,
    };
    refused(
        "shell",
        shell::build(&input, &Settings::default()),
        "crust level 1000 is above the maximum 6",
    );
    println!(
        "six constructions' absurd sizes refused in {:?}",
        t.elapsed()
    );
}

/// The fold check's ceilings: base lattices above `MAX_FOLD_SAMPLES` refused from the counts
/// before any evaluation or callback (through Rust and C, the output untouched), exactly at
/// the ceiling accepted (cancelled at its first callback, which comes after the checks), and
/// one face's adaptive halving stopped at `MAX_FACE_SAMPLES` (the time printed, not asserted).
#[test]
fn fold_check_work_above_its_ceilings_is_refused() {
    use profsubd::eval::folds::{
        find_folds, find_folds_with, FoldSettings, MAX_FACE_SAMPLES, MAX_FOLD_SAMPLES,
    };
    use profsubd::ffi::folds::{profsubd_check_folds, profsubd_fold_settings};
    use profsubd::Control;

    // 65,536 faces at 1025 x 1025: 6.9e10 evaluations asked.
    let big = Evaluator::new(&grid(256), &SubdivOptions::default()).unwrap();
    let absurd = FoldSettings {
        samples_per_edge: 1025,
        adaptive_depth: 16,
        ..FoldSettings::default()
    };
    let t = std::time::Instant::now();
    match find_folds(&big, &absurd) {
        Err(Error::LimitExceeded(m)) => assert!(
            m.contains(
                "65536 parametric faces at 1025 × 1025 samples makes 68853760000 limit evaluations"
            ) && m.contains(&format!("above the limit of {MAX_FOLD_SAMPLES}")),
            "{m}"
        ),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
    println!(
        "fold check of 65536 faces at 1025 x 1025 refused in {:?}",
        t.elapsed()
    );
    unsafe {
        let m = profsubd::ffi::mesh::new_mesh_handle(grid(256));
        let mut ev = ptr::null_mut();
        assert_eq!(profsubd_evaluator_new(m, ptr::null(), &mut ev), PROFSUBD_OK);
        let settings = profsubd_fold_settings {
            samples_per_edge: 1025,
            adaptive_depth: 16,
            refine_turn_deg: 45.0,
        };
        let sentinel = 0x5eed as *mut _;
        let mut out = sentinel;
        let t = std::time::Instant::now();
        let s = profsubd_check_folds(ev, &settings, &mut out);
        println!("the same through C refused in {:?}", t.elapsed());
        assert_eq!(s, PROFSUBD_ERROR_LIMIT_EXCEEDED);
        assert_eq!(out, sentinel);
        assert!(last_error().contains("68853760000"), "{}", last_error());
        profsubd_evaluator_free(ev);
        profsubd::ffi::mesh::profsubd_mesh_free(m);
    }

    // 64 faces: at 1024 x 1024 exactly MAX_FOLD_SAMPLES (accepted: the first callback comes
    // after the checks and cancels), at 1025 x 1025 above (refused, no callback).
    const { assert!(64 * 1024 * 1024 == MAX_FOLD_SAMPLES) };
    let small = Evaluator::new(&grid(8), &SubdivOptions::default()).unwrap();
    let calls = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let seen = calls.clone();
    let cancel_at_once = Control::NONE.with_progress(move |_| {
        seen.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        true
    });
    let at = |n: usize| FoldSettings {
        samples_per_edge: n,
        adaptive_depth: 0,
        ..FoldSettings::default()
    };
    assert!(matches!(
        find_folds_with(&small, &at(1024), &cancel_at_once),
        Err(Error::Cancelled(_))
    ));
    match find_folds_with(&small, &at(1025), &cancel_at_once) {
        Err(Error::LimitExceeded(m)) => assert!(m.contains("67240000 limit evaluations"), "{m}"),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
    assert_eq!(calls.load(std::sync::atomic::Ordering::Relaxed), 1);

    // One face refined wherever its normal turns at all: (8 · 2^16 + 1)^2 samples asked of a
    // curved face, stopped at MAX_FACE_SAMPLES.
    let curved = Evaluator::new(&paraboloid(4), &SubdivOptions::default()).unwrap();
    let everywhere = FoldSettings {
        samples_per_edge: 9,
        adaptive_depth: 16,
        refine_turn_deg: 1e-9,
    };
    let t = std::time::Instant::now();
    match find_folds(&curved, &everywhere) {
        Err(Error::LimitExceeded(m)) => assert!(
            m.contains(&format!(
                "parametric face 0 needs more than {MAX_FACE_SAMPLES} samples at 9 × 9 with adaptive depth 16"
            )),
            "{m}"
        ),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
    println!(
        "a face's adaptive halving stopped at {MAX_FACE_SAMPLES} samples after {:?}",
        t.elapsed()
    );
}

/// An `n` x `n` grid of quads lifted onto the paraboloid `z = (x² + y²) / n²`: curved
/// everywhere, its patches regular (cheap to evaluate at any depth).
fn paraboloid(n: u32) -> Mesh {
    let mesh = grid(n);
    let positions = (mesh.positions().iter())
        .map(|p| glam::DVec3::new(p.x, p.y, (p.x * p.x + p.y * p.y) / f64::from(n * n)))
        .collect();
    Mesh::from_parts(MeshParts {
        positions,
        face_sizes: mesh.face_sizes().to_vec(),
        face_indices: mesh.face_indices().to_vec(),
        ..Default::default()
    })
    .unwrap()
}
