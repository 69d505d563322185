"""Loading ``libprofsubd.so`` and declaring its functions from ``profsubd.h``.

The C header is the one description of the C ABI: this module reads the function prototypes,
struct layouts and enumerated constants from it (the copy bundled in the package, else the
repository's ``include/profsubd.h``) and gives every function its ``argtypes`` and
``restype``, so a C entry point added to the header is callable from Python without a
hand-written declaration.

Where the library comes from, first found wins: ``$PROFSUBD_LIBRARY`` (a path to
``libprofsubd.so``), the copy bundled in the package, the repository's
``target/release/libprofsubd.so`` (running from a clone without installing).
"""

from __future__ import annotations

import ctypes
import os
import re
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple

_HERE = Path(__file__).resolve().parent
_REPO = _HERE.parent.parent

_SCALARS: Dict[str, Any] = {
    "double": ctypes.c_double,
    "float": ctypes.c_float,
    "size_t": ctypes.c_size_t,
    "uint8_t": ctypes.c_uint8,
    "int32_t": ctypes.c_int32,
    "uint32_t": ctypes.c_uint32,
    "int64_t": ctypes.c_int64,
    "uint64_t": ctypes.c_uint64,
    "int": ctypes.c_int,
    "bool": ctypes.c_bool,
    "int8_t": ctypes.c_int8,
    "int16_t": ctypes.c_int16,
    "uint16_t": ctypes.c_uint16,
    "char": ctypes.c_char,
}


def _find_header() -> Path:
    for candidate in (_HERE / "profsubd.h", _REPO / "include" / "profsubd.h"):
        if candidate.is_file():
            return candidate
    raise ImportError("profsubd.h not found (neither bundled nor in the repository's include/)")


def _find_library() -> str:
    env = os.environ.get("PROFSUBD_LIBRARY")
    if env:
        if not Path(env).is_file():
            raise ImportError(f"PROFSUBD_LIBRARY={env}: no such file")
        return env
    for candidate in (
        _HERE / "libprofsubd.so",
        Path(os.environ.get("CARGO_TARGET_DIR", _REPO / "target")) / "release" / "libprofsubd.so",
    ):
        if candidate.is_file():
            return str(candidate)
    raise ImportError(
        "libprofsubd.so not found: install the package with `pip install ./python` "
        "(it builds and bundles the library) or set PROFSUBD_LIBRARY=/path/to/libprofsubd.so"
    )


def _strip_comments(text: str) -> str:
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


class Unsupported(Exception):
    """A declaration this reader cannot map to ctypes (its function is left out)."""


def _ctype(decl: str, header: "Header") -> Any:
    """The ctypes type of a C type as cbindgen writes it (``const double *``, ``struct x **``)."""
    decl = re.sub(r"\bconst\b", " ", decl).strip()
    stars = decl.count("*")
    base = re.sub(r"^(struct|enum)\s+", "", decl.replace("*", " ").strip())
    if stars == 0:
        if base in header.structs:
            return header.structs[base]
        if base in header.enums:
            return ctypes.c_int32  # passed as int32_t by the C API's rules
        if base in header.callback_types:
            return ctypes.c_void_p
        if base in _SCALARS:
            return _SCALARS[base]
        raise Unsupported(f"type {decl!r}")
    if stars == 1 and base == "char":
        return ctypes.c_char_p
    # Pointers are passed as addresses (NumPy buffers, byref, handles): no pointee checks.
    return ctypes.c_void_p


def _split_top(text: str, sep: str) -> List[str]:
    """``text`` split at ``sep`` outside parentheses and braces."""
    parts: List[str] = []
    cur: List[str] = []
    depth = 0
    for ch in text:
        depth += ch in "({"
        depth -= ch in ")}"
        if ch == sep and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    parts.append("".join(cur))
    return [p.strip() for p in parts if p.strip()]


def _declarator(param: str, header: "Header") -> Tuple[Any, str]:
    """``(ctypes type, name)`` of ``type name``, ``type name[N]`` or a function pointer."""
    fn = re.search(r"\(\s*\*\s*(\w+)\s*\)\s*\(", param)
    if fn:
        return ctypes.c_void_p, fn.group(1)
    m = re.match(r"^(.*?)(\w+)\s*(?:\[\s*(\d+)\s*\])?$", param.strip(), flags=re.S)
    if not m or not m.group(1).strip():
        raise Unsupported(f"declaration {param!r}")
    t = _ctype(m.group(1), header)
    return (t * int(m.group(3)) if m.group(3) else t), m.group(2)


