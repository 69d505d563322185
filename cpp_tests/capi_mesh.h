// A profsubd mesh read back through the C API (include/profsubd.h only): every count and
// every array, each copy-out done the documented way (ask for the size, then fill), with the
// buffer protocol itself checked on the way.
#pragma once

#include "osd_shape.h"

#include <profsubd.h>

#include <memory>
#include <string>
#include <vector>

namespace profsubd_test {

struct MeshDeleter {
    void operator()(profsubd_mesh *m) const { profsubd_mesh_free(m); }
};
using MeshPtr = std::unique_ptr<profsubd_mesh, MeshDeleter>;

struct OptionsDeleter {
    void operator()(profsubd_options *o) const { profsubd_options_free(o); }
};
using OptionsPtr = std::unique_ptr<profsubd_options, OptionsDeleter>;

// A profsubd_options with the boundary rule, crease method and triangle rule of `options` set
// explicitly; null if a call fails (profsubd_last_error_message() says why).
OptionsPtr capi_options(const OpenSubdiv::Sdc::Options &options);

// "PROFSUBD_ERROR_PARSE (malformed input file): <last error message>".
std::string describe_status(profsubd_status status);

// Everything the C API tells about a mesh.
struct CapiMesh {
    size_t num_vertices = 0;
    size_t num_faces = 0;
    size_t num_edges = 0;
    std::vector<double> positions;  // 3 per vertex
    std::vector<uint32_t> face_sizes;
    std::vector<uint32_t> face_indices;
    std::vector<uint32_t> crease_vertices;  // 2 per crease
    std::vector<float> crease_sharpness;
    std::vector<uint32_t> corner_vertices;
    std::vector<float> corner_sharpness;
    std::vector<uint32_t> holes;
    std::vector<uint32_t> edges;  // 2 per edge, Far's level-0 edge order
    std::vector<uint32_t> valences;  // edges at each vertex
    profsubd_mesh_report report{};
};

// Reads `mesh` completely. Returns an empty string on success, otherwise what went wrong
// (a failing call, or a copy-out that broke the buffer protocol).
std::string read_capi_mesh(const profsubd_mesh *mesh, CapiMesh *out);

// profsubd_mesh_read_obj; on failure `error` gets the status description.
MeshPtr load_obj_capi(const std::string &path, std::string *error);

// profsubd_mesh_new from an OsdShape's arrays; on failure `error` gets the status description.
MeshPtr new_mesh_capi(const OsdShape &shape, std::string *error);

struct EvaluatorDeleter {
    void operator()(profsubd_evaluator *e) const { profsubd_evaluator_free(e); }
};
using EvaluatorPtr = std::unique_ptr<profsubd_evaluator, EvaluatorDeleter>;

// profsubd_evaluator_new for `shape` (through new_mesh_capi) under `options`; on failure
// `error` says which call failed and why.
EvaluatorPtr new_evaluator_capi(const OsdShape &shape, const OpenSubdiv::Sdc::Options &options,
                                std::string *error);

// The C API's data as an OsdShape with the given options, to build a Far refiner from it.
OsdShape to_osd_shape(const CapiMesh &mesh, const OpenSubdiv::Sdc::Options &options);

}  // namespace profsubd_test
