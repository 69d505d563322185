"""The header reader (profsubd/_lib.py) maps every declaration of profsubd.h, and the C
forms other constructions may add (fixed arrays, bool, callbacks, structs by value); what it
cannot map is left out by name instead of failing the import."""

import ctypes
import re

from profsubd import _lib

from conftest import REPO

SYNTHETIC = """
#define PROFSUBD_VERSION_MAJOR 3
typedef enum profsubd_status { PROFSUBD_OK = 0, } profsubd_status;
typedef enum profsubd_kind { PROFSUBD_KIND_A = 0, PROFSUBD_KIND_B_C = 7, } profsubd_kind;
typedef int32_t (*profsubd_progress_fn)(void *user, double fraction);
typedef struct profsubd_frame { double axis[3]; bool closed; } profsubd_frame;
typedef struct profsubd_job { size_t struct_size; struct profsubd_frame frame; const double *points; } profsubd_job;
typedef struct profsubd_weird { long double x; } profsubd_weird;
#ifdef __cplusplus
extern "C" {
#endif
/** A construction with a callback. */
enum profsubd_status profsubd_shell(const struct profsubd_mesh *base,
                                    profsubd_progress_fn progress,
                                    void (*log)(const char *line, void *user),
                                    const struct profsubd_options *options,
                                    struct profsubd_fitted **out);
double profsubd_frame_length(struct profsubd_frame frame, int32_t kind);
const char *profsubd_name(void);
void profsubd_weird_use(long double x);
#ifdef __cplusplus
}
#endif
"""


def test_synthetic_declarations():
    h = _lib.Header(SYNTHETIC)
    assert h.constants["PROFSUBD_VERSION_MAJOR"] == 3 and h.enums["profsubd_kind"]["PROFSUBD_KIND_B_C"] == 7
    frame = h.structs["profsubd_frame"]
    assert [(n, t) for n, t in frame._fields_] == [("axis", ctypes.c_double * 3), ("closed", ctypes.c_bool)]
    job = h.structs["profsubd_job"]
    assert [n for n, _ in job._fields_] == ["struct_size", "frame", "points"] and job._fields_[1][1] is frame
    ret, args = h.functions["profsubd_shell"]
    assert ret is ctypes.c_int32 and args == [ctypes.c_void_p] * 5
    assert h.functions["profsubd_frame_length"] == (ctypes.c_double, [frame, ctypes.c_int32])
    assert h.functions["profsubd_name"] == (ctypes.c_char_p, [])
    assert set(h.unsupported) == {"profsubd_weird", "profsubd_weird_use"}
    assert "profsubd_weird_use" not in h.functions


def test_every_function_of_the_real_header_is_mapped():
    text = (REPO / "include" / "profsubd.h").read_text()
    code = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    declared = set(re.findall(r"\b(profsubd_\w+)\s*\(", code))
    assert declared and declared == set(_lib.HEADER.functions) and not _lib.HEADER.unsupported
