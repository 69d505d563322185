#!/usr/bin/env bash
# The Rust side under AddressSanitizer: the C API's unit tests (src/ffi/, every handle, bad
# input, caught panics) and the cancellation and limits tests, built with nightly's
# `-Zsanitizer=address` (the crate and its dependencies instrumented; Rust's std is not:
# `-Zbuild-std` would rebuild it too). Leaks are checked (LeakSanitizer, ASan's default on
# Linux). Not in `.ci/run`: the instrumented build of the crate takes several minutes on 2
# cores (README, Reliability). Installs the nightly toolchain when missing.
# Usage: scripts/asan_rust.sh [extra cargo test arguments]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="$HOME/.cargo/bin:$PATH"
rustup toolchain list | grep -q '^nightly' || rustup toolchain install nightly --profile minimal
TARGET="$(rustc -vV | sed -n 's/^host: //p')"
# --target: build scripts and proc macros stay uninstrumented; a target dir of its own keeps
# the plain build's artifacts.
export RUSTFLAGS="-Zsanitizer=address" RUSTDOCFLAGS="-Zsanitizer=address"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export CARGO_TARGET_DIR="${ASAN_TARGET_DIR:-target/asan}"
args=(+nightly test --release --target "$TARGET" "$@")
cargo "${args[@]}" --lib -- ffi::
cargo "${args[@]}" --test cancel --test limits
