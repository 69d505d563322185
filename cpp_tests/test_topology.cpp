// profsubd's level-0 topology, read through the C API, against OpenSubdiv's
// Far::TopologyRefiner built by the harness's own reader from the same file, and against
// OpenMesh for the manifold meshes: every shape of OpenSubdiv's regression folder, plus
// meshes built here through profsubd_mesh_new (so a clone without the shapes still tests).
#include "capi_mesh.h"
#include "osd_shape.h"
#include "test_support.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <opensubdiv/far/topologyLevel.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

using namespace profsubd_test;
using OpenSubdiv::Sdc::Options;
using Level = OpenSubdiv::Far::TopologyLevel;

namespace {

constexpr float kInfinitelySharp = 10.0f;  // Sdc::Crease::SHARPNESS_INFINITE

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <class A, class B>
bool same_values(const std::vector<A> &a, const std::vector<B> &b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (size_t i = 0; i < a.size(); ++i) {
        if (!same_bits(static_cast<A>(b[i]), a[i])) {
            return false;
        }
    }
    return true;
}

template <class A, class B>
bool same_ints(const std::vector<A> &a, const std::vector<B> &b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](A x, B y) {
               return static_cast<long long>(x) == static_cast<long long>(y);
           });
}

// The mesh data the C API returns is exactly the data of the file / descriptor.
void compare_arrays(Checker &ck, const OsdShape &s, const CapiMesh &c) {
    ck.check(same_values(s.positions, c.positions), "positions bit-identical to the file's decimals");
    ck.check(same_ints(s.face_sizes, c.face_sizes), "face sizes");
    ck.check(same_ints(s.face_indices, c.face_indices), "face indices");
    ck.check(same_ints(s.crease_vertices, c.crease_vertices), "crease vertex pairs, in order");
    ck.check(same_values(s.crease_sharpness, c.crease_sharpness), "crease sharpness, in order");
    ck.check(same_ints(s.corner_vertices, c.corner_vertices), "corner vertices, in order");
    ck.check(same_values(s.corner_sharpness, c.corner_sharpness), "corner sharpness, in order");
    ck.check(same_ints(s.holes, c.holes), "hole faces");
}

