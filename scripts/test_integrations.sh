#!/usr/bin/env bash
# Runs profsubd inside the programs people use it from, each with its own test:
#   FreeCAD   integrations/freecad/test_freecad.py in freecadcmd (Part solid valid, closed,
#             volume = the tessellation's)
#   OpenSCAD  examples/openscad/check_csg.py (openscad -o out.stl on profsubd_csg.scad with
#             profsubd's STL and OFF; watertight and volume checked with trimesh / manifold3d)
#   Blender   integrations/blender/run_tests.sh (the add-on: tags, export, limit vs profsubd)
# Installs what is missing: Debian packages (freecad blender openscad python3-pip python3-numpy) when
# run as root or with password-less sudo, the pip packages numpy trimesh manifold3d; builds
# the Python package as `pip install ./python` does (cargo build --release, library bundled).
# Heavy (FreeCAD alone is 266 MB of packages): not part of scripts/test_all.sh unless
# PROFSUBD_INTEGRATIONS=1.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
APT_PACKAGES=(freecad blender openscad python3-pip python3-numpy)
START=$SECONDS
passed=0
failed=0
failed_steps=()
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
SITE="$WORK/site"
export PATH="$HOME/.cargo/bin:$PATH"

# section, step
source "$ROOT/scripts/steps.sh"

install_programs() {
    local missing=()
    for p in "${APT_PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    if [ ${#missing[@]} -gt 0 ]; then
        local sudo=()
        if [ "$(id -u)" -ne 0 ]; then
            sudo -n true 2>/dev/null || { echo "not root: apt-get install -y ${missing[*]}, then rerun" >&2; return 1; }
            sudo=(sudo -n)
        fi
        "${sudo[@]}" apt-get update
        # The lock timeout: other jobs on the machine may be installing too.
        DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y \
            --no-install-recommends "${missing[@]}"
    else
        echo "Debian packages present: ${APT_PACKAGES[*]}"
    fi
    freecadcmd --version 2>/dev/null | tail -1 || true
    openscad --version
}

pip_packages() {
    if ! python3 -c 'import numpy, trimesh, manifold3d' 2>/dev/null; then
        python3 -m pip install --break-system-packages numpy trimesh manifold3d \
            || python3 -m pip install numpy trimesh manifold3d
    fi
    python3 -c 'import numpy, trimesh, manifold3d; print("numpy", numpy.__version__, "trimesh", trimesh.__version__)'
}

# One wheel for every interpreter here (the package is Python + the bundled library, loaded
# with ctypes): installed into a folder that FreeCAD's and the test's Python both get on
# PYTHONPATH.
python_package() {
    python3 -m pip install --no-deps --no-build-isolation --target "$SITE" ./python
    PYTHONPATH="$SITE" python3 -c 'import profsubd; print("profsubd", profsubd.__version__, profsubd.LIBRARY_PATH)'
}

freecad_test() {
    # freecadcmd exits 0 after an uncaught exception: the test's last line says ok, or not.
    # (FreeCAD's progress lines are left out of the output.)
    PYTHONPATH="$SITE" freecadcmd integrations/freecad/test_freecad.py 2>&1 | tee "$WORK/freecad.log" \
        | grep -a -o -E '^FreeCAD [0-9].*|[a-z_]+: solid valid.*|^freecad: ok|Traceback.*|^  File .*|^[A-Za-z]*Error.*' || true
    grep -q '^freecad: ok' "$WORK/freecad.log"
}

openscad_test() { PYTHONPATH="$SITE" python3 examples/openscad/check_csg.py "$WORK/openscad"; }

# The package on PYTHONPATH: the add-on's profile operator is tested too.
blender_test() { PYTHONPATH="$SITE" PROFSUBD_PYTHON_SITE="$SITE" bash integrations/blender/run_tests.sh; }

step "install freecad, blender, openscad (apt-get)" install_programs
step "pip packages (numpy, trimesh, manifold3d)" pip_packages
step "Python package (pip install ./python)" python_package
step "FreeCAD: integrations/freecad/test_freecad.py in freecadcmd" freecad_test
step "OpenSCAD: examples/openscad/profsubd_csg.scad, openscad -o out.stl" openscad_test
step "Blender: integrations/blender/run_tests.sh" blender_test

section "summary"
echo "total time: $((SECONDS - START)) s"
for s in "${failed_steps[@]}"; do
    echo "failed: $s"
done
echo "test_integrations: $passed steps passed, $failed failed"
[ "$failed" -eq 0 ]
