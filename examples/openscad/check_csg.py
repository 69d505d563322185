"""Test of profsubd_csg.scad in OpenSCAD (run by scripts/test_integrations.sh).

Builds the built-in bottle through the Python package, tessellates its limit surface
(rate 2) into bottle.stl and bottle.off, runs `openscad -o out.stl` on profsubd_csg.scad with
each, and checks with trimesh that the result is watertight, a consistently oriented volume,
and that its volume equals the same CSG computed independently by manifold3d on the same
triangles (relative 1e-5; OpenSCAD rounds through float32 STL).

Usage: python3 examples/openscad/check_csg.py [WORK_DIR]   (needs openscad, trimesh, manifold3d)
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import manifold3d
import numpy as np
import trimesh

import profsubd

HERE = Path(__file__).resolve().parent


def reference_volume(points: np.ndarray, triangles: np.ndarray) -> float:
    """The .scad's CSG by manifold3d: (bottle - cylinder) + cube."""
    bottle = manifold3d.Manifold(manifold3d.Mesh(vert_properties=points.astype(np.float32), tri_verts=triangles))
    assert bottle.status() == manifold3d.Error.NoError, bottle.status()
    cylinder = manifold3d.Manifold.cylinder(4, 0.3, 0.3, 32).translate((0, 0, 1))
    cube = manifold3d.Manifold.cube((3, 3, 0.4)).translate((-1.5, -1.5, -0.3))
    return ((bottle - cylinder) + cube).volume()


def main() -> int:
    work = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="profsubd-openscad-"))
    work.mkdir(parents=True, exist_ok=True)
    shutil.copy(HERE / "profsubd_csg.scad", work)
    with profsubd.profile() as model, model.evaluator() as ev, ev.tessellate(rate=2) as t:
        t.write(work / "bottle.stl")
        t.write(work / "bottle.off")
        points, triangles = t.points, t.triangles
    bottle = trimesh.Trimesh(points, triangles, process=False)
    assert bottle.is_watertight and bottle.is_volume, "profsubd's tessellation is not closed"
    expected = reference_volume(points, triangles)
    for source in ("bottle.stl", "bottle.off"):
        out = work / f"out_{source.replace('.', '_')}.stl"
        subprocess.run(["openscad", "-o", str(out), "-D", f'model="{source}"', "profsubd_csg.scad"],
                       cwd=work, check=True, capture_output=True)
        result = trimesh.load(out, force="mesh")
        print(f"{source}: openscad -> {out.name}: {len(result.faces)} triangles, watertight "
              f"{result.is_watertight}, volume {result.volume:.6f} (manifold3d: {expected:.6f}; "
              f"bottle alone {bottle.volume:.6f})")
        assert result.is_watertight and result.is_volume, f"{source}: OpenSCAD's result is not watertight"
        assert abs(result.volume - expected) <= 1e-5 * expected, f"{source}: volume {result.volume} != {expected}"
        # The CSG did something: the bore and the plate changed the volume.
        assert abs(result.volume - bottle.volume) > 1.0
    print("openscad CSG: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