// Level-0 topology and sharpness: profsubd's answers against Far's.
void compare_with_far(Checker &ck, const OsdShape &s, const CapiMesh &c) {
    auto refiner = build_refiner(s);
    if (!ck.check(refiner != nullptr, "Far accepts the mesh")) {
        return;
    }
    const Level &l = refiner->GetLevel(0);
    ck.equal(c.num_vertices, size_t(l.GetNumVertices()), "vertex count vs Far");
    ck.equal(c.num_faces, size_t(l.GetNumFaces()), "face count vs Far");
    if (!ck.equal(c.num_edges, size_t(l.GetNumEdges()), "edge count vs Far")) {
        return;
    }
    ck.equal(c.report.num_vertices, c.num_vertices, "report vertex count");
    ck.equal(c.report.num_edges, c.num_edges, "report edge count");
    ck.equal(c.report.num_faces, c.num_faces, "report face count");

    // Edge instances are Far's; the report counts vertex pairs (a pair a face uses twice and
    // a degenerate pair (v,v) are an edge per use in Far, one pair in the report).
    int edge_mismatch = -1;
    std::map<std::pair<int, int>, size_t> uses_of_pair;
    for (int e = 0; e < l.GetNumEdges(); ++e) {
        auto ev = l.GetEdgeVertices(e);
        if (edge_mismatch < 0 && (c.edges[2 * e] != uint32_t(ev[0]) || c.edges[2 * e + 1] != uint32_t(ev[1]))) {
            edge_mismatch = e;
        }
        uses_of_pair[std::minmax(ev[0], ev[1])] += l.GetEdgeFaces(e).size();
    }
    if (edge_mismatch >= 0) {
        auto ev = l.GetEdgeVertices(edge_mismatch);
        ck.check(false, "edge " + std::to_string(edge_mismatch) + " is (" +
                            std::to_string(c.edges[2 * edge_mismatch]) + "," +
                            std::to_string(c.edges[2 * edge_mismatch + 1]) + "), Far has (" +
                            std::to_string(ev[0]) + "," + std::to_string(ev[1]) + ")");
    } else {
        ck.check(true, "edge vertices in Far's edge order");
    }
    size_t boundary_pairs = 0, non_manifold_pairs = 0;
    for (const auto &kv : uses_of_pair) {
        boundary_pairs += kv.second == 1;
        non_manifold_pairs += kv.second > 2;
    }
    ck.equal(c.report.num_boundary_edges, boundary_pairs, "boundary edges (vertex pairs with one face) vs Far");
    ck.equal(c.report.num_non_manifold_edges, non_manifold_pairs, "non-manifold edges (pairs with > 2 faces) vs Far");

    int valence_mismatch = -1, non_manifold_vertices = 0, isolated = 0;
    for (int v = 0; v < l.GetNumVertices(); ++v) {
        if (valence_mismatch < 0 && c.valences[v] != uint32_t(l.GetVertexEdges(v).size())) {
            valence_mismatch = v;
        }
        non_manifold_vertices += l.IsVertexNonManifold(v);
        isolated += l.GetVertexFaces(v).size() == 0;
    }
    if (valence_mismatch >= 0) {
        ck.check(false, "valence of vertex " + std::to_string(valence_mismatch) + " is " +
                            std::to_string(c.valences[valence_mismatch]) + ", Far has " +
                            std::to_string(l.GetVertexEdges(valence_mismatch).size()));
    } else {
        ck.check(true, "valence of every vertex");
    }
    ck.equal(c.report.num_non_manifold_vertices, size_t(non_manifold_vertices), "non-manifold vertices vs Far");
    ck.equal(c.report.num_isolated_vertices, size_t(isolated), "isolated vertices vs Far");
    size_t repeating = 0;
    for (int f = 0; f < l.GetNumFaces(); ++f) {
        auto fv = l.GetFaceVertices(f);
        std::vector<int> sorted(fv.begin(), fv.end());
        std::sort(sorted.begin(), sorted.end());
        repeating += std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    }
    ck.equal(c.report.num_faces_with_repeated_vertices, repeating, "faces repeating a vertex vs Far");
    ck.equal(c.report.euler_characteristic,
             int64_t(l.GetNumVertices()) - l.GetNumEdges() + l.GetNumFaces(), "Euler characteristic V-E+F");

    // Sharpness Far derives from profsubd's creases, corners and edges: the last tag on a
    // component wins; Far makes boundary and non-manifold edges infinitely sharp, and with
    // edge-and-corner boundaries every vertex with one face and two edges.
    std::map<std::pair<uint32_t, uint32_t>, float> crease_of_pair;
    for (size_t i = 0; i < c.crease_sharpness.size(); ++i) {
        crease_of_pair[std::minmax(c.crease_vertices[2 * i], c.crease_vertices[2 * i + 1])] = c.crease_sharpness[i];
    }
    int sharp_mismatch = -1;
    float expected_sharpness = 0.0f;
    for (int e = 0; e < l.GetNumEdges() && sharp_mismatch < 0; ++e) {
        float expected = 0.0f;
        if (l.GetEdgeFaces(e).size() < 2 || l.IsEdgeNonManifold(e)) {
            expected = kInfinitelySharp;
        } else {
            auto it = crease_of_pair.find(std::minmax(c.edges[2 * e], c.edges[2 * e + 1]));
            expected = it == crease_of_pair.end() ? 0.0f : it->second;
        }
        if (!same_bits(l.GetEdgeSharpness(e), expected)) {
            sharp_mismatch = e;
            expected_sharpness = expected;
        }
    }
    if (sharp_mismatch >= 0) {
        ck.check(false, "edge " + std::to_string(sharp_mismatch) + ": profsubd's creases give sharpness " +
                            std::to_string(expected_sharpness) + ", Far has " +
                            std::to_string(l.GetEdgeSharpness(sharp_mismatch)));
    } else {
        ck.check(true, "edge sharpness from profsubd's creases and edges equals Far's");
    }

    std::vector<float> corner_of_vertex(c.num_vertices, 0.0f);
    for (size_t i = 0; i < c.corner_sharpness.size(); ++i) {
        corner_of_vertex[c.corner_vertices[i]] = c.corner_sharpness[i];
    }
    bool sharpen_corners = s.options.GetVtxBoundaryInterpolation() == Options::VTX_BOUNDARY_EDGE_AND_CORNER;
    int corner_mismatch = -1;
    for (int v = 0; v < l.GetNumVertices() && corner_mismatch < 0; ++v) {
        if (l.IsVertexNonManifold(v)) {
            continue;  // Far may sharpen these; profsubd's answer is its own (src/catmark).
        }
        bool topological_corner = l.GetVertexFaces(v).size() == 1 && l.GetVertexEdges(v).size() == 2;
        float expected = sharpen_corners && topological_corner ? kInfinitelySharp : corner_of_vertex[v];
        if (!same_bits(l.GetVertexSharpness(v), expected)) {
            corner_mismatch = v;
        }
    }
    if (corner_mismatch >= 0) {
        ck.check(false, "vertex " + std::to_string(corner_mismatch) + ": corner sharpness " +
                            std::to_string(corner_of_vertex[corner_mismatch]) + ", Far has " +
                            std::to_string(l.GetVertexSharpness(corner_mismatch)));
    } else {
        ck.check(true, "vertex sharpness from profsubd's corners equals Far's");
    }

    int holes = 0;
    for (int f = 0; f < l.GetNumFaces(); ++f) {
        holes += l.IsFaceHole(f);
    }
    std::vector<uint32_t> distinct_holes = c.holes;
    std::sort(distinct_holes.begin(), distinct_holes.end());
    distinct_holes.erase(std::unique(distinct_holes.begin(), distinct_holes.end()), distinct_holes.end());
    if (s.options.GetVtxBoundaryInterpolation() != Options::VTX_BOUNDARY_NONE) {
        ck.equal(size_t(holes), distinct_holes.size(), "hole faces vs Far");
    }
}

