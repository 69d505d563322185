// The harness's own shape reader, checked against the shapes folder's INDEX.tsv (vertex and
// face counts, face sizes, tags, boundary-edge counts) and against Far, which must accept
// every shape. Runs before the profsubd comparisons rely on the reader.
#include "osd_shape.h"
#include "test_support.h"

#include <opensubdiv/far/topologyLevel.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace profsubd_test;
using OpenSubdiv::Sdc::Options;

namespace {

struct IndexRow {
    int verts = 0;
    int faces = 0;
    bool all_quads = false;
    bool has_creases = false;
    bool has_corners = false;
    std::string boundary;
    std::string notes;
};

std::map<std::string, IndexRow> read_index(const std::string &path) {
    std::map<std::string, IndexRow> rows;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<std::string> col;
        std::istringstream s(line);
        std::string c;
        while (std::getline(s, c, '\t')) {
            col.push_back(c);
        }
        if (col.size() < 7) {
            continue;
        }
        IndexRow r;
        r.verts = std::stoi(col[1]);
        r.faces = std::stoi(col[2]);
        r.all_quads = col[3] == "yes";
        r.has_creases = col[4] == "yes";
        r.has_corners = col[5] == "yes";
        r.boundary = col[6];
        r.notes = col.size() > 7 ? col[7] : "";
        rows[col[0]] = r;
    }
    return rows;
}

