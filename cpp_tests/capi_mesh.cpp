#include "capi_mesh.h"

#include <cstring>

namespace profsubd_test {

namespace {

// Copy-out in two calls, as a C caller does: capacity 0 to learn the size (the documented
// answer is BUFFER_TOO_SMALL with *needed set, or OK when there is nothing to copy), then an
// exact buffer. Checks that the size learned equals `expected` and that the second call
// reports the same count.
template <class Call>
std::string two_call_copy(const char *what, size_t expected, Call call) {
    size_t needed = 12345;
    profsubd_status st = call(0, &needed);
    if (expected == 0) {
        if (st != PROFSUBD_OK || needed != 0) {
            return std::string(what) + ": capacity 0 on an empty array gave " + describe_status(st) +
                   ", needed " + std::to_string(needed);
        }
        return std::string();
    }
    if (st != PROFSUBD_ERROR_BUFFER_TOO_SMALL) {
        return std::string(what) + ": capacity 0 gave " + describe_status(st) +
               " instead of PROFSUBD_ERROR_BUFFER_TOO_SMALL";
    }
    if (needed != expected) {
        return std::string(what) + ": needed " + std::to_string(needed) + ", count query says " +
               std::to_string(expected);
    }
    size_t again = 0;
    st = call(needed, &again);
    if (st != PROFSUBD_OK || again != needed) {
        return std::string(what) + ": exact buffer gave " + describe_status(st) + ", needed " +
               std::to_string(again);
    }
    return std::string();
}

std::string count(const char *what, profsubd_status st) {
    if (st != PROFSUBD_OK) {
        return std::string(what) + ": " + describe_status(st);
    }
    return std::string();
}

}  // namespace

std::string describe_status(profsubd_status status) {
    std::string s = profsubd_status_string(static_cast<int32_t>(status));
    const char *msg = profsubd_last_error_message();
    return "status " + std::to_string(static_cast<int>(status)) + " (" + s + "): " + (msg ? msg : "(null)");
}

std::string read_capi_mesh(const profsubd_mesh *m, CapiMesh *out) {
    CapiMesh r;
    size_t n_creases = 0, n_corners = 0, n_holes = 0, n_face_indices = 0;
    std::string err;
    if (!(err = count("num_vertices", profsubd_mesh_num_vertices(m, &r.num_vertices))).empty() ||
        !(err = count("num_faces", profsubd_mesh_num_faces(m, &r.num_faces))).empty() ||
        !(err = count("num_edges", profsubd_mesh_num_edges(m, &r.num_edges))).empty() ||
        !(err = count("num_face_indices", profsubd_mesh_num_face_indices(m, &n_face_indices))).empty() ||
        !(err = count("num_creases", profsubd_mesh_num_creases(m, &n_creases))).empty() ||
        !(err = count("num_corners", profsubd_mesh_num_corners(m, &n_corners))).empty() ||
        !(err = count("num_holes", profsubd_mesh_num_holes(m, &n_holes))).empty()) {
        return err;
    }
    r.positions.resize(3 * r.num_vertices);
    r.face_sizes.resize(r.num_faces);
    r.face_indices.resize(n_face_indices);
    r.crease_vertices.resize(2 * n_creases);
    r.crease_sharpness.resize(n_creases);
    r.corner_vertices.resize(n_corners);
    r.corner_sharpness.resize(n_corners);
    r.holes.resize(n_holes);
    r.edges.resize(2 * r.num_edges);
    r.valences.resize(r.num_vertices);

    // Capacity is in elements of the array: doubles for positions, creases/corners/edges
    // for the per-component arrays.
    const std::string errors[] = {
        two_call_copy("get_positions", 3 * r.num_vertices, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_positions(m, cap ? r.positions.data() : nullptr, cap, need);
        }),
        two_call_copy("get_face_sizes", r.num_faces, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_face_sizes(m, cap ? r.face_sizes.data() : nullptr, cap, need);
        }),
        two_call_copy("get_face_indices", n_face_indices, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_face_indices(m, cap ? r.face_indices.data() : nullptr, cap, need);
        }),
        two_call_copy("get_creases", n_creases, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_creases(m, cap ? r.crease_vertices.data() : nullptr,
                                             cap ? r.crease_sharpness.data() : nullptr, cap, need);
        }),
        two_call_copy("get_corners", n_corners, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_corners(m, cap ? r.corner_vertices.data() : nullptr,
                                             cap ? r.corner_sharpness.data() : nullptr, cap, need);
        }),
        two_call_copy("get_holes", n_holes, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_holes(m, cap ? r.holes.data() : nullptr, cap, need);
        }),
        two_call_copy("get_edges", r.num_edges, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_edges(m, cap ? r.edges.data() : nullptr, cap, need);
        }),
        two_call_copy("get_valences", r.num_vertices, [&](size_t cap, size_t *need) {
            return profsubd_mesh_get_valences(m, cap ? r.valences.data() : nullptr, cap, need);
        }),
    };
    for (const std::string &e : errors) {
        if (!e.empty()) {
            return e;
        }
    }
    std::memset(&r.report, 0, sizeof r.report);
    r.report.struct_size = sizeof r.report;
    profsubd_status st = profsubd_mesh_check(m, &r.report);
    if (st != PROFSUBD_OK) {
        return "mesh_check: " + describe_status(st);
    }
    *out = std::move(r);
    return std::string();
}