// A manifold mesh must be accepted by OpenMesh with the same counts and valences.
void compare_with_openmesh(Checker &ck, const CapiMesh &c) {
    using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;
    PolyMesh om;
    std::vector<PolyMesh::VertexHandle> vh;
    for (size_t v = 0; v < c.num_vertices; ++v) {
        vh.push_back(om.add_vertex(PolyMesh::Point(float(c.positions[3 * v]), float(c.positions[3 * v + 1]),
                                                   float(c.positions[3 * v + 2]))));
    }
    size_t k = 0;
    for (size_t f = 0; f < c.num_faces; ++f) {
        std::vector<PolyMesh::VertexHandle> face;
        for (uint32_t i = 0; i < c.face_sizes[f]; ++i) {
            face.push_back(vh[c.face_indices[k++]]);
        }
        if (!ck.check(om.add_face(face).is_valid(), "OpenMesh accepts face " + std::to_string(f))) {
            return;
        }
    }
    ck.equal(om.n_vertices(), c.num_vertices, "OpenMesh vertex count");
    ck.equal(om.n_faces(), c.num_faces, "OpenMesh face count");
    ck.equal(om.n_edges(), c.num_edges, "OpenMesh edge count");
    size_t boundary = 0;
    for (auto e : om.edges()) {
        boundary += om.is_boundary(e);
    }
    ck.equal(boundary, c.report.num_boundary_edges, "OpenMesh boundary edges");
    // OpenMesh only accepts consistently oriented faces, so the report must agree.
    ck.equal(c.report.is_consistently_oriented, int32_t(1), "consistently oriented (OpenMesh took every face)");
    ck.equal(c.report.num_inconsistent_edges, size_t(0), "no inconsistent edges");
    // Boundary loops: follow next_halfedge around each boundary.
    size_t loops = 0;
    std::vector<bool> seen(om.n_halfedges(), false);
    for (auto h : om.halfedges()) {
        if (!om.is_boundary(h) || seen[h.idx()]) {
            continue;
        }
        ++loops;
        for (auto g = h; !seen[g.idx()]; g = om.next_halfedge_handle(g)) {
            seen[g.idx()] = true;
        }
    }
    ck.equal(c.report.num_boundary_loops, loops, "OpenMesh boundary loops");
    // Components: faces joined through shared vertices.
    std::vector<int> component(om.n_faces(), -1);
    size_t components = 0;
    for (auto f : om.faces()) {
        if (component[f.idx()] >= 0) {
            continue;
        }
        std::vector<PolyMesh::FaceHandle> stack{f};
        component[f.idx()] = int(components);
        while (!stack.empty()) {
            auto g = stack.back();
            stack.pop_back();
            for (auto v : om.fv_range(g)) {
                for (auto n : om.vf_range(v)) {
                    if (component[n.idx()] < 0) {
                        component[n.idx()] = int(components);
                        stack.push_back(n);
                    }
                }
            }
        }
        ++components;
    }
    ck.equal(c.report.num_components, components, "OpenMesh components");
    int valence_mismatch = -1;
    for (size_t v = 0; v < c.num_vertices && valence_mismatch < 0; ++v) {
        if (om.valence(vh[v]) != c.valences[v]) {
            valence_mismatch = int(v);
        }
    }
    ck.check(valence_mismatch < 0, "OpenMesh valence of every vertex (first mismatch: vertex " +
                                       std::to_string(valence_mismatch) + ")");
}

