#!/usr/bin/env bash
# Runs every test of profsubd: Rust (fmt, clippy, cargo test), the C++ conformance harness
# against OpenSubdiv and OpenMesh (CMake + CTest), valgrind over the C API harness, and the
# installed package consumed by the C example through find_package and pkg-config.
# Installs missing Debian packages when run as root (or with password-less sudo).
#
# Environment: PROFSUBD_OSD_SHAPES (OpenSubdiv shapes folder, default ../shared/conformance/osd_shapes),
# BUILD_DIR (default build), JOBS (default: number of cores).
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
APT_PACKAGES=(cmake make g++ pkg-config libosd-dev libopenmesh-dev libclang-dev valgrind binutils)
START=$SECONDS
passed=0
failed=0
failed_steps=()

section() {
    printf '\n==================== %s ====================\n' "$1"
}

# step TITLE FUNCTION: runs FUNCTION with `set -e` in a subshell, records the outcome and
# goes on, so one failure does not hide the others.
step() {
    local title="$1"
    shift
    section "$title"
    local t0=$SECONDS
    set +e
    (set -e; "$@")
    local rc=$?
    if [ $rc -eq 0 ]; then
        passed=$((passed + 1))
        echo "--> ok: $title ($((SECONDS - t0)) s)"
    else
        failed=$((failed + 1))
        failed_steps+=("$title")
        echo "--> FAILED (exit $rc): $title ($((SECONDS - t0)) s)"
    fi
}

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
# Release: the numeric tests are heavy, and CMake reuses the same release library below.
rust_test() { cargo test --release; }

cmake_build() {
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
    cmake --build "$BUILD_DIR" -j "$JOBS"
}

ctest_all() { ctest --test-dir "$BUILD_DIR" -LE valgrind --output-on-failure -j "$JOBS"; }
ctest_valgrind() {
    local n
    n=$(ctest --test-dir "$BUILD_DIR" -L valgrind -N | sed -n 's/^Total Tests: //p')
    [ "${n:-0}" -gt 0 ] || { echo "no valgrind tests registered (is valgrind installed?)" >&2; return 1; }
    ctest --test-dir "$BUILD_DIR" -L valgrind --output-on-failure -j "$JOBS"
}

if [ -z "${PROFSUBD_OSD_SHAPES:-}" ] && [ ! -d "$ROOT/../shared/conformance/osd_shapes" ]; then
    echo "NOTE: OpenSubdiv shapes not found at $ROOT/../shared/conformance/osd_shapes;"
    echo "      the conformance tests will run on project-generated meshes only."
fi

step "dependencies" install_dependencies
export PATH="$HOME/.cargo/bin:$PATH"
step "cargo fmt --check" rust_fmt
step "cargo clippy --all-targets -- -D warnings" rust_clippy
step "cargo test --release" rust_test
step "cmake configure + build ($BUILD_DIR)" cmake_build
step "ctest (C++ harness vs OpenSubdiv and OpenMesh)" ctest_all
step "valgrind --error-exitcode=1 over the C API harness" ctest_valgrind

section "summary"
echo "total time: $((SECONDS - START)) s"
for s in "${failed_steps[@]}"; do
    echo "failed: $s"
done
echo "test_all: $passed steps passed, $failed failed"
[ "$failed" -eq 0 ]
