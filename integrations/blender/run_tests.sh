#!/usr/bin/env bash
# Tests the profsubd Blender add-on headless in Blender (Debian's blender package, 3.4):
# import of every example OBJ, tags, export round trip, and the modifier's limit surface
# against profsubd's exact limit (see test_blender.py). Installs blender with apt-get when
# missing and run as root; builds the profsubd command-line tool when missing.
# Environment: PROFSUBD_CLI (default target/release/profsubd), BLENDER (default blender),
# PYTHONPATH (where Blender's Python finds the profsubd package, if not installed).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
BLENDER="${BLENDER:-blender}"
if ! command -v "$BLENDER" >/dev/null; then
    if [ "$(id -u)" -eq 0 ]; then
        apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y blender
    else
        echo "blender not found: run 'apt-get install -y blender' as root, or set BLENDER" >&2
        exit 1
    fi
fi
export PROFSUBD_CLI="${PROFSUBD_CLI:-$ROOT/target/release/profsubd}"
if [ ! -x "$PROFSUBD_CLI" ]; then
    cargo build --release --bin profsubd
fi
"$BLENDER" --version | head -1
start=$SECONDS
# The test installs the add-on from a zip into this scratch user folder, as a user would.
BLENDER_USER_SCRIPTS="$(mktemp -d)"
export BLENDER_USER_SCRIPTS
trap 'rm -rf "$BLENDER_USER_SCRIPTS"' EXIT
# --python-use-system-env: PYTHONPATH reaches Blender's Python (for the profsubd package).
"$BLENDER" -b --factory-startup --python-use-system-env --python-exit-code 1 \
    --python integrations/blender/test_blender.py
echo "integrations/blender/run_tests.sh: $((SECONDS - start)) s"
