"""OBJ files with OpenSubdiv's tag lines, without Blender: read, write, crease mapping.

The format is profsubd's (README "Command-line tool and OBJ files"): `v`, 1-based `f`, and
`t` lines with 0-based indices — `t crease 2/1/0 v0 v1 s` (also `2k/1/0`, `2k/k/0`),
`t corner n/1/0 v.. s` / `n/n/0`, `t hole n/0/0 f..`, `t interpolateboundary 1/0/0 B`,
`t creasemethod 0/0/1 normal|chaikin`, `t smoothtriangles 0/0/1 catmark|smooth`.
Kept free of `bpy` so that the mapping can be read and tested alone.
"""

import math
import struct
from decimal import Decimal

#: OpenSubdiv's infinite sharpness (`Sdc::Crease::SHARPNESS_INFINITE`).
INFINITE = 10.0

#: `t interpolateboundary` values.
BOUNDARY_NONE, BOUNDARY_EDGE_AND_CORNER, BOUNDARY_EDGE_ONLY = 0, 1, 2


def f32(x):
    """`x` rounded to the nearest single-precision float (sharpness is `float` in OpenSubdiv)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def sharpness_to_crease(s):
    """Blender crease for OpenSubdiv sharpness `s`.

    Blender's Subdivision Surface modifier hands OpenSubdiv the sharpness 10·c² for a crease
    c, so c = √(s/10), clamped to [0, 1]; infinite sharpness (s >= 10) is crease 1.
    """
    if not s > 0.0:
        return 0.0
    return min(1.0, math.sqrt(s / INFINITE))


def crease_to_sharpness(c):
    """OpenSubdiv sharpness that Blender's modifier uses for crease `c`: 10·c²."""
    c = min(1.0, max(0.0, c))
    return f32(INFINITE * c * c)


def same_crease(c_blender, s):
    """Whether Blender's stored (single-precision) crease is what importing `s` stored."""
    return f32(sharpness_to_crease(s)) == f32(c_blender)


class TaggedMesh:
    """A polygon mesh with OpenSubdiv tags.

    `positions`: list of (x, y, z) floats; `faces`: lists of 0-based vertex indices;
    `creases`: list of ((a, b), sharpness) in file order; `corners`: list of (vertex,
    sharpness); `holes`: face indices; `boundary`, `crease_method`, `triangles`: the option
    tags, None where the file has none; `warnings`: what the reader skipped.
    """

    def __init__(self):
        self.positions = []
        self.faces = []
        self.creases = []
        self.corners = []
        self.holes = []
        self.boundary = None
        self.crease_method = None
        self.triangles = None
        self.warnings = []


class ObjError(ValueError):
    """A line that cannot be read as OBJ with OpenSubdiv tags."""


def _tag_values(n, name, args):
    try:
        ni, nf, ns = (int(x) for x in args[0].split("/"))
    except (IndexError, ValueError):
        raise ObjError(f"line {n}: expected argument counts ints/floats/strings after `t {name}`")
    values = args[1:]
    if len(values) != ni + nf + ns:
        raise ObjError(f"line {n}: tag `{name}` announces {ni}/{nf}/{ns} arguments but has {len(values)} values")
    try:
        ints = [int(x) for x in values[:ni]]
        floats = [float(x) for x in values[ni : ni + nf]]
    except ValueError:
        raise ObjError(f"line {n}: bad number in tag `{name}`")
    if any(i < 0 for i in ints):
        raise ObjError(f"line {n}: negative index in tag `{name}`")
    return ints, floats, values[ni + nf :]


def _sharpness(n, name, s, warnings):
    if math.isnan(s):
        raise ObjError(f"line {n}: sharpness NaN in tag `{name}`")
    if s < 0.0:
        warnings.append(f"line {n}: negative sharpness {s} in tag `{name}` clamped to 0")
        return 0.0
    return f32(s)


def parse(text):
    """Read OBJ text into a `TaggedMesh`; raises `ObjError` naming the line."""
    m = TaggedMesh()
    for n, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].split()
        if not line:
            continue
        key, args = line[0], line[1:]
        if key == "v":
            if len(args) not in (3, 4):
                raise ObjError(f"line {n}: expected `v x y z`")
            try:
                xyz = tuple(float(a) for a in args[:3])
            except ValueError:
                raise ObjError(f"line {n}: bad coordinate")
            if not all(math.isfinite(c) for c in xyz):
                raise ObjError(f"line {n}: coordinate not finite")
            m.positions.append(xyz)
        elif key == "f":
            if len(args) < 3:
                raise ObjError(f"line {n}: a face needs at least 3 vertices")
            face = []
            for tok in args:
                try:
                    i = int(tok.split("/")[0])
                except ValueError:
                    raise ObjError(f"line {n}: bad vertex index `{tok}`")
                face.append(i - 1 if i > 0 else len(m.positions) + i)
            m.faces.append(face)
        elif key == "t" and args:
            _tag(m, n, args[0], args[1:])
        elif key in ("vt", "vn", "o", "g", "s", "usemtl", "mtllib", "l"):
            continue
        else:
            m.warnings.append(f"line {n}: ignored statement `{key}`")
    nv, nf = len(m.positions), len(m.faces)
    for f in m.faces:
        if any(not 0 <= i < nv for i in f):
            raise ObjError(f"a face refers to a vertex outside 1..{nv}")
    for (a, b), _ in m.creases:
        if not (a < nv and b < nv):
            raise ObjError(f"crease on vertices {a} {b} but the file has {nv} vertices")
    for v, _ in m.corners:
        if v >= nv:
            raise ObjError(f"corner on vertex {v} but the file has {nv} vertices")
    for h in m.holes:
        if h >= nf:
            raise ObjError(f"hole on face {h} but the file has {nf} faces")
    return m