class Header:
    """What ``profsubd.h`` declares: constants, struct types, function signatures.
    Declarations it cannot map (``unsupported``) are left out rather than failing the import."""

    def __init__(self, text: str) -> None:
        code = _strip_comments(text)
        self.constants: Dict[str, int] = {}
        self.enums: Dict[str, Dict[str, int]] = {}
        for name, body in re.findall(r"typedef\s+enum\s+(\w+)\s*\{(.*?)\}", code, flags=re.S):
            members = dict((k, int(v)) for k, v in re.findall(r"(\w+)\s*=\s*(-?\d+)", body))
            self.enums[name] = members
            self.constants.update(members)
        for k, v in re.findall(r"#define\s+(PROFSUBD_\w+)\s+(\d+)", code):
            self.constants[k] = int(v)
        self.callback_types = set(re.findall(r"typedef[^;{]*?\(\s*\*\s*(\w+)\s*\)\s*\(", code))
        self.unsupported: Dict[str, str] = {}
        self.structs: Dict[str, Any] = {}
        for name, body in re.findall(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*\w+\s*;", code, flags=re.S):
            try:
                fields = [tuple(reversed(_declarator(m, self))) for m in _split_top(body, ";")]
            except Unsupported as e:
                self.unsupported[name] = str(e)
                continue
            self.structs[name] = type(name, (ctypes.Structure,), {"_fields_": fields})
        # Function declarations: what is left without typedefs and preprocessor lines.
        rest = re.sub(r"typedef\s+(struct|enum)\s+\w+\s*\{.*?\}\s*\w+\s*;", " ", code, flags=re.S)
        rest = re.sub(r"^\s*#.*$", " ", rest, flags=re.M)
        rest = re.sub(r'extern\s+"C"\s*\{', " ", rest)
        self.functions: Dict[str, Tuple[Any, list]] = {}
        for stmt in _split_top(rest, ";"):
            m = re.search(r"([\w\s\*]*?)\b(profsubd_\w+)\s*\((.*)\)\s*$", stmt, flags=re.S)
            if not m or stmt.lstrip("} \n").startswith("typedef"):
                continue
            ret, name, params = m.group(1).strip().lstrip("}").strip(), m.group(2), m.group(3).strip()
            try:
                argtypes = [] if params in ("", "void") else [_declarator(p, self)[0] for p in _split_top(params, ",")]
                restype = None if ret == "void" else _ctype(ret, self)
            except Unsupported as e:
                self.unsupported[name] = str(e)
                continue
            self.functions[name] = (restype, argtypes)


HEADER = Header(_find_header().read_text(encoding="utf-8"))
LIBRARY_PATH = _find_library()
_dll = ctypes.CDLL(LIBRARY_PATH)


class _Functions:
    """The library's functions, typed from the header, as attributes (``lib.profsubd_mesh_new``)."""

    def __getattr__(self, name: str) -> Any:
        try:
            restype, argtypes = HEADER.functions[name]
        except KeyError:
            why = HEADER.unsupported.get(name)
            raise AttributeError(f"{name}: " + (f"not callable from Python ({why})" if why
                                                 else "not declared in profsubd.h")) from None
        fn = getattr(_dll, name)
        fn.restype = restype
        fn.argtypes = argtypes
        setattr(self, name, fn)
        return fn


lib = _Functions()


def struct(name: str) -> Any:
    """The ctypes Structure of the header's ``name`` (``profsubd_mesh_desc``...)."""
    return HEADER.structs[name]


def new_struct(name: str) -> Any:
    """A zeroed instance of struct ``name``, with ``struct_size`` set when it has one."""
    s = HEADER.structs[name]()
    if any(f == "struct_size" for f, _ in s._fields_):
        s.struct_size = ctypes.sizeof(s)
    return s


def constant(name: str) -> int:
    """A named constant of the header (``PROFSUBD_BOUNDARY_EDGE_ONLY``...)."""
    return HEADER.constants[name]


def enum_values(enum: str, prefix: str) -> Dict[str, int]:
    """``{"edge-only": 1, ...}`` for the members of ``enum`` named ``prefix + NAME``."""
    out: Dict[str, int] = {}
    for k, v in HEADER.enums[enum].items():
        if k.startswith(prefix):
            out[k[len(prefix):].lower().replace("_", "-")] = v
    return out


def last_message() -> str:
    """The thread's last error message of the library."""
    raw: Optional[bytes] = lib.profsubd_last_error_message()
    return raw.decode("utf-8", "replace") if raw else ""
