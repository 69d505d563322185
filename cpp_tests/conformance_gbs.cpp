// Generalized B-spline subdivision of order 4 at tension 1 (C API: profsubd_gbs_refine) against
// OpenSubdiv 3.5's Catmull-Clark refinement (Far::TopologyRefiner::RefineUniform +
// PrimvarRefinerReal<double>::Interpolate, edge-only boundaries, uniform creasing, Catmark
// triangles), levels 1-3. GBS is implemented from its own masks (midpoint insertion, tension
// smoothing, rule (A) vertex weights), not from profsubd's Catmark code, so Far is the
// independent reference.
//
// Children are matched by parent as Far orders them: both number the children of the
// vertices, then of the faces, then of the edges, in their parents' order, and each parent
// face's quads in turn, so vertex i and face f of a level are compared index by index (the
// face-vertex lists must be identical, which checks the matching itself).
//
// Meshes: every OpenSubdiv shape without tags (but `smoothtriangles catmark`) that a topology check finds manifold (triangles:
// pyramid, smoothtris0, pole*; pentagons: gregory_test8; open meshes), the three shapes whose
// only tags are infinitely sharp creases and corners, and 12 randomized meshes stripped of their
// tags (triangles and n-gons up to 8 sides, valences 2-8, boundaries). Bound: 1e-12 x the
// bounding-box diagonal. Prints the largest deviation.
#include "capi_mesh.h"
#include "far_points.h"
#include "osd_shape.h"
#include "random_mesh.h"
#include "test_support.h"

#include <profsubd.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace OpenSubdiv;
using profsubd_test::Checker;
using profsubd_test::OsdShape;

namespace {

constexpr double kTolerance = 1e-12;  // x bounding-box diagonal

// Shapes whose only tags are infinitely sharp creases or corners (manifold, no holes).
const char *const kInfinitelySharp[] = {"catmark_cube_corner4", "catmark_inf_crease0", "catmark_inf_crease1"};

Sdc::Options edge_only() {
    Sdc::Options o;
    o.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    o.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
    o.SetTriangleSubdivision(Sdc::Options::TRI_SUB_CATMARK);
    return o;
}

// No tags but `smoothtriangles catmark` (the default triangle rule).
bool untagged(const OsdShape &s) {
    return std::all_of(s.tags.begin(), s.tags.end(), [](const profsubd_test::OsdTag &t) {
        return t.name == "smoothtriangles" && t.strings.size() == 1 && t.strings[0] == "catmark";
    });
}

struct Worst {
    double rel = 0;
    std::string where;
    long compared = 0;
};

// Compares profsubd_gbs_refine(order 4, tension 1) with Far at `level`.
void compare(Checker &c, Worst &worst, const std::string &name, const OsdShape &s, int level) {
    c.set_context(name + " level " + std::to_string(level));
    std::unique_ptr<Far::TopologyRefiner> refiner = profsubd_test::build_refiner(s, edge_only());
    if (!c.check(refiner != nullptr, "Far accepts the mesh")) return;
    Far::TopologyRefiner::UniformOptions uo(level);
    uo.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uo);
    const std::vector<profsubd_test::FarPoint> all = profsubd_test::refine_points(*refiner, s.positions);
    const Far::TopologyLevel &far = refiner->GetLevel(level);
    const profsubd_test::FarPoint *pts = all.data() + all.size() - far.GetNumVertices();