def _tag(m, n, name, args):
    if name == "crease":
        ints, floats, strings = _tag_values(n, name, args)
        k = len(ints) // 2
        if not ints or len(ints) % 2 or len(floats) not in (1, k) or strings:
            raise ObjError(f"line {n}: expected `t crease 2/1/0 v0 v1 s`, `2k/1/0` or `2k/k/0`")
        for j in range(k):
            s = _sharpness(n, name, floats[0 if len(floats) == 1 else j], m.warnings)
            m.creases.append(((ints[2 * j], ints[2 * j + 1]), s))
    elif name == "corner":
        ints, floats, strings = _tag_values(n, name, args)
        if not ints or len(floats) not in (1, len(ints)) or strings:
            raise ObjError(f"line {n}: expected `t corner n/1/0 v.. s` or `n/n/0 v.. s..`")
        for j, v in enumerate(ints):
            m.corners.append((v, _sharpness(n, name, floats[0 if len(floats) == 1 else j], m.warnings)))
    elif name == "hole":
        ints, floats, strings = _tag_values(n, name, args)
        if floats or strings:
            raise ObjError(f"line {n}: expected `t hole n/0/0 f..`")
        m.holes.extend(ints)
    elif name == "interpolateboundary":
        ints, floats, strings = _tag_values(n, name, args)
        if len(ints) != 1 or floats or strings or ints[0] not in (0, 1, 2):
            raise ObjError(f"line {n}: expected `t interpolateboundary 1/0/0 B`, B in 0, 1, 2")
        m.boundary = ints[0]
    elif name == "creasemethod":
        ints, floats, strings = _tag_values(n, name, args)
        if ints or floats or strings not in (["normal"], ["chaikin"]):
            raise ObjError(f"line {n}: expected `t creasemethod 0/0/1 normal|chaikin`")
        m.crease_method = strings[0]
    elif name == "smoothtriangles":
        ints, floats, strings = _tag_values(n, name, args)
        if ints or floats or strings not in (["catmark"], ["smooth"]):
            raise ObjError(f"line {n}: expected `t smoothtriangles 0/0/1 catmark|smooth`")
        m.triangles = strings[0]
    else:
        m.warnings.append(f"line {n}: ignored tag `{name}`")


def _digits(shortest):
    """profsubd's number text from Python's shortest repr: plain decimals for magnitudes in
    [1e-5, 1e16) or zero, otherwise `1.5e-7` (no `+`, no leading zeros in the exponent)."""
    x = float(shortest)
    mag = abs(x)
    if mag == 0.0 or 1e-5 <= mag < 1e16:
        s = format(Decimal(shortest), "f")
        return s.rstrip("0").rstrip(".") if "." in s else s
    mantissa, exponent = shortest.lower().split("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return f"{mantissa}e{int(exponent)}"


def num64(x):
    """A double with the fewest digits that read back to it, as profsubd writes it."""
    return _digits(repr(float(x)))


def num32(x):
    """A single-precision value with the fewest digits that read back to it as `float`."""
    x = f32(x)
    for digits in range(1, 10):
        s = f"{x:.{digits}g}"
        if f32(float(s)) == x:
            return _digits(repr(float(s)))
    return _digits(repr(x))


def write(m, header="# written by profsubd's Blender add-on; tags as OpenSubdiv's regression shapes"):
    """The OBJ text of a `TaggedMesh`, in the order and number format profsubd writes."""
    out = [header]
    out += [f"v {num64(x)} {num64(y)} {num64(z)}" for x, y, z in m.positions]
    out += ["f " + " ".join(str(i + 1) for i in f) for f in m.faces]
    if m.boundary is not None:
        out.append(f"t interpolateboundary 1/0/0 {m.boundary}")
    if m.crease_method is not None:
        out.append(f"t creasemethod 0/0/1 {m.crease_method}")
    if m.triangles is not None:
        out.append(f"t smoothtriangles 0/0/1 {m.triangles}")
    out += [f"t crease 2/1/0 {a} {b} {num32(s)}" for (a, b), s in m.creases]
    out += [f"t corner 1/1/0 {v} {num32(s)}" for v, s in m.corners]
    if m.holes:
        out.append(f"t hole {len(m.holes)}/0/0 " + " ".join(str(h) for h in m.holes))
    return "\n".join(out) + "\n"
