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
from typing import Any, Dict, Optional, Tuple

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


def _ctype(decl: str, structs: Dict[str, Any]) -> Any:
    """The ctypes type of a C type as cbindgen writes it (``const double *``, ``struct x **``)."""
    decl = decl.replace("const ", "").strip()
    stars = decl.count("*")
    base = decl.replace("*", "").strip()
    base = re.sub(r"^(struct|enum)\s+", "", base)
    if stars == 0:
        if base in structs:
            return structs[base]
        if base.startswith("profsubd_"):  # an enum passed by value
            return ctypes.c_int32
        return _SCALARS[base]
    if stars == 1 and base == "char":
        return ctypes.c_char_p
    # Pointers are passed as addresses (NumPy buffers, byref, handles): no pointee checks.
    return ctypes.c_void_p


def _split_decl(param: str) -> Tuple[str, str]:
    m = re.match(r"^(.*?)(\w+)$", param.strip())
    if not m:
        raise ImportError(f"profsubd.h: cannot read parameter {param!r}")
    return m.group(1).strip(), m.group(2)


class Header:
    """What ``profsubd.h`` declares: constants, struct types, function signatures."""

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
        self.structs: Dict[str, Any] = {}
        for name, body in re.findall(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*\w+\s*;", code, flags=re.S):
            fields = []
            for member in body.split(";"):
                if member.strip():
                    ctype_decl, field = _split_decl(member)
                    fields.append((field, _ctype(ctype_decl, self.structs)))
            self.structs[name] = type(name, (ctypes.Structure,), {"_fields_": fields})
        self.functions: Dict[str, Tuple[Any, list]] = {}
        for ret, name, params in re.findall(
            r"((?:const\s+)?(?:enum\s+|struct\s+)?\w+\s*\**)\s*(profsubd_\w+)\s*\(([^)]*)\)\s*;", code
        ):
            params = params.strip()
            argtypes = []
            if params and params != "void":
                argtypes = [_ctype(_split_decl(p)[0], self.structs) for p in params.split(",")]
            ret = ret.strip()
            restype = None if ret == "void" else _ctype(ret, self.structs)
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
            raise AttributeError(f"{name} is not declared in profsubd.h") from None
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