    std::string err;
    profsubd_test::MeshPtr base = profsubd_test::new_mesh_capi(s, &err);
    if (!c.check(base != nullptr, "profsubd_mesh_new: " + err)) return;
    profsubd_mesh *out = nullptr;
    profsubd_status st = profsubd_gbs_refine(base.get(), 4, 1.0, static_cast<uint32_t>(level), &out);
    if (!c.check(st == PROFSUBD_OK, "profsubd_gbs_refine: " + profsubd_test::describe_status(st))) return;
    profsubd_test::MeshPtr mine(out);
    profsubd_test::CapiMesh m;
    err = profsubd_test::read_capi_mesh(mine.get(), &m);
    if (!c.check(err.empty(), "reading the refined mesh: " + err)) return;
    if (!c.equal(m.num_vertices, static_cast<size_t>(far.GetNumVertices()), "vertex count") ||
        !c.equal(m.num_faces, static_cast<size_t>(far.GetNumFaces()), "face count")) {
        return;
    }
    size_t at = 0;
    bool same = true;
    for (int f = 0; same && f < far.GetNumFaces(); ++f) {
        Far::ConstIndexArray fv = far.GetFaceVertices(f);
        same = m.face_sizes[f] == static_cast<uint32_t>(fv.size());
        for (int j = 0; same && j < fv.size(); ++j) same = m.face_indices[at + j] == static_cast<uint32_t>(fv[j]);
        if (!same) c.check(false, "face " + std::to_string(f) + " differs from Far's");
        at += fv.size();
    }
    if (same) c.check(true, "faces");
    const double diag = std::max(profsubd_test::bbox_diagonal(s.positions), 1e-300);
    double shape_worst = 0;
    for (int v = 0; v < far.GetNumVertices(); ++v) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += std::pow(pts[v].p[k] - m.positions[3 * v + k], 2);
        const double rel = std::sqrt(d2) / diag;
        shape_worst = !(rel <= shape_worst) ? rel : shape_worst;  // NaN sticks
        ++worst.compared;
        if (rel > worst.rel) {
            worst.rel = rel;
            worst.where = name + " level " + std::to_string(level) + " vertex " + std::to_string(v);
        }
    }
    std::ostringstream s2;
    s2 << "every vertex within 1e-12 x diagonal of Far's (worst " << shape_worst << ")";
    c.check(shape_worst <= kTolerance, s2.str());
}

}  // namespace

int main() {
    Checker c("conformance_gbs");
    Worst worst;
    int shapes = 0, triangles = 0, pentagons = 0;
    const std::string dir = profsubd_test::osd_shapes_dir();
    if (dir.empty()) {
        c.note("OpenSubdiv shapes not found (looked in " + profsubd_test::osd_shapes_dir_searched() +
               "): randomized meshes only");
    }
    for (const std::string &path : dir.empty() ? std::vector<std::string>{} : profsubd_test::list_obj_files(dir)) {
        const std::string name = profsubd_test::shape_name(path);
        OsdShape s;
        std::string err;
        if (!c.check(profsubd_test::read_osd_shape(path, &s, &err), "read " + path + ": " + err)) continue;
        const bool sharp = std::find(std::begin(kInfinitelySharp), std::end(kInfinitelySharp), name) !=
                           std::end(kInfinitelySharp);
        if (!(untagged(s) || sharp) || profsubd_test::is_known_non_manifold(name)) continue;
        ++shapes;
        triangles += std::count(s.face_sizes.begin(), s.face_sizes.end(), 3) > 0;
        pentagons += std::count(s.face_sizes.begin(), s.face_sizes.end(), 5) > 0;
        for (int level = 1; level <= 3; ++level) compare(c, worst, name, s, level);
    }
    if (!dir.empty()) {
        // 19 untagged manifold shapes (lefthanded among them) and the three infinitely sharp
        // ones, with triangles and pentagons among them.
        c.set_context("shape selection");
        c.equal(shapes, 22, "shapes compared");
        c.check(triangles >= 3 && pentagons >= 1, "triangle and pentagon meshes included");
    }
    for (unsigned seed = 1; seed <= 12; ++seed) {
        OsdShape s = profsubd_test::random_mesh(seed);
        s.crease_vertices.clear();
        s.crease_sharpness.clear();
        s.corner_vertices.clear();
        s.corner_sharpness.clear();
        s.holes.clear();
        for (int level = 1; level <= 3; ++level) compare(c, worst, "random mesh " + std::to_string(seed), s, level);
    }
    std::ostringstream s;
    s << worst.compared << " vertices compared on " << shapes
      << " shapes and 12 randomized meshes; largest deviation " << worst.rel << " x diagonal at " << worst.where;
    c.note(s.str());
    return c.finish();
}
