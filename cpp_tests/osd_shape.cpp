#include "osd_shape.h"

#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace profsubd_test {

using OpenSubdiv::Sdc::Options;
namespace Far = OpenSubdiv::Far;

namespace {

std::vector<std::string> split_ws(const std::string &line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    std::string tok;
    while (in >> tok) {
        out.push_back(tok);
    }
    return out;
}

bool to_int(const std::string &s, int *v) {
    errno = 0;
    char *end = nullptr;
    long x = std::strtol(s.c_str(), &end, 10);
    if (end == s.c_str() || *end != '\0' || errno != 0 || x < INT32_MIN || x > INT32_MAX) {
        return false;
    }
    *v = static_cast<int>(x);
    return true;
}

bool to_double(const std::string &s, double *v) {
    errno = 0;
    char *end = nullptr;
    *v = std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0' && errno == 0;
}

// Statements with no vertex data that need no mention.
bool is_silent_statement(const std::string &keyword) {
    static const char *const kNames[] = {"vt", "vn", "g", "o", "s", "usemtl", "mtllib"};
    return std::find(std::begin(kNames), std::end(kNames), keyword) != std::end(kNames);
}

bool fail(std::string *error, int line, const std::string &what) {
    if (error != nullptr) {
        *error = "line " + std::to_string(line) + ": " + what;
    }
    return false;
}

// "a/b/c" -> a (the vertex index; texture and normal indices are not vertex data).
bool face_vertex(const std::string &tok, int *v) {
    return to_int(tok.substr(0, tok.find('/')), v);
}

bool parse_tag(const std::vector<std::string> &tok, OsdTag *tag) {
    // t NAME ni/nf/ns ints... floats... strings...
    if (tok.size() < 3) {
        return false;
    }
    tag->name = tok[1];
    int counts[3];
    std::istringstream c(tok[2]);
    char slash1 = 0, slash2 = 0;
    if (!(c >> counts[0] >> slash1 >> counts[1] >> slash2 >> counts[2]) || slash1 != '/' ||
        slash2 != '/' || counts[0] < 0 || counts[1] < 0 || counts[2] < 0) {
        return false;
    }
    std::size_t need = 3 + static_cast<std::size_t>(counts[0]) + counts[1] + counts[2];
    if (tok.size() < need) {
        return false;
    }
    std::size_t k = 3;
    for (int i = 0; i < counts[0]; ++i, ++k) {
        int v;
        if (!to_int(tok[k], &v)) {
            return false;
        }
        tag->ints.push_back(v);
    }
    for (int i = 0; i < counts[1]; ++i, ++k) {
        double v;
        if (!to_double(tok[k], &v)) {
            return false;
        }
        tag->floats.push_back(static_cast<float>(v));
    }
    for (int i = 0; i < counts[2]; ++i, ++k) {
        tag->strings.push_back(tok[k]);
    }
    return true;
}

// Sharpness of item j of a tag: one value for all, or one per item; negatives clamp to 0
// as in OpenSubdiv's harness.
float tag_sharpness(const OsdTag &t, std::size_t item) {
    float s = 0.0f;
    if (t.floats.size() > 1 && item < t.floats.size()) {
        s = t.floats[item];
    } else if (!t.floats.empty()) {
        s = t.floats[0];
    }
    return std::max(0.0f, s);
}

bool is_vertex_tag(const std::string &name) {
    static const char *const kNames[] = {"crease", "corner", "hole", "interpolateboundary", "creasemethod",
                                         "smoothtriangles"};
    return std::find(std::begin(kNames), std::end(kNames), name) != std::end(kNames);
}

// Applies the tags that carry topology or options (far_utils.h semantics) and notes the
// warnings they deserve.
void apply_tags(OsdShape *s) {
    std::vector<std::string> options_seen;
    for (const OsdTag &t : s->tags) {
        if (!is_vertex_tag(t.name)) {
            s->warning_lines.push_back(t.line);
            continue;
        }
        for (float f : t.floats) {
            if (f < 0.0f) {
                s->warning_lines.push_back(t.line);
            }
        }
        if (t.name == "interpolateboundary" || t.name == "creasemethod" || t.name == "smoothtriangles") {
            if (std::find(options_seen.begin(), options_seen.end(), t.name) != options_seen.end()) {
                s->warning_lines.push_back(t.line);
            }
            options_seen.push_back(t.name);
        }
        if (t.name == "crease") {
            for (std::size_t j = 0; j + 1 < t.ints.size(); j += 2) {
                s->crease_vertices.push_back(t.ints[j]);
                s->crease_vertices.push_back(t.ints[j + 1]);
                s->crease_sharpness.push_back(tag_sharpness(t, j / 2));
            }
        } else if (t.name == "corner") {
            for (std::size_t j = 0; j < t.ints.size(); ++j) {
                s->corner_vertices.push_back(t.ints[j]);
                s->corner_sharpness.push_back(tag_sharpness(t, j));
            }
        } else if (t.name == "hole") {
            s->holes.insert(s->holes.end(), t.ints.begin(), t.ints.end());
        } else if (t.name == "interpolateboundary" && t.ints.size() == 1) {
            switch (t.ints[0]) {
            case 0: s->options.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_NONE); break;
            case 1: s->options.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_EDGE_AND_CORNER); break;
            case 2: s->options.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_EDGE_ONLY); break;
            default: continue;
            }
            s->boundary_tagged = true;
        } else if (t.name == "creasemethod" && !t.strings.empty()) {
            if (t.strings[0] == "normal") {
                s->options.SetCreasingMethod(Options::CREASE_UNIFORM);
            } else if (t.strings[0] == "chaikin") {
                s->options.SetCreasingMethod(Options::CREASE_CHAIKIN);
            }
        } else if (t.name == "smoothtriangles" && !t.strings.empty()) {
            if (t.strings[0] == "catmark") {
                s->options.SetTriangleSubdivision(Options::TRI_SUB_CATMARK);
            } else if (t.strings[0] == "smooth") {
                s->options.SetTriangleSubdivision(Options::TRI_SUB_SMOOTH);
            }
        }
    }
}

}  // namespace

