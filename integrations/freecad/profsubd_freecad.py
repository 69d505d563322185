"""profsubd in FreeCAD: profile curves (a Sketcher sketch or profsubd's JSON) -> profsubd (the
Python package) -> a Mesh feature and a Part solid of the tessellated limit surface.

Scripting entry point (no dialog; FreeCAD's Python console, a macro, or ``freecadcmd``)::

    import profsubd_freecad as pf
    mesh_obj, part_obj = pf.run("examples/profiles/bottle.json")          # a JSON file or dict
    mesh_obj, part_obj = pf.run({"construction": "revolve", "caps": "flat"}, sketches=[sketch])
    mesh_obj, part_obj = pf.run({}, sketches=[sketch_c1, sketch_c2])          # profile model

A spec is the JSON input of ``profsubd profile`` / ``revolve`` / ``sweep`` (the same keys as
the Python functions' keywords); its construction is ``spec["construction"]`` or, without it,
``"sweep"`` if it has a ``trajectory``, ``"revolve"`` if it has a ``profile``, else
``"profile"``. Sketches supply curves: each sketch's first wire, in the sketch's own (x, y)
coordinates, ordered bottom to top, its vertices as curve points (curved edges sampled at 8
points). For ``profile``: one sketch gives ``c1`` = ``c2`` (a model with circular rings; add
``c2`` in the spec for another silhouette), two give ``c1`` and ``c2``. For ``revolve``: the
profile ``(r, z)``. For ``sweep``: the profile ``(a, b)``; the trajectory stays in the spec.

The Part solid is sewn from the tessellation's triangles (``Part.Shape.makeShapeFromMesh``):
closed wherever the control mesh is closed, since profsubd computes the points of shared
edges once. ``rate`` (uniform, per quad) or ``tolerance`` (adaptive, model units) set its
density. Needs the ``profsubd`` package importable by FreeCAD's Python (``pip install
./python`` with Debian's python3, or ``sys.path``).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

import profsubd

Spec = Union[str, Path, Dict[str, Any]]
CONSTRUCTIONS = ("profile", "revolve", "sweep")


def sketch_curve(sketch: Any) -> np.ndarray:
    """The points of a sketch's first wire in the sketch's (x, y) coordinates, bottom to top
    (increasing y at the ends), as an (n, 2) array."""
    import FreeCAD

    shape = sketch.Shape
    if not shape.Wires:
        raise ValueError(f"{sketch.Name}: the sketch has no wire")
    wire = shape.Wires[0]
    to_local = sketch.getGlobalPlacement().inverse()
    pts: List[Any] = []
    for edge in wire.OrderedEdges:
        if edge.Curve.TypeId == "Part::GeomLine":
            ends = [v.Point for v in edge.Vertexes]
        else:
            ends = edge.discretize(Number=8)
        # OrderedEdges keeps the chain; an edge may run backwards along it.
        if pts and (ends[0] - pts[-1]).Length > (ends[-1] - pts[-1]).Length:
            ends = ends[::-1]
        pts.extend(ends[1:] if pts else ends)
    local = np.array([[q.x, q.y] for q in (to_local.multVec(FreeCAD.Vector(p)) for p in pts)])
    keep = np.concatenate([[True], np.linalg.norm(np.diff(local, axis=0), axis=1) > 1e-12])
    local = local[keep]
    return local[::-1] if local[0, 1] > local[-1, 1] else local


def _load(spec: Spec) -> Dict[str, Any]:
    if isinstance(spec, (str, Path)):
        return json.loads(Path(spec).read_text(encoding="utf-8"))
    return dict(spec)


def build_model(spec: Spec, sketches: Sequence[Any] = ()) -> profsubd.Model:
    """The profsubd model of a spec (JSON file, dict) and optional sketches (see the module)."""
    kwargs = _load(spec)
    kind = kwargs.pop("construction", None)
    if kind is None:
        kind = "sweep" if "trajectory" in kwargs else "revolve" if "profile" in kwargs else "profile"
    if kind not in CONSTRUCTIONS:
        raise ValueError(f"construction {kind!r}: expected one of {', '.join(CONSTRUCTIONS)}")
    curves = [sketch_curve(s) for s in sketches]
    if curves:
        if kind == "profile":
            if len(curves) > 2:
                raise ValueError("a profile model takes one or two sketches (c1, c2)")
            kwargs["c1"] = curves[0]
            kwargs.setdefault("c2", curves[1] if len(curves) == 2 else curves[0])
        else:
            if len(curves) != 1:
                raise ValueError(f"{kind} takes one sketch (its profile)")
            kwargs["profile"] = curves[0]
    return getattr(profsubd, kind)(**kwargs)


def tessellation_arrays(model: profsubd.Model, rate: Optional[int] = 4,
                        tolerance: Optional[float] = None) -> Tuple[np.ndarray, np.ndarray]:
    """``(points (n, 3), triangles (T, 3))`` of the model's limit surface."""
    with model.evaluator() as ev:
        with ev.tessellate(rate=None if tolerance else rate, tolerance=tolerance) as t:
            return t.points, t.triangles


def add_to_document(doc: Any, points: np.ndarray, triangles: np.ndarray, name: str = "Profsubd") -> Tuple[Any, Any]:
    """Add a ``Mesh::Feature`` (FreeCAD meshes hold float32 points) and a ``Part::Feature``
    (the solid sewn from the triangles' double-precision points; a shell when the surface is
    open) named ``name + "Mesh"`` / ``name``; returns both."""
    import FreeCAD
    import Mesh
    import Part

    vectors = [FreeCAD.Vector(*p) for p in points.tolist()]
    mesh = Mesh.Mesh([[vectors[i] for i in tri] for tri in triangles.tolist()])
    mesh_obj = doc.addObject("Mesh::Feature", f"{name}Mesh")
    mesh_obj.Mesh = mesh
    diag = float(np.linalg.norm(points.max(0) - points.min(0)))
    shape = Part.Shape()
    # From the double-precision points (a Mesh keeps float32 ones).
    shape.makeShapeFromMesh((vectors, [tuple(t) for t in triangles.tolist()]), 1e-7 * diag)
    shell = Part.Shell(shape.Faces)
    solid = Part.Solid(shell) if shell.isClosed() else shell
    if solid.ShapeType == "Solid" and solid.Volume < 0:
        solid.reverse()
    part_obj = doc.addObject("Part::Feature", name)
    part_obj.Shape = solid
    doc.recompute()
    return mesh_obj, part_obj


def run(spec: Spec, sketches: Iterable[Any] = (), doc: Any = None, name: str = "Profsubd",
        rate: Optional[int] = 4, tolerance: Optional[float] = None) -> Tuple[Any, Any]:
    """Build the model, tessellate it and add its Mesh feature and Part solid to ``doc``
    (default: the active document, or a new one). Returns ``(mesh_feature, part_feature)``."""
    import FreeCAD

    if doc is None:
        doc = FreeCAD.ActiveDocument or FreeCAD.newDocument("profsubd")
    with build_model(spec, list(sketches)) as model:
        points, triangles = tessellation_arrays(model, rate, tolerance)
    return add_to_document(doc, points, triangles, name)