// The reader on text with known content: multi-edge and per-edge crease forms, corner
// lists, holes, options, `a/b/c` face vertices.
void check_reader_on_inline_text(Checker &ck) {
    ck.set_context("inline text");
    const std::string text =
        "# two quads\n"
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0.125\n"
        "vt 0 0\n"
        "f 1/1 2/1 5/1 4/1\n"
        "f 2 3 6 5\r\n"
        "t crease 4/1/0 0 1 1 2 2.5\n"
        "t crease 4/2/0 3 4 4 5 1.5 -3\n"
        "t corner 2/2/0 0 5 4 10\n"
        "t hole 1/0/0 1\n"
        "t interpolateboundary 1/0/0 2\n"
        "t creasemethod 0/0/1 chaikin\n"
        "t smoothtriangles 0/0/1 smooth\n"
        "t facevaryinginterpolateboundary 1/0/0 1\n"
        "t interpolateboundary 1/0/0 2\n"
        "bevel on\n"
        "g group # comment\n";
    OsdShape s;
    std::string err;
    if (!ck.check(parse_osd_shape(text, &s, &err), "parse: " + err)) {
        return;
    }
    ck.equal(s.num_vertices(), 6, "vertices");
    ck.equal(s.positions[17], 0.125, "z of vertex 5");
    ck.check(s.face_indices == std::vector<int>({0, 1, 4, 3, 1, 2, 5, 4}), "face indices");
    ck.check(s.crease_vertices == std::vector<int>({0, 1, 1, 2, 3, 4, 4, 5}), "crease pairs");
    ck.check(s.crease_sharpness == std::vector<float>({2.5f, 2.5f, 1.5f, 0.0f}),
             "crease sharpness (shared, per edge, negative clamped)");
    ck.check(s.corner_vertices == std::vector<int>({0, 5}), "corner vertices");
    ck.check(s.corner_sharpness == std::vector<float>({4.0f, 10.0f}), "corner sharpness");
    ck.check(s.holes == std::vector<int>({1}), "holes");
    ck.equal(int(s.options.GetVtxBoundaryInterpolation()), int(Options::VTX_BOUNDARY_EDGE_ONLY),
             "interpolateboundary 2 = edge only");
    ck.equal(int(s.options.GetCreasingMethod()), int(Options::CREASE_CHAIKIN), "creasemethod");
    ck.equal(int(s.options.GetTriangleSubdivision()), int(Options::TRI_SUB_SMOOTH), "smoothtriangles");
    ck.check(s.warning_lines == std::vector<int>({12, 18, 19, 20}),
             "warnings: negative sharpness, face-varying tag, repeated option, unknown statement");

    auto refiner = build_refiner(s);
    if (!ck.check(refiner != nullptr, "Far accepts the inline mesh")) {
        return;
    }
    const auto &l = refiner->GetLevel(0);
    ck.equal(l.GetNumEdges(), 7, "edges");
    ck.equal(count_boundary_edges(l), 6, "boundary edges");
    // The one interior edge (1,4) is untagged; boundary edges are infinitely sharp in Far.
    ck.equal(l.GetEdgeSharpness(l.FindEdge(1, 4)), 0.0f, "interior edge sharpness");
    ck.equal(l.GetVertexSharpness(0), 4.0f, "corner sharpness of vertex 0");

    OsdShape bad;
    ck.check(!parse_osd_shape("v 0 0\n", &bad, &err) && err.find("line 1") != std::string::npos,
             "a short v line is rejected with its line number");
    ck.check(!parse_osd_shape("v 0 0 0\nf 1 x 2\n", &bad, &err) && err.find("line 2") != std::string::npos,
             "a bad face index is rejected with its line number");
    ck.check(!parse_osd_shape("t crease 2/1/0 0\n", &bad, &err), "a short tag is rejected");

    OsdShape untagged;
    ck.check(parse_osd_shape("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &untagged, &err), "triangle");
    ck.equal(int(untagged.options.GetVtxBoundaryInterpolation()),
             int(Options::VTX_BOUNDARY_EDGE_AND_CORNER), "untagged boundary = edge and corner");
    ck.check(!untagged.boundary_tagged, "untagged boundary is reported as untagged");
}

int boundary_edges_in_notes(const std::string &notes) {
    static const std::regex open_re("open \\(([0-9]+) boundary edges\\)");
    std::smatch m;
    if (std::regex_search(notes, m, open_re)) {
        return std::stoi(m[1]);
    }
    return 0;
}

void check_shape(Checker &ck, const std::string &path, const IndexRow &row) {
    OsdShape s;
    std::string err;
    if (!ck.check(read_osd_shape(path, &s, &err), "read: " + err)) {
        return;
    }
    ck.equal(s.num_vertices(), row.verts, "vertex count vs INDEX.tsv");
    ck.equal(s.num_faces(), row.faces, "face count vs INDEX.tsv");
    bool quads = std::all_of(s.face_sizes.begin(), s.face_sizes.end(), [](int n) { return n == 4; });
    ck.equal(quads, row.all_quads, "all quads vs INDEX.tsv");
    ck.equal(!s.crease_sharpness.empty(), row.has_creases, "has creases vs INDEX.tsv");
    ck.equal(!s.corner_sharpness.empty(), row.has_corners, "has corners vs INDEX.tsv");
    std::string tagged = "untagged";
    if (s.boundary_tagged) {
        switch (s.options.GetVtxBoundaryInterpolation()) {
        case Options::VTX_BOUNDARY_NONE: tagged = "none"; break;
        case Options::VTX_BOUNDARY_EDGE_ONLY: tagged = "edge"; break;
        case Options::VTX_BOUNDARY_EDGE_AND_CORNER: tagged = "edgeandcorner"; break;
        }
    }
    ck.equal(tagged, row.boundary, "boundary tag vs INDEX.tsv");

    auto refiner = build_refiner(s);
    if (!ck.check(refiner != nullptr, "Far accepts the shape")) {
        return;
    }
    const auto &l = refiner->GetLevel(0);
    ck.equal(l.GetNumVertices(), row.verts, "Far vertex count");
    ck.equal(l.GetNumFaces(), row.faces, "Far face count");
    // INDEX.tsv counts vertex pairs with one face; Far makes an edge instance of its own for a
    // degenerate pair (v,v) and for a pair that a face uses twice, so sum faces per pair.
    std::map<std::pair<int, int>, int> faces_per_pair;
    int degenerate = 0;
    for (int e = 0; e < l.GetNumEdges(); ++e) {
        auto ev = l.GetEdgeVertices(e);
        if (ev[0] == ev[1]) {
            ++degenerate;
            continue;
        }
        faces_per_pair[std::minmax(ev[0], ev[1])] += l.GetEdgeFaces(e).size();
    }
    int boundary = 0;
    for (const auto &kv : faces_per_pair) {
        boundary += kv.second == 1;
    }
    ck.equal(boundary, boundary_edges_in_notes(row.notes), "boundary vertex pairs vs INDEX.tsv notes");
    ck.equal(degenerate > 0, row.notes.find("repeated vertices") != std::string::npos,
             "degenerate edges exactly in shapes noted with repeated face vertices");
}

}  // namespace

int main() {
    Checker ck("osd_shape_reader");
    check_reader_on_inline_text(ck);

    std::string dir = osd_shapes_dir();
    if (dir.empty()) {
        ck.note("OpenSubdiv shapes folder NOT FOUND at '" + osd_shapes_dir_searched() +
                "' (set PROFSUBD_OSD_SHAPES); only the inline reader checks ran");
        return ck.finish();
    }
    std::map<std::string, IndexRow> index = read_index(dir + "/INDEX.tsv");
    std::vector<std::string> files = list_obj_files(dir);
    ck.set_context(dir);
    ck.equal(files.size(), kExpectedShapeCount, "number of shapes in the folder");
    ck.equal(index.size(), files.size(), "INDEX.tsv rows");
    for (const std::string &path : files) {
        ck.set_context(shape_name(path));
        auto it = index.find(shape_name(path));
        if (ck.check(it != index.end(), "shape listed in INDEX.tsv")) {
            check_shape(ck, path, it->second);
        }
    }
    ck.note("checked " + std::to_string(files.size()) + " shapes from " + dir);
    return ck.finish();
}
