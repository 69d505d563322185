#!/usr/bin/env bash
# The full generated fold matrix of issue #10 (README "Valid surfaces: folds, design distance,
# fairness"): spheres, ellipsoids, flat-based bottles and goblets by profiles, revolutions
# (full and partial turns, open and capped) and sweeps, at 16 x 8 to 128 x 64 samples.
# 1. `cargo test --release --test fold_matrix -- --ignored` builds each one and checks it by
#    the library's fold check (a partial turn may instead be refused with InvalidArgument),
#    writing every built mesh to BUILD/fold_matrix/*.obj;
# 2. the C++ harness checks every one of those files with OpenSubdiv's Bfr
#    (`conformance_folds --fold-free`): no folded face by Bfr and the same (empty) set by
#    the library, at 9 x 9 (depth 4) and 17 x 17 (depth 2).
# Usage: scripts/fold_matrix.sh [BUILD]   (BUILD: a configured CMake build folder, default
# build; see README "Using the installed library from C or C++" for the configure line).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD="${1:-build}"
OUT="$BUILD/fold_matrix"
rm -rf "$OUT"
PROFSUBD_FOLD_MATRIX_OBJ="$OUT" cargo test --release --test fold_matrix -- --ignored --nocapture
cmake --build "$BUILD" -j2 --target conformance_folds
"$BUILD/cpp_tests/conformance_folds" --fold-free "$OUT"/*.obj