// profsubd_mesh_write_obj must write what the harness's reader (and so OpenSubdiv's
// format) reads back to the same data, and profsubd reads back to the same mesh.
void check_write_read(Checker &ck, const profsubd_mesh *m, const CapiMesh &c, const TempDir &tmp) {
    std::string path = tmp.file("written.obj");
    profsubd_status st = profsubd_mesh_write_obj(m, path.c_str());
    if (!ck.check(st == PROFSUBD_OK, "write_obj: " + describe_status(st))) {
        return;
    }
    OsdShape back;
    std::string err;
    if (ck.check(read_osd_shape(path, &back, &err), "harness reads the written file: " + err)) {
        compare_arrays(ck, back, c);
    }
    MeshPtr again = load_obj_capi(path, &err);
    if (!ck.check(again != nullptr, "profsubd reads its own file: " + err)) {
        return;
    }
    CapiMesh c2;
    err = read_capi_mesh(again.get(), &c2);
    if (ck.check(err.empty(), "C API on the re-read mesh: " + err)) {
        ck.check(same_values(c.positions, c2.positions) && c.face_indices == c2.face_indices &&
                     c.edges == c2.edges && same_values(c.crease_sharpness, c2.crease_sharpness) &&
                     c.crease_vertices == c2.crease_vertices && c.corner_vertices == c2.corner_vertices &&
                     same_values(c.corner_sharpness, c2.corner_sharpness) && c.holes == c2.holes,
                 "write + read gives the same mesh");
    }
}

// The reader's warnings: one per ignored or adjusted line, each "file:line: ...".
void check_warnings(Checker &ck, const profsubd_mesh *m, const OsdShape &s, const std::string &path) {
    size_t n = 0;
    if (!ck.check(profsubd_mesh_num_warnings(m, &n) == PROFSUBD_OK, "num_warnings")) {
        return;
    }
    std::vector<int> lines;
    for (size_t i = 0; i < n; ++i) {
        const char *w = nullptr;
        if (!ck.check(profsubd_mesh_get_warning(m, i, &w) == PROFSUBD_OK && w != nullptr, "get_warning")) {
            return;
        }
        std::string text = w;
        std::string prefix = path + ":";
        if (!ck.check(text.compare(0, prefix.size(), prefix) == 0, "warning starts with the file: " + text)) {
            continue;
        }
        lines.push_back(std::atoi(text.c_str() + prefix.size()));
    }
    std::sort(lines.begin(), lines.end());
    std::string expected, got;
    for (int l : s.warning_lines) {
        expected += " " + std::to_string(l);
    }
    for (int l : lines) {
        got += " " + std::to_string(l);
    }
    ck.equal(got, expected, "lines of the reader's warnings (ignored tags, clamped sharpness, repeated options)");
}

void check_osd_shape(Checker &ck, const std::string &path, const TempDir &tmp) {
    OsdShape s;
    std::string err;
    if (!ck.check(read_osd_shape(path, &s, &err), "harness reader: " + err)) {
        return;
    }
    MeshPtr m = load_obj_capi(path, &err);
    if (!ck.check(m != nullptr, "profsubd_mesh_read_obj: " + err)) {
        return;
    }
    CapiMesh c;
    err = read_capi_mesh(m.get(), &c);
    if (!ck.check(err.empty(), "C API: " + err)) {
        return;
    }
    compare_arrays(ck, s, c);
    compare_with_far(ck, s, c);
    check_warnings(ck, m.get(), s, path);
    bool manifold = !is_known_non_manifold(shape_name(path));
    ck.equal(c.report.is_manifold != 0, manifold, "is_manifold vs the folder's README");
    if (manifold) {
        compare_with_openmesh(ck, c);
    }
    check_write_read(ck, m.get(), c, tmp);
}

// ---- meshes built here ----

// nx x ny quads on [0,1]^2 with a bumpy z, coordinates that need all 17 digits.
OsdShape grid(int nx, int ny) {
    OsdShape s;
    s.options = profsubd_default_options();
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            double x = double(i) / nx, y = double(j) / ny;
            s.positions.insert(s.positions.end(), {x, y, 0.1 * std::sin(3.0 * x + y)});
        }
    }
    auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            s.face_sizes.push_back(4);
            s.face_indices.insert(s.face_indices.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    for (int i = 0; i < nx; ++i) {  // a semi-sharp crease along the interior row j = 1
        s.crease_vertices.insert(s.crease_vertices.end(), {id(i, 1), id(i + 1, 1)});
        s.crease_sharpness.push_back(2.5f);
    }
    s.corner_vertices = {id(1, 1), id(0, 0)};
    s.corner_sharpness = {1.25f, 3.0f};
    s.holes = {nx * ny - 1};
    return s;
}

