"""Test of profsubd_freecad in FreeCAD's console (``freecadcmd test_freecad.py``; run by
scripts/test_integrations.sh, which puts the profsubd package on PYTHONPATH).

For each input (profsubd JSON files, and Sketcher sketches made here): the Part solid is
valid and closed, and its volume (OpenCASCADE) equals the volume of the tessellation's
triangles computed here with NumPy (divergence theorem) to 1e-9 relative; the Mesh feature is
a closed solid mesh with the same volume to 1e-5 (FreeCAD's meshes hold float32 points
and sum in float32; measured up to 1.0e-5). Sketch inputs: the model equals the one built from
the same points without FreeCAD. Exits 1 on the first failure (freecadcmd itself exits 0
after an uncaught exception).
"""

import os
import sys
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)


def tessellation_volume(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    import numpy as np

    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def check_solid(label, doc, spec, sketches=(), rate=2):
    import time

    import profsubd_freecad as pf

    t0 = time.time()
    with pf.build_model(spec, sketches) as model:
        points, triangles = pf.tessellation_arrays(model, rate=rate)
        targets = model.targets
    mesh_obj, part_obj = pf.add_to_document(doc, points, triangles, name=label)
    solid = part_obj.Shape
    expected = tessellation_volume(points, triangles)
    assert solid.ShapeType == "Solid", f"{label}: {solid.ShapeType}, not a solid"
    assert solid.isValid(), f"{label}: invalid solid"
    assert solid.Shells[0].isClosed(), f"{label}: open shell"
    assert len(solid.Faces) == len(triangles), f"{label}: {len(solid.Faces)} faces for {len(triangles)} triangles"
    assert abs(solid.Volume - expected) <= 1e-9 * abs(expected), f"{label}: volume {solid.Volume} != {expected}"
    mesh = mesh_obj.Mesh
    assert mesh.isSolid() and not mesh.hasNonManifolds(), f"{label}: Mesh feature not a closed solid"
    # FreeCAD's mesh holds float32 points and sums its volume in float32 (measured: up to 1e-5).
    assert abs(mesh.Volume - expected) <= 1e-4 * abs(expected), f"{label}: mesh volume {mesh.Volume} != {expected}"
    print(f"{label}: solid valid, closed, {len(solid.Faces)} faces, volume {solid.Volume:.12g} "
          f"(tessellation {expected:.12g}, relative difference {abs(solid.Volume - expected) / expected:.1e}; "
          f"Mesh feature {mesh.Volume:.9g}, {abs(mesh.Volume - expected) / expected:.1e}; {time.time() - t0:.1f} s)")
    return targets


def make_sketch(doc, name, points):
    """A sketch in the global XZ plane: polyline through (x, z) points."""
    import FreeCAD
    import Part

    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 0), FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90))
    for (x0, y0), (x1, y1) in zip(points[:-1], points[1:]):
        sk.addGeometry(Part.LineSegment(FreeCAD.Vector(x0, y0, 0), FreeCAD.Vector(x1, y1, 0)))
    doc.recompute()
    return sk


def main():
    import FreeCAD
    import numpy as np

    import profsubd
    import profsubd_freecad as pf

    print("FreeCAD", ".".join(FreeCAD.Version()[:3]), "profsubd", profsubd.__version__, "from", profsubd.__file__)
    doc = FreeCAD.newDocument("profsubd_test")
    check_solid("bottle_json", doc, os.path.join(REPO, "examples", "profiles", "bottle.json"))
    # 32 x 32 samples with caps: rate 1 keeps the sewing (superlinear in the faces) short.
    check_solid("vase_cutaway_json", doc, os.path.join(REPO, "examples", "sweeps", "vase_cutaway.json"), rate=1)
    # A bottle's silhouette drawn (reversed, top to bottom) in a sketch: a profile model.
    silhouette = [[0, 2.5], [0.8, 2.0], [1.0, 0.5], [0, 0]]
    sk = make_sketch(doc, "Silhouette", silhouette)
    assert np.allclose(pf.sketch_curve(sk), silhouette[::-1], rtol=0, atol=1e-12), pf.sketch_curve(sk)
    got = check_solid("sketch_profile", doc, {"around": 16, "along": 8}, [sk])
    with profsubd.profile(c1=silhouette[::-1], c2=silhouette[::-1], around=16, along=8) as ref:
        assert np.allclose(got, ref.targets, rtol=0, atol=1e-10), "sketch profile != profile from points"
    # A cup's wall as a sketch: a flat-capped revolution.
    wall = [[1.2, 0], [1.9, 0.6], [2.2, 1.6], [1.3, 2.5]]
    cup = make_sketch(doc, "Wall", wall)
    got = check_solid("sketch_revolve", doc, {"construction": "revolve", "caps": "flat", "samples_profile": 8}, [cup])
    with profsubd.revolve(wall, caps="flat", samples_profile=8) as ref:
        assert np.allclose(got, ref.targets, rtol=0, atol=1e-10), "sketch revolve != revolve from points"
    # A curved edge (an arc bulging outwards, (1, 0) to (1, 2) about (1, 1)) is sampled.
    import FreeCAD
    import Part

    bulge = doc.addObject("Sketcher::SketchObject", "Bulge")
    bulge.Placement = cup.Placement
    bulge.addGeometry(Part.ArcOfCircle(Part.Circle(FreeCAD.Vector(1, 1, 0), FreeCAD.Vector(0, 0, 1), 1),
                                       -np.pi / 2, np.pi / 2))
    doc.recompute()
    arc = pf.sketch_curve(bulge)
    assert len(arc) == 8 and np.allclose(arc[[0, -1]], [[1, 0], [1, 2]], atol=1e-12), arc
    assert np.allclose(np.linalg.norm(arc - [1, 1], axis=1), 1, atol=1e-12) and np.all(arc[:, 0] >= 1 - 1e-12), arc
    check_solid("sketch_arc_revolve", doc, {"construction": "revolve", "caps": "flat", "samples_profile": 8, "samples_around": 16}, [bulge])
    print("freecad: ok")


try:
    main()
except BaseException:  # freecadcmd swallows exceptions: exit non-zero ourselves
    traceback.print_exc()
    sys.stdout.flush()
    sys.exit(1)
sys.stdout.flush()
