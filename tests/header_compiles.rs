//! `include/profsubd.h` compiles warning-free as C99 and as C++17, included alone and twice.

use std::path::Path;
use std::process::Command;

const C_PROGRAM: &str = r#"
#include "profsubd.h"
#include "profsubd.h" /* the include guard makes a second inclusion harmless */
#include <stdio.h>

int main(void) {
    double positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    uint32_t sizes[1] = {4};
    uint32_t indices[4] = {0, 1, 2, 3};
    profsubd_mesh_desc desc = {0};
    profsubd_mesh *mesh = NULL;
    profsubd_options *options = NULL;
    size_t needed = 0;
    profsubd_status status;
    desc.struct_size = sizeof desc;
    desc.positions = positions;
    desc.num_vertices = 4;
    desc.face_sizes = sizes;
    desc.num_faces = 1;
    desc.face_indices = indices;
    desc.num_face_indices = 4;
    status = profsubd_mesh_new(&desc, &mesh);
    if (status != PROFSUBD_OK) {
        fprintf(stderr, "%s: %s\n", profsubd_status_string(status), profsubd_last_error_message());
    }
    {
        profsubd_mesh_report report = {0};
        report.struct_size = sizeof report;
        if (profsubd_mesh_check(mesh, &report) == PROFSUBD_OK && !report.is_manifold) {
            return 2;
        }
    }
    status = profsubd_mesh_get_positions(mesh, NULL, 0, &needed);
    (void)profsubd_options_new(&options);
    (void)profsubd_options_set_boundary(options, PROFSUBD_BOUNDARY_EDGE_ONLY);
    profsubd_options_free(options);
    profsubd_mesh_free(mesh);
    printf("%s %u.%u.%u\n", profsubd_version_string(), PROFSUBD_VERSION_MAJOR,
           PROFSUBD_VERSION_MINOR, PROFSUBD_VERSION_PATCH);
    return status == PROFSUBD_ERROR_BUFFER_TOO_SMALL && needed == 12 ? 0 : 1;
}
"#;

const CPP_PROGRAM: &str = r#"
#include "profsubd.h"
#include <cstdio>
#include <vector>

int main() {
    std::vector<double> positions{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    std::vector<uint32_t> sizes{4}, indices{0, 1, 2, 3};
    profsubd_mesh_desc desc{};
    desc.struct_size = sizeof desc;
    desc.positions = positions.data();
    desc.num_vertices = positions.size() / 3;
    desc.face_sizes = sizes.data();
    desc.num_faces = sizes.size();
    desc.face_indices = indices.data();
    desc.num_face_indices = indices.size();
    profsubd_mesh *mesh = nullptr;
    profsubd_status status = profsubd_mesh_new(&desc, &mesh);
    if (status != PROFSUBD_OK) {
        std::fprintf(stderr, "%s\n", profsubd_last_error_message());
    }
    size_t n = 0;
    status = profsubd_mesh_num_vertices(mesh, &n);
    profsubd_mesh_free(mesh);
    return status == PROFSUBD_OK && n == 4 ? 0 : 1;
}
"#;

fn syntax_check(compiler: &str, std: &str, extra: &[&str], source: &str, file: &str) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(file);
    std::fs::write(&path, source).unwrap();
    let output = Command::new(compiler)
        .arg(format!("-std={std}"))
        .args(["-Wall", "-Wextra", "-Werror", "-fsyntax-only"])
        .args(extra)
        .arg("-I")
        .arg(root.join("include"))
        .arg(&path)
        .output()
        .unwrap_or_else(|e| panic!("cannot run `{compiler}` ({e}); install gcc and g++"));
    assert!(
        output.status.success(),
        "{compiler} -std={std} rejects include/profsubd.h:\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

#[test]
fn header_is_clean_c99() {
    syntax_check(
        "gcc",
        "c99",
        &["-pedantic", "-Wstrict-prototypes", "-Wmissing-prototypes"],
        C_PROGRAM,
        "use_header.c",
    );
}

#[test]
fn header_is_clean_cpp17() {
    syntax_check(
        "g++",
        "c++17",
        &["-pedantic"],
        CPP_PROGRAM,
        "use_header.cpp",
    );
}