MeshPtr load_obj_capi(const std::string &path, std::string *error) {
    profsubd_mesh *m = nullptr;
    profsubd_status st = profsubd_mesh_read_obj(path.c_str(), &m);
    if (st != PROFSUBD_OK) {
        if (error != nullptr) {
            *error = describe_status(st);
        }
        return MeshPtr();
    }
    return MeshPtr(m);
}

EvaluatorPtr new_evaluator_capi(const OsdShape &shape, const OpenSubdiv::Sdc::Options &options,
                                std::string *error) {
    std::string err;
    MeshPtr mesh = new_mesh_capi(shape, &err);
    if (!mesh) {
        *error = "profsubd_mesh_new: " + err;
        return EvaluatorPtr();
    }
    OptionsPtr o = capi_options(options);
    profsubd_evaluator *raw = nullptr;
    profsubd_status st = profsubd_evaluator_new(mesh.get(), o.get(), &raw);
    if (st != PROFSUBD_OK) {
        *error = "profsubd_evaluator_new: " + describe_status(st);
        return EvaluatorPtr();
    }
    return EvaluatorPtr(raw);
}

MeshPtr new_mesh_capi(const OsdShape &s, std::string *error) {
    std::vector<uint32_t> sizes(s.face_sizes.begin(), s.face_sizes.end());
    std::vector<uint32_t> indices(s.face_indices.begin(), s.face_indices.end());
    std::vector<uint32_t> creases(s.crease_vertices.begin(), s.crease_vertices.end());
    std::vector<uint32_t> corners(s.corner_vertices.begin(), s.corner_vertices.end());
    std::vector<uint32_t> holes(s.holes.begin(), s.holes.end());
    profsubd_mesh_desc d;
    std::memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.positions = s.positions.data();
    d.num_vertices = s.positions.size() / 3;
    d.face_sizes = sizes.data();
    d.num_faces = sizes.size();
    d.face_indices = indices.data();
    d.num_face_indices = indices.size();
    d.crease_vertices = creases.data();
    d.crease_sharpness = s.crease_sharpness.data();
    d.num_creases = s.crease_sharpness.size();
    d.corner_vertices = corners.data();
    d.corner_sharpness = s.corner_sharpness.data();
    d.num_corners = s.corner_sharpness.size();
    d.hole_faces = holes.data();
    d.num_holes = holes.size();
    profsubd_mesh *m = nullptr;
    profsubd_status st = profsubd_mesh_new(&d, &m);
    if (st != PROFSUBD_OK) {
        if (error != nullptr) {
            *error = describe_status(st);
        }
        return MeshPtr();
    }
    return MeshPtr(m);
}

OsdShape to_osd_shape(const CapiMesh &c, const OpenSubdiv::Sdc::Options &options) {
    OsdShape s;
    s.positions = c.positions;
    s.face_sizes.assign(c.face_sizes.begin(), c.face_sizes.end());
    s.face_indices.assign(c.face_indices.begin(), c.face_indices.end());
    s.crease_vertices.assign(c.crease_vertices.begin(), c.crease_vertices.end());
    s.crease_sharpness = c.crease_sharpness;
    s.corner_vertices.assign(c.corner_vertices.begin(), c.corner_vertices.end());
    s.corner_sharpness = c.corner_sharpness;
    s.holes.assign(c.holes.begin(), c.holes.end());
    s.options = options;
    return s;
}

OptionsPtr capi_options(const OpenSubdiv::Sdc::Options &options) {
    using Sdc = OpenSubdiv::Sdc::Options;
    profsubd_options *raw = nullptr;
    if (profsubd_options_new(&raw) != PROFSUBD_OK) return nullptr;
    OptionsPtr out(raw);
    int32_t boundary = PROFSUBD_BOUNDARY_EDGE_AND_CORNER;
    switch (options.GetVtxBoundaryInterpolation()) {
        case Sdc::VTX_BOUNDARY_NONE: boundary = PROFSUBD_BOUNDARY_NONE; break;
        case Sdc::VTX_BOUNDARY_EDGE_ONLY: boundary = PROFSUBD_BOUNDARY_EDGE_ONLY; break;
        default: break;
    }
    int32_t crease = options.GetCreasingMethod() == Sdc::CREASE_CHAIKIN ? PROFSUBD_CREASE_CHAIKIN
                                                                        : PROFSUBD_CREASE_UNIFORM;
    int32_t triangles = options.GetTriangleSubdivision() == Sdc::TRI_SUB_SMOOTH ? PROFSUBD_TRIANGLES_SMOOTH
                                                                                : PROFSUBD_TRIANGLES_CATMARK;
    if (profsubd_options_set_boundary(raw, boundary) != PROFSUBD_OK ||
        profsubd_options_set_crease_method(raw, crease) != PROFSUBD_OK ||
        profsubd_options_set_triangle_rule(raw, triangles) != PROFSUBD_OK) {
        return nullptr;
    }
    return out;
}

}  // namespace profsubd_test
