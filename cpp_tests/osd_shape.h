// The harness's own reader of OpenSubdiv regression shapes (OBJ + `t` tag lines) and the
// construction of a Far::TopologyRefiner from it through Far::TopologyDescriptor.
//
// Semantics follow OpenSubdiv's regression/common/shape_utils.cpp (parsing) and far_utils.h
// (applying tags), with two deliberate differences:
//  - coordinates are read as double (profsubd is f64; OpenSubdiv's harness reads float);
//  - with no `interpolateboundary` tag the boundary rule is profsubd's default,
//    edge-and-corner (the OpenSubdiv harness defaults to edge-only).
// Per-edge crease sharpness (`t crease 2k/k/0`) is read as one value per pair, as the tag
// format means it (the OpenSubdiv harness indexes it by int position; no shape uses it).
#pragma once

#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/sdc/options.h>

#include <memory>
#include <string>
#include <vector>

namespace profsubd_test {

// One `t` line.
struct OsdTag {
    int line = 0;  // 1-based line in the file
    std::string name;
    std::vector<int> ints;
    std::vector<float> floats;
    std::vector<std::string> strings;
};

// A control mesh in Far::TopologyDescriptor form, plus the tags it came with.
struct OsdShape {
    std::vector<double> positions;  // 3 per vertex
    std::vector<int> face_sizes;
    std::vector<int> face_indices;  // 0-based
    std::vector<int> crease_vertices;  // 2 per crease, in file order
    std::vector<float> crease_sharpness;
    std::vector<int> corner_vertices;
    std::vector<float> corner_sharpness;
    std::vector<int> holes;
    std::vector<OsdTag> tags;  // every tag line, in file order
    OpenSubdiv::Sdc::Options options;  // from the tags, profsubd defaults otherwise
    bool boundary_tagged = false;
    // Lines a reader must report as ignored or adjusted, one entry per warning: unknown
    // statements, tags without effect on vertex data (face-varying, hierarchical edits,
    // unknown names), each negative sharpness clamped to 0, and an option tag repeating an
    // earlier one.
    std::vector<int> warning_lines;

    int num_vertices() const { return static_cast<int>(positions.size() / 3); }
    int num_faces() const { return static_cast<int>(face_sizes.size()); }
};

// Parses OBJ text. Returns false and sets `error` ("line N: ...") on a malformed line.
bool parse_osd_shape(const std::string &text, OsdShape *out, std::string *error);

// Reads and parses a file.
bool read_osd_shape(const std::string &path, OsdShape *out, std::string *error);

// Sdc options as profsubd resolves them when nothing is tagged.
OpenSubdiv::Sdc::Options profsubd_default_options();

// Far refiner (level 0 only) of `shape` with `shape.options`; nullptr if Far rejects it.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> build_refiner(const OsdShape &shape);

// Same, with explicit options.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> build_refiner(
    const OsdShape &shape, const OpenSubdiv::Sdc::Options &options);

// Number of level-0 edges with exactly one incident face.
int count_boundary_edges(const OpenSubdiv::Far::TopologyLevel &level);

}  // namespace profsubd_test