OsdShape cube() {
    OsdShape s;
    s.options = profsubd_default_options();
    s.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    s.face_sizes = {4, 4, 4, 4, 4, 4};
    s.face_indices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    s.crease_vertices = {4, 5, 5, 6, 6, 7, 7, 4};
    s.crease_sharpness = {10.0f, 10.0f, 2.0f, 0.5f};
    s.corner_vertices = {0};
    s.corner_sharpness = {10.0f};
    return s;
}

// Square pyramid: a quad and four triangles, closed.
OsdShape pyramid() {
    OsdShape s;
    s.options = profsubd_default_options();
    s.positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1.5};
    s.face_sizes = {4, 3, 3, 3, 3};
    s.face_indices = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    return s;
}

// Three quads on one edge (a "fin"): non-manifold, which Far and profsubd accept.
OsdShape fin() {
    OsdShape s;
    s.options = profsubd_default_options();
    s.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, -1, 0, 0, -1, 0, 1, 0, 1, 0, 0, 1};
    s.face_sizes = {4, 4, 4};
    s.face_indices = {0, 1, 2, 3, 1, 0, 5, 4, 0, 1, 6, 7};
    return s;
}

struct Expected {
    size_t vertices, edges, faces, boundary_edges;
    int64_t euler;
    bool manifold;
    std::vector<uint32_t> valences;
};

void check_generated(Checker &ck, const std::string &name, const OsdShape &s, const Expected &x,
                     const TempDir &tmp) {
    ck.set_context("generated " + name);
    std::string err;
    MeshPtr m = new_mesh_capi(s, &err);
    if (!ck.check(m != nullptr, "profsubd_mesh_new: " + err)) {
        return;
    }
    CapiMesh c;
    err = read_capi_mesh(m.get(), &c);
    if (!ck.check(err.empty(), "C API: " + err)) {
        return;
    }
    // Known answers first, then the same comparisons as for OpenSubdiv's shapes.
    ck.equal(c.num_vertices, x.vertices, "vertices");
    ck.equal(c.num_edges, x.edges, "edges");
    ck.equal(c.num_faces, x.faces, "faces");
    ck.equal(c.report.num_boundary_edges, x.boundary_edges, "boundary edges");
    ck.equal(c.report.euler_characteristic, x.euler, "Euler characteristic");
    ck.equal(c.report.is_manifold != 0, x.manifold, "is_manifold");
    ck.check(c.valences == x.valences, "valences");
    compare_arrays(ck, s, c);
    compare_with_far(ck, s, c);
    if (x.manifold) {
        compare_with_openmesh(ck, c);
    }
    check_write_read(ck, m.get(), c, tmp);
}

std::vector<uint32_t> grid_valences(int nx, int ny) {
    std::vector<uint32_t> v;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            int on_boundary = (i == 0 || i == nx) + (j == 0 || j == ny);
            v.push_back(4 - on_boundary);
        }
    }
    return v;
}

}  // namespace

int main() {
    Checker ck("topology");
    TempDir tmp;

    check_generated(ck, "grid 4x3", grid(4, 3), {20, 31, 12, 14, 1, true, grid_valences(4, 3)}, tmp);
    check_generated(ck, "grid 7x5", grid(7, 5), {48, 82, 35, 24, 1, true, grid_valences(7, 5)}, tmp);
    check_generated(ck, "cube", cube(), {8, 12, 6, 0, 2, true, std::vector<uint32_t>(8, 3)}, tmp);
    check_generated(ck, "pyramid", pyramid(), {5, 8, 5, 0, 2, true, {3, 3, 3, 3, 4}}, tmp);
    check_generated(ck, "fin", fin(), {8, 10, 3, 9, 1, false, {4, 4, 2, 2, 2, 2, 2, 2}}, tmp);

    std::string dir = osd_shapes_dir();
    if (dir.empty()) {
        ck.set_context("");
        ck.note("OpenSubdiv shapes folder NOT FOUND at '" + osd_shapes_dir_searched() +
                "' (set PROFSUBD_OSD_SHAPES): only project-generated meshes were compared");
        return ck.finish();
    }
    std::vector<std::string> files = list_obj_files(dir);
    ck.set_context(dir);
    ck.equal(files.size(), kExpectedShapeCount, "number of shapes in the folder");
    for (const std::string &path : files) {
        ck.set_context(shape_name(path));
        check_osd_shape(ck, path, tmp);
    }
    ck.set_context("");
    ck.note("compared " + std::to_string(files.size()) + " OpenSubdiv shapes from " + dir);
    return ck.finish();
}
