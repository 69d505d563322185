"""PEP 517 backend of the profsubd Python package (no third-party requirements).

``build_wheel`` builds the repository's shared library with ``cargo build --release --lib``
(or takes ``$PROFSUBD_LIBRARY``), and writes a wheel holding the ``profsubd`` package, the
library and the C header it reads the ABI from. The version is the crate's (Cargo.toml).
"""

from __future__ import annotations

import base64
import hashlib
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

HERE = Path(__file__).resolve().parent.parent  # python/
REPO = HERE.parent
NAME = "profsubd"


def _version() -> str:
    cargo = (REPO / "Cargo.toml").read_text(encoding="utf-8")
    m = re.search(r'^version\s*=\s*"([^"]+)"', cargo, flags=re.M)
    if not m:
        raise RuntimeError("no version in Cargo.toml")
    return m.group(1)


def _library() -> Path:
    env = os.environ.get("PROFSUBD_LIBRARY")
    if env:
        return Path(env)
    if not (REPO / "Cargo.toml").is_file():
        raise RuntimeError("not in a profsubd clone: set PROFSUBD_LIBRARY=/path/to/libprofsubd.so")
    cargo = shutil.which("cargo") or str(Path.home() / ".cargo" / "bin" / "cargo")
    cmd = [cargo, "build", "--release", "--lib", "--manifest-path", str(REPO / "Cargo.toml")]
    print("profsubd build:", " ".join(cmd), file=sys.stderr, flush=True)
    # cargo's output to stderr: pip shows it with -v, and stdout stays free for pip's hooks.
    subprocess.run(cmd, check=True, stdout=sys.stderr)
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    if not target.is_absolute():
        target = REPO / target
    return target / "release" / "libprofsubd.so"


def _metadata(version: str) -> str:
    readme = (HERE / "README.md").read_text(encoding="utf-8")
    return (
        "Metadata-Version: 2.1\n"
        f"Name: {NAME}\nVersion: {version}\n"
        "Summary: Profile curves to Catmull-Clark control meshes with crease tags, and an exact "
        "Catmull-Clark evaluator (OpenSubdiv 3.5 rules), over libprofsubd's C ABI\n"
        "Requires-Python: >=3.8\nRequires-Dist: numpy\n"
        "Description-Content-Type: text/markdown\n\n" + readme
    )


def _tag() -> str:
    plat = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"py3-none-{plat}"


def _record_line(arcname: str, data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}"


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version = _version()
    library = _library()
    if not library.is_file():
        raise RuntimeError(f"{library}: no such library")
    files = {}
    for src in sorted((HERE / NAME).glob("*")):
        if src.suffix in (".py", ".typed"):
            files[f"{NAME}/{src.name}"] = src.read_bytes()
    files[f"{NAME}/libprofsubd.so"] = library.read_bytes()
    files[f"{NAME}/profsubd.h"] = (REPO / "include" / "profsubd.h").read_bytes() if (
        REPO / "include" / "profsubd.h").is_file() else (HERE / NAME / "profsubd.h").read_bytes()
    dist = f"{NAME}-{version}.dist-info"
    files[f"{dist}/METADATA"] = _metadata(version).encode()
    files[f"{dist}/WHEEL"] = (
        f"Wheel-Version: 1.0\nGenerator: profsubd_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n"
    ).encode()
    record = [_record_line(k, v) for k, v in files.items()] + [f"{dist}/RECORD,,"]
    files[f"{dist}/RECORD"] = ("\n".join(record) + "\n").encode()
    wheel_name = f"{NAME}-{version}-{_tag()}.whl"
    with zipfile.ZipFile(Path(wheel_directory) / wheel_name, "w", zipfile.ZIP_DEFLATED) as zf:
        for arcname, data in files.items():
            info = zipfile.ZipInfo(arcname, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if arcname.endswith(".so") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, data)
    return wheel_name


def get_requires_for_build_wheel(config_settings=None):
    return []