Options profsubd_default_options() {
    Options o;
    o.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    o.SetCreasingMethod(Options::CREASE_UNIFORM);
    o.SetTriangleSubdivision(Options::TRI_SUB_CATMARK);
    return o;
}

bool parse_osd_shape(const std::string &text, OsdShape *out, std::string *error) {
    OsdShape s;
    s.options = profsubd_default_options();
    std::istringstream in(text);
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        line = line.substr(0, line.find('#'));  // comments, also after a statement
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        std::vector<std::string> tok = split_ws(line);
        if (tok.empty()) {
            continue;
        }
        if (tok[0] == "v") {
            double x, y, z;
            if (tok.size() < 4 || !to_double(tok[1], &x) || !to_double(tok[2], &y) ||
                !to_double(tok[3], &z)) {
                return fail(error, line_no, "expected 'v x y z'");
            }
            s.positions.insert(s.positions.end(), {x, y, z});
        } else if (tok[0] == "f") {
            for (std::size_t i = 1; i < tok.size(); ++i) {
                int v;
                if (!face_vertex(tok[i], &v) || v < 1) {
                    return fail(error, line_no, "expected 1-based vertex index, got '" + tok[i] + "'");
                }
                s.face_indices.push_back(v - 1);
            }
            s.face_sizes.push_back(static_cast<int>(tok.size() - 1));
        } else if (tok[0] == "t") {
            OsdTag tag;
            if (!parse_tag(tok, &tag)) {
                return fail(error, line_no, "malformed tag line");
            }
            tag.line = line_no;
            s.tags.push_back(std::move(tag));
        } else if (!is_silent_statement(tok[0])) {
            s.warning_lines.push_back(line_no);
        }
    }
    apply_tags(&s);
    std::sort(s.warning_lines.begin(), s.warning_lines.end());
    *out = std::move(s);
    return true;
}

bool read_osd_shape(const std::string &path, OsdShape *out, std::string *error) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        if (error != nullptr) {
            *error = "cannot open " + path;
        }
        return false;
    }
    std::ostringstream text;
    text << f.rdbuf();
    if (!parse_osd_shape(text.str(), out, error)) {
        if (error != nullptr) {
            *error = path + ": " + *error;
        }
        return false;
    }
    return true;
}

std::unique_ptr<Far::TopologyRefiner> build_refiner(const OsdShape &shape) {
    return build_refiner(shape, shape.options);
}

std::unique_ptr<Far::TopologyRefiner> build_refiner(const OsdShape &shape, const Options &options) {
    Far::TopologyDescriptor desc;
    desc.numVertices = shape.num_vertices();
    desc.numFaces = shape.num_faces();
    desc.numVertsPerFace = shape.face_sizes.data();
    desc.vertIndicesPerFace = shape.face_indices.data();
    desc.numCreases = static_cast<int>(shape.crease_sharpness.size());
    desc.creaseVertexIndexPairs = shape.crease_vertices.data();
    desc.creaseWeights = shape.crease_sharpness.data();
    desc.numCorners = static_cast<int>(shape.corner_sharpness.size());
    desc.cornerVertexIndices = shape.corner_vertices.data();
    desc.cornerWeights = shape.corner_sharpness.data();
    desc.numHoles = static_cast<int>(shape.holes.size());
    desc.holeIndices = shape.holes.data();

    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    Factory::Options fo(OpenSubdiv::Sdc::SCHEME_CATMARK, options);
    fo.validateFullTopology = true;
    return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(desc, fo));
}

int count_boundary_edges(const Far::TopologyLevel &level) {
    int n = 0;
    for (int e = 0; e < level.GetNumEdges(); ++e) {
        n += level.GetEdgeFaces(e).size() == 1;
    }
    return n;
}

}  // namespace profsubd_test
