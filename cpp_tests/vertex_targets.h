// The check of a fitted model against OpenSubdiv shared by conformance_profile and
// conformance_sweep: the data points each control vertex must interpolate (read from a
// *.targets.txt file) and OpenSubdiv's limit position of every control vertex.
#pragma once

#include "osd_shape.h"

#include <opensubdiv/far/topologyRefiner.h>
#include <profsubd.h>

#include <string>
#include <vector>

namespace profsubd_test {

// Whitespace-separated doubles, 3 per vertex; false if the file is missing, empty or not a
// multiple of 3 long.
bool read_targets(const std::string &path, std::vector<double> *out);

// Bfr::Surface<double>'s limit position (approximation levels 10) of every vertex of `refiner`'s
// level 0, 3 doubles each: the surface of the vertex's first incident face evaluated at the
// vertex's corner. NaN for a vertex without faces or whose face has no limit surface.
std::vector<double> bfr_vertex_limits(const OpenSubdiv::Far::TopologyRefiner &refiner,
                                      const std::vector<double> &points);

// profsubd's exact limit position of every control vertex (profsubd_evaluator_limit_vertices,
// options from the mesh's tags), 3 doubles each; false if the C API fails.
bool profsubd_vertex_limits(const profsubd_mesh *mesh, std::vector<double> *out);

// The mesh as a reader of its OBJ file sees it: written to `path` by profsubd_mesh_write_obj,
// then parsed by the harness's reader, so `out->options` are the Sdc options its tags record.
// Returns an empty string on success, otherwise what failed.
std::string shape_via_obj(const profsubd_mesh *mesh, const std::string &path, OsdShape *out);

}  // namespace profsubd_test
