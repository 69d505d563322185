#!/usr/bin/env bash
# Runs every test of profsubd: Rust (fmt, clippy, cargo test), the C++ conformance harness
# against OpenSubdiv and OpenMesh (CMake + CTest), valgrind over the C API harness, and the
# installed package consumed by the C example through find_package and pkg-config, a subset of
# the C/C++ tests under AddressSanitizer + UBSan, and the examples' bytes under emulated CPUs.
# Installs missing Debian packages when run as root (or with password-less sudo).
#
# Environment: PROFSUBD_OSD_SHAPES (OpenSubdiv shapes folder, default ../shared/conformance/osd_shapes),
# BUILD_DIR (default build), JOBS (default: number of cores).
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
APT_PACKAGES=(cmake make g++ pkg-config libosd-dev libopenmesh-dev libclang-dev valgrind binutils python3-pip openscad qemu-user)
START=$SECONDS
passed=0
failed=0
failed_steps=()

# section, step
source "$ROOT/scripts/steps.sh"

install_dependencies() {
    local missing=()
    if command -v dpkg-query >/dev/null; then
        for p in "${APT_PACKAGES[@]}"; do
            if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
                missing+=("$p")
            fi
        done
    fi
    if [ ${#missing[@]} -gt 0 ]; then
        echo "missing Debian packages: ${missing[*]}"
        local sudo=()
        if [ "$(id -u)" -ne 0 ]; then
            if sudo -n true 2>/dev/null; then
                sudo=(sudo -n)
            else
                echo "not root: run 'apt-get install -y ${missing[*]}' as root, then rerun" >&2
                return 1
            fi
        fi
        "${sudo[@]}" apt-get update
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
    else
        echo "Debian packages present: ${APT_PACKAGES[*]}"
    fi
    if ! command -v cargo >/dev/null; then
        export PATH="$HOME/.cargo/bin:$PATH"
    fi
    command -v cargo >/dev/null || { echo "cargo not found: install Rust (https://rustup.rs)" >&2; return 1; }
    if ! cargo fmt --version >/dev/null 2>&1 || ! cargo clippy --version >/dev/null 2>&1; then
        command -v rustup >/dev/null && rustup component add rustfmt clippy
    fi
    cargo --version
    cmake --version | head -1
}

rust_fmt() { cargo fmt --check; }
rust_clippy() { cargo clippy --all-targets -- -D warnings; }
# Broken intra-doc links and links from public docs to private items fail the run.
rust_doc() { RUSTDOCFLAGS="-D warnings" cargo doc --no-deps; }
# Release: the numeric tests are heavy, and CMake reuses the same release library below.
rust_test() { cargo test --release; }

cmake_build() {
    # --tests: same feature resolution as `cargo test`, so its release library is reused.
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DPROFSUBD_CARGO_EXTRA_ARGS=--tests
    cmake --build "$BUILD_DIR" -j "$JOBS"
}

ctest_all() { ctest --test-dir "$BUILD_DIR" -LE valgrind --output-on-failure -j "$JOBS"; }
ctest_valgrind() {
    local n
    n=$(ctest --test-dir "$BUILD_DIR" -L valgrind -N | sed -n 's/^Total Tests: //p')
    [ "${n:-0}" -gt 0 ] || { echo "no valgrind tests registered (is valgrind installed?)" >&2; return 1; }
    ctest --test-dir "$BUILD_DIR" -L valgrind --output-on-failure -j "$JOBS"
}

# AddressSanitizer + UBSan over a subset of the C/C++ tests (the C API's bad-input, cancellation, topology,
# sweep and 16-thread tests; the OpenSubdiv conformance tests are left to the plain and
# valgrind runs, to keep the run short).
ASAN_TESTS=(threads bad_input topology conformance_sweep cancel)
ctest_asan() {
    cmake -S . -B "$BUILD_DIR-asan" -DCMAKE_BUILD_TYPE=Release -DPROFSUBD_SANITIZE=ON \
        -DPROFSUBD_CARGO_EXTRA_ARGS=--tests
    cmake --build "$BUILD_DIR-asan" -j "$JOBS" --target "${ASAN_TESTS[@]}"
    local regex
    regex="^($(IFS='|'; echo "${ASAN_TESTS[*]}"))\$"
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        ctest --test-dir "$BUILD_DIR-asan" -R "$regex" --output-on-failure -j "$JOBS"
}

# Smoke fuzzing: every fuzz target from its seed corpus for a few seconds (scripts/fuzz.sh),
# built without ASan (coverage instrumentation and panics only: the ASan build of the whole
# crate is the long runs' cost); a crash, panic, contract break or input over 60 s (wall time, a loaded machine) fails.
fuzz_smoke() { FUZZ_SANITIZER=none FUZZ_TIMEOUT=60 SECONDS_PER_TARGET="${FUZZ_SECONDS:-10}" scripts/fuzz.sh; }

# The same bytes on every CPU: the examples under emulated CPUs without AVX/FMA.
determinism() { scripts/check_determinism.sh; }

PREFIX_ROOT="$(mktemp -d)"
PREFIX="$PREFIX_ROOT/prefix"
trap 'rm -rf "$PREFIX_ROOT"' EXIT

# Install into a temporary prefix and check what landed there.
install_package() {
    cmake --install "$BUILD_DIR" --prefix "$PREFIX"
    local libdir
    libdir="$(dirname "$(find "$PREFIX" -name profsubd.pc)")/.."
    for f in "$PREFIX/include/profsubd.h" "$libdir/libprofsubd.so" "$libdir/libprofsubd.so.0" \
        "$libdir/libprofsubd.a" "$libdir/cmake/profsubd/profsubdConfig.cmake" \
        "$libdir/cmake/profsubd/profsubdConfigVersion.cmake"; do
        [ -e "$f" ] || { echo "missing after install: $f" >&2; return 1; }
    done
    [ -L "$libdir/libprofsubd.so" ] && [ -L "$libdir/libprofsubd.so.0" ]
    readelf -d "$libdir/libprofsubd.so.0" | grep -q 'SONAME.*\[libprofsubd\.so\.0\]'
    echo "installed into $PREFIX; SONAME: $(readelf -d "$libdir/libprofsubd.so.0" | sed -n 's/.*SONAME.*\[\(.*\)\]/\1/p')"
}

example_find_package() {
    local dir="$PREFIX_ROOT/example-find-package"
    cmake -S examples/c -B "$dir" -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_BUILD_TYPE=Release
    cmake --build "$dir" -j "$JOBS"
    "$dir/cube_example" "$dir/cube.obj"
    "$dir/cube_example_static" "$dir/cube_static.obj"
    "$dir/profile_example" "$dir/profile.obj"
    # The C programs' use of the library is memory-clean.
    valgrind --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite --quiet \
        "$dir/cube_example" "$dir/cube_valgrind.obj"
    # The program records the versioned SONAME, not the bare .so name.
    readelf -d "$dir/cube_example" | grep -q 'NEEDED.*\[libprofsubd\.so\.0\]'
}

# The build tree as is: a fresh copy of the sources built with plain cargo (sharing the
# compiled dependencies through CARGO_TARGET_DIR), then a C program linked against
# target/release starts; build.rs makes target/release/libprofsubd.so.0 (the SONAME).
build_tree_linking() {
    local clone="$PREFIX_ROOT/clone" target="${CARGO_TARGET_DIR:-$ROOT/target}"
    mkdir -p "$clone"
    git -C "$ROOT" archive HEAD | tar -x -C "$clone"
    rm -f "$target/release/libprofsubd.so.0"
    # The shared target dir saves rebuilding the dependencies; build.rs, which makes the
    # link, runs again only when it is newer than its last run, as in a fresh clone.
    touch "$clone/build.rs"
    (cd "$clone" && CARGO_TARGET_DIR="$target" cargo build --release --lib)
    [ -L "$target/release/libprofsubd.so.0" ] || { echo "no libprofsubd.so.0 in $target/release" >&2; return 1; }
    cc -std=c99 -I"$clone/include" "$clone/examples/c/cube_example.c" -o "$PREFIX_ROOT/cube_build_tree" \
        -L"$target/release" -lprofsubd -Wl,-rpath,"$target/release"
    readelf -d "$PREFIX_ROOT/cube_build_tree" | grep -q 'NEEDED.*\[libprofsubd\.so\.0\]'
    "$PREFIX_ROOT/cube_build_tree" "$PREFIX_ROOT/cube_build_tree.obj"
}

# usd-core and trimesh for tests/external_readers.rs (openscad comes from APT_PACKAGES).
python_packages() {
    if ! python3 -c 'import pxr.Usd, trimesh' 2>/dev/null; then
        python3 -m pip install --break-system-packages usd-core trimesh \
            || python3 -m pip install usd-core trimesh
    fi
    python3 -c 'import pxr.Usd, trimesh; print("usd-core and trimesh present")'
}

# The Python package (python/): built and installed as a user does (`pip install ./python`:
# cargo build --release of this tree, the library bundled in a wheel) into a temporary
# target, then its pytest suite runs against that copy, checking its bytes against the CLI's.
python_package() {
    if ! python3 -c 'import numpy, pytest' 2>/dev/null; then
        python3 -m pip install --break-system-packages numpy pytest || python3 -m pip install numpy pytest
    fi
    local site="$PREFIX_ROOT/python-site"
    python3 -m pip install --no-deps --no-build-isolation --target "$site" ./python
    PYTHONPATH="$site" PROFSUBD_CLI="${CARGO_TARGET_DIR:-$ROOT/target}/release/profsubd" \
        python3 -m pytest -q -p no:cacheprovider python/tests
}

example_pkg_config() {
    local dir="$PREFIX_ROOT/example-pkg-config" pcdir
    mkdir -p "$dir"
    pcdir="$(dirname "$(find "$PREFIX" -name profsubd.pc)")"
    echo "pkg-config --cflags --libs profsubd: $(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs profsubd)"
    PKG_CONFIG_PATH="$pcdir" make -C examples/c OUT="$dir"
    "$dir/cube_example" "$dir/cube.obj"
}

SHAPES="${PROFSUBD_OSD_SHAPES:-$ROOT/../shared/conformance/osd_shapes}"
if [ -d "$SHAPES" ]; then
    echo "OpenSubdiv shapes: $SHAPES ($(find "$SHAPES" -maxdepth 1 -name '*.obj' | wc -l) .obj files)"
else
    echo "NOTE: OpenSubdiv shapes NOT FOUND at $SHAPES (set PROFSUBD_OSD_SHAPES);"
    echo "      the conformance tests will run on project-generated meshes only."
fi
export PROFSUBD_OSD_SHAPES="$SHAPES"

step "dependencies" install_dependencies
export PATH="$HOME/.cargo/bin:$PATH"
step "python packages (usd-core, trimesh)" python_packages
step "cargo fmt --check" rust_fmt
step "cargo clippy --all-targets -- -D warnings" rust_clippy
step "cargo doc (warnings are errors)" rust_doc
step "cargo test --release" rust_test
step "cmake configure + build ($BUILD_DIR)" cmake_build
step "ctest (C++ harness vs OpenSubdiv and OpenMesh)" ctest_all
step "valgrind --error-exitcode=1 over the C API harness" ctest_valgrind
step "AddressSanitizer + UBSan: ${ASAN_TESTS[*]}" ctest_asan
step "determinism: examples byte-identical under qemu64 / Haswell CPUs" determinism
step "smoke fuzzing: obj_reader, mesh_arrays, construction (scripts/fuzz.sh, no ASan)" fuzz_smoke
step "cmake --install into a temporary prefix" install_package
step "C example via find_package(profsubd) (installed package)" example_find_package
step "C example via pkg-config (installed package)" example_pkg_config
step "fresh sources, plain cargo build: C program linked against target/release runs" build_tree_linking
step "Python package: pip install ./python, pytest python/tests" python_package
# FreeCAD, OpenSCAD (and Blender) integration tests: heavy installs, opt-in.
if [ "${PROFSUBD_INTEGRATIONS:-0}" = 1 ]; then
    step "integrations (scripts/test_integrations.sh)" bash scripts/test_integrations.sh
fi

section "summary"
echo "total time: $((SECONDS - START)) s"
for s in "${failed_steps[@]}"; do
    echo "failed: $s"
done
echo "test_all: $passed steps passed, $failed failed"
[ "$failed" -eq 0 ]
