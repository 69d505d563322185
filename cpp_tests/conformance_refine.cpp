// Conformance of profsubd's uniform refinement (C API: profsubd_refine_uniform) with
// OpenSubdiv 3.5's Far (TopologyRefiner::RefineUniform + PrimvarRefinerReal<double>::Interpolate),
// index by index (both of Far's vertex orders): vertex positions within 1e-12 x the
// bounding-box diagonal, face-vertex lists identical, hole tags identical, and the
// crease/corner tags of the refined mesh equal to Far's refined sharpness. Run over every shape of the OpenSubdiv shapes folder under each
// boundary rule and crease method, and over randomized meshes (valences 2-8, darts,
// semi-sharp and fractional sharpness on edges and vertices, boundaries, holes,
// triangles with both triangle rules), levels 1-3.
//
// Second reference: OpenMesh's Catmull-Clark subdivider, for crease-free closed manifold
// meshes (levels 1-2): the children of the base vertices by index, all vertices as point sets.
//
// Prints the largest deviation found, relative to the diagonal.
#include "capi_mesh.h"
#include "far_points.h"
#include "osd_shape.h"
#include "test_support.h"

#include <opensubdiv/far/topologyRefiner.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include <profsubd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <array>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace OpenSubdiv;
using profsubd_test::Checker;
using profsubd_test::OsdShape;

namespace {

constexpr double kTolerance = 1e-12;  // x bounding-box diagonal

std::string point(const double *p) {
    char b[128];
    std::snprintf(b, sizeof b, "(%.17g %.17g %.17g)", p[0], p[1], p[2]);
    return b;
}

const char *boundary_name(Sdc::Options::VtxBoundaryInterpolation b) {
    switch (b) {
        case Sdc::Options::VTX_BOUNDARY_NONE: return "none";
        case Sdc::Options::VTX_BOUNDARY_EDGE_ONLY: return "edge-only";
        default: return "edge-and-corner";
    }
}

// The largest relative deviation seen, and where.
struct Stats {
    double max_rel = 0.0;
    std::string where;
    long compared = 0;
    int cases = 0;
    void add(double rel, const std::string &what) {
        ++compared;
        if (rel > max_rel) {
            max_rel = rel;
            where = what;
        }
    }
};

// profsubd through the C API, every option explicit.
profsubd_test::MeshPtr refine_profsubd(Checker &c, const OsdShape &s, const Sdc::Options &o,
                                       uint32_t level, bool faces_first = false) {
    std::string err;
    profsubd_test::MeshPtr base = profsubd_test::new_mesh_capi(s, &err);
    if (!c.check(base != nullptr, "profsubd_mesh_new: " + err)) return {};
    profsubd_test::OptionsPtr opts = profsubd_test::capi_options(o);
    if (!c.check(opts != nullptr, std::string("options: ") + profsubd_last_error_message())) return {};
    if (faces_first) profsubd_options_set_vertex_order(opts.get(), PROFSUBD_ORDER_FACES_FIRST);
    profsubd_mesh *out = nullptr;
    profsubd_status st = profsubd_refine_uniform(base.get(), opts.get(), level, &out);
    if (!c.check(st == PROFSUBD_OK,
                 "profsubd_refine_uniform: " + profsubd_test::describe_status(st))) {
        return {};
    }
    return profsubd_test::MeshPtr(out);
}

// Compares profsubd's level-`level` refinement of `s` with Far's; returns false on failure.
bool compare_with_far(Checker &c, Stats &stats, const std::string &name, const OsdShape &s,
                      const Sdc::Options &o, int level, bool faces_first = false) {
    std::ostringstream ctx;
    ctx << name << " boundary=" << boundary_name(o.GetVtxBoundaryInterpolation())
        << " crease=" << (o.GetCreasingMethod() == Sdc::Options::CREASE_CHAIKIN ? "chaikin" : "uniform")
        << " triangles=" << (o.GetTriangleSubdivision() == Sdc::Options::TRI_SUB_SMOOTH ? "smooth" : "catmark")
        << " level=" << level << (faces_first ? " faces-first" : "");
    c.set_context(ctx.str());
    ++stats.cases;

    auto refiner = profsubd_test::build_refiner(s, o);
    if (!c.check(refiner != nullptr, "Far rejected the mesh")) return false;
    Far::TopologyRefiner::UniformOptions uo(level);
    uo.fullTopologyInLastLevel = true;
    uo.orderVerticesFromFacesFirst = faces_first;
    refiner->RefineUniform(uo);
    const std::vector<profsubd_test::FarPoint> buf = profsubd_test::refine_points(*refiner, s.positions);
    const Far::TopologyLevel &far = refiner->GetLevel(level);
    const profsubd_test::FarPoint *src = buf.data() + buf.size() - far.GetNumVertices();  // the last level

    profsubd_test::MeshPtr mine = refine_profsubd(c, s, o, static_cast<uint32_t>(level), faces_first);
    if (!mine) return false;
    profsubd_test::CapiMesh m;
    std::string err = profsubd_test::read_capi_mesh(mine.get(), &m);
    if (!c.check(err.empty(), "reading the refined mesh: " + err)) return false;

    bool ok = c.equal(m.num_vertices, static_cast<size_t>(far.GetNumVertices()), "vertex count");
    ok &= c.equal(m.num_faces, static_cast<size_t>(far.GetNumFaces()), "face count");
    if (!ok) return false;

    // Faces, index by index.
    size_t at = 0;
    for (int f = 0; f < far.GetNumFaces(); ++f) {
        Far::ConstIndexArray fv = far.GetFaceVertices(f);
        bool same = m.face_sizes[f] == static_cast<uint32_t>(fv.size());
        for (int j = 0; same && j < fv.size(); ++j) {
            same = m.face_indices[at + j] == static_cast<uint32_t>(fv[j]);
        }
        if (!same) {
            std::ostringstream w;
            w << "face " << f << ": profsubd";
            for (uint32_t j = 0; j < m.face_sizes[f]; ++j) w << ' ' << m.face_indices[at + j];
            w << ", Far";
            for (int j = 0; j < fv.size(); ++j) w << ' ' << fv[j];
            c.check(false, w.str());
            return false;
        }
        at += m.face_sizes[f];
    }

    // Positions, index by index.
    const double diag = std::max(profsubd_test::bbox_diagonal(s.positions), 1e-300);
    int reported = 0;
    for (int v = 0; v < far.GetNumVertices(); ++v) {
        double d = 0;
        for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(src[v].p[k] - m.positions[3 * v + k]));
        double rel = d / diag;
        stats.add(rel, ctx.str() + " vertex " + std::to_string(v));
        if (rel > kTolerance) {
            ok = false;
            if (reported++ < 5) {
                std::ostringstream w;
                w << "vertex " << v << ": profsubd " << point(&m.positions[3 * v]) << ", Far "
                  << point(src[v].p) << ", deviation " << rel << " x diagonal";
                c.check(false, w.str());
            }
        }
    }
    if (reported == 0) c.check(true, "positions");

    // Holes.
    std::set<uint32_t> holes(m.holes.begin(), m.holes.end());
    int far_holes = 0;
    for (int f = 0; f < far.GetNumFaces(); ++f) {
        if (far.IsFaceHole(f)) {
            ++far_holes;
            ok &= c.check(holes.count(static_cast<uint32_t>(f)) == 1,
                          "face " + std::to_string(f) + " is a hole in Far, not in profsubd");
        }
    }
    ok &= c.equal(holes.size(), static_cast<size_t>(far_holes), "hole count");

    // Creases: every tag equals Far's refined sharpness, and every sharp edge Far does not
    // derive from topology (non-manifold; boundary, except under boundary rule "none", where
    // boundary tags decide the holes) is tagged.
    const bool boundary_none = o.GetVtxBoundaryInterpolation() == Sdc::Options::VTX_BOUNDARY_NONE;
    int far_creases = 0;
    for (int e = 0; e < far.GetNumEdges(); ++e) {
        if (far.GetEdgeSharpness(e) > 0.0f && !far.IsEdgeNonManifold(e) &&
            (far.GetEdgeFaces(e).size() == 2 || boundary_none)) {
            ++far_creases;
        }
    }
    ok &= c.equal(m.crease_sharpness.size(), static_cast<size_t>(far_creases), "crease count");
    for (size_t i = 0; i < m.crease_sharpness.size(); ++i) {
        int e = far.FindEdge(m.crease_vertices[2 * i], m.crease_vertices[2 * i + 1]);
        if (!c.check(e >= 0, "crease " + std::to_string(i) + " is not an edge in Far")) {
            ok = false;
            continue;
        }
        ok &= c.equal(m.crease_sharpness[i], far.GetEdgeSharpness(e),
                      "sharpness of crease " + std::to_string(i));
    }
    // Corners: every tag equals Far's; every other sharp vertex is one Far sharpens itself.
    std::map<uint32_t, float> corners;
    for (size_t i = 0; i < m.corner_sharpness.size(); ++i) {
        corners[m.corner_vertices[i]] = m.corner_sharpness[i];
    }
    for (int v = 0; v < far.GetNumVertices(); ++v) {
        float fs = far.GetVertexSharpness(v);
        auto it = corners.find(static_cast<uint32_t>(v));
        if (it != corners.end()) {
            ok &= c.equal(it->second, fs, "sharpness of corner vertex " + std::to_string(v));
        } else if (fs > 0.0f) {
            bool derived =
                far.IsVertexNonManifold(v) ||
                (far.GetVertexFaces(v).size() == 1 && far.GetVertexEdges(v).size() == 2 &&
                 o.GetVtxBoundaryInterpolation() == Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
            ok &= c.check(derived, "vertex " + std::to_string(v) + " has sharpness " +
                                       std::to_string(fs) + " in Far but no corner tag");
        }
    }
    return ok;
}

// ---------------------------------------------------------------------------------------
// Randomized meshes.

using Faces = std::vector<std::vector<int>>;

int count_valence(const Faces &faces, int v) {
    std::set<std::pair<int, int>> edges;
    for (const auto &f : faces) {
        for (size_t i = 0; i < f.size(); ++i) {
            int a = f[i], b = f[(i + 1) % f.size()];
            if (a == v || b == v) edges.insert({std::min(a, b), std::max(a, b)});
        }
    }
    return static_cast<int>(edges.size());
}

// Removes the edge between two faces, merging them (lowers both end valences by one).
bool merge_random_edge(Faces &faces, std::mt19937 &rng) {
    std::uniform_int_distribution<size_t> pick(0, faces.size() - 1);
    const size_t fi = pick(rng);
    const auto &f = faces[fi];
    const size_t i = std::uniform_int_distribution<size_t>(0, f.size() - 1)(rng);
    const int a = f[i], b = f[(i + 1) % f.size()];
    for (size_t gi = 0; gi < faces.size(); ++gi) {
        if (gi == fi) continue;
        const auto &g = faces[gi];
        for (size_t j = 0; j < g.size(); ++j) {
            if (g[j] != b || g[(j + 1) % g.size()] != a) continue;
            // Only faces sharing just this edge, ends keeping valence >= 2, merged size <= 8.
            int common = 0;
            for (int x : f) common += static_cast<int>(std::count(g.begin(), g.end(), x));
            if (common != 2 || f.size() + g.size() - 2 > 8) return false;
            if (count_valence(faces, a) < 3 || count_valence(faces, b) < 3) return false;
            std::vector<int> merged;
            for (size_t k = 0; k < f.size(); ++k) merged.push_back(f[(i + 1 + k) % f.size()]);
            for (size_t k = 2; k < g.size(); ++k) merged.push_back(g[(j + k) % g.size()]);
            faces[fi] = merged;
            faces.erase(faces.begin() + static_cast<long>(gi));
            return true;
        }
    }
    return false;
}

// Splits a face into a fan of triangles around a new vertex (valence = face size).
void poke_random_face(Faces &faces, std::vector<double> &pos, std::mt19937 &rng) {
    const size_t fi = std::uniform_int_distribution<size_t>(0, faces.size() - 1)(rng);
    const std::vector<int> f = faces[fi];
    const int c = static_cast<int>(pos.size() / 3);
    double p[3] = {0, 0, 0};
    for (int v : f) {
        for (int k = 0; k < 3; ++k) p[k] += pos[3 * v + k] / f.size();
    }
    std::uniform_real_distribution<double> noise(-0.05, 0.05);
    for (int k = 0; k < 3; ++k) pos.push_back(p[k] + noise(rng));
    faces.erase(faces.begin() + static_cast<long>(fi));
    for (size_t i = 0; i < f.size(); ++i) faces.push_back({c, f[i], f[(i + 1) % f.size()]});
}

// A random mesh: a grid (open) or a torus (closed), edges merged away and faces poked,
// boundaries cut, random sharpness and holes.
OsdShape random_mesh(std::mt19937 &rng, bool closed, bool features) {
    std::uniform_int_distribution<int> dim(3, 6);
    const int nu = dim(rng), nv = dim(rng);
    std::uniform_real_distribution<double> noise(-0.1, 0.1);
    std::vector<double> pos;
    Faces faces;
    const int cols = closed ? nu : nu + 1, rows = closed ? nv : nv + 1;
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            if (closed) {
                double u = 2 * M_PI * i / nu, w = 2 * M_PI * j / nv;
                pos.push_back((2 + std::cos(w)) * std::cos(u) + noise(rng));
                pos.push_back((2 + std::cos(w)) * std::sin(u) + noise(rng));
                pos.push_back(std::sin(w) + noise(rng));
            } else {
                pos.push_back(i + noise(rng));
                pos.push_back(j + noise(rng));
                pos.push_back(noise(rng) * 3);
            }
        }
    }
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            int a = j * cols + i, b = j * cols + (i + 1) % cols;
            int c = ((j + 1) % rows) * cols + (i + 1) % cols, d = ((j + 1) % rows) * cols + i;
            faces.push_back({a, b, c, d});
        }
    }
    const int merges = std::uniform_int_distribution<int>(0, nu * nv / 3)(rng);
    for (int k = 0; k < merges; ++k) merge_random_edge(faces, rng);
    const int pokes = std::uniform_int_distribution<int>(0, 3)(rng);
    for (int k = 0; k < pokes; ++k) poke_random_face(faces, pos, rng);
    if (!closed && faces.size() > 6 && std::bernoulli_distribution(0.5)(rng)) {
        // Cut a face out of the interior: an inner boundary.
        faces.erase(faces.begin() + std::uniform_int_distribution<long>(0, faces.size() - 1)(rng));
    }

    OsdShape s;
    s.positions = pos;
    for (const auto &f : faces) {
        s.face_sizes.push_back(static_cast<int>(f.size()));
        s.face_indices.insert(s.face_indices.end(), f.begin(), f.end());
    }
    if (features) {
        std::set<std::pair<int, int>> edges;
        for (const auto &f : faces) {
            for (size_t i = 0; i < f.size(); ++i) {
                int a = f[i], b = f[(i + 1) % f.size()];
                edges.insert({std::min(a, b), std::max(a, b)});
            }
        }
        std::uniform_real_distribution<float> sharp(0.0f, 3.5f);
        std::uniform_int_distribution<int> kind(0, 9);
        for (const auto &e : edges) {
            int k = kind(rng);
            float value = k == 0 ? 10.0f : k == 1 ? sharp(rng) : k == 2 ? 0.5f * (1 + kind(rng) % 4) : 0.0f;
            if (value > 0.0f) {
                s.crease_vertices.push_back(e.first);
                s.crease_vertices.push_back(e.second);
                s.crease_sharpness.push_back(value);
            }
        }
        const int nverts = s.num_vertices();
        for (int v = 0; v < nverts; ++v) {
            int k = kind(rng);
            if (k == 0) {
                s.corner_vertices.push_back(v);
                s.corner_sharpness.push_back(kind(rng) < 3 ? 10.0f : sharp(rng));
            }
        }
        for (int f = 0; f < s.num_faces(); ++f) {
            if (kind(rng) == 0) s.holes.push_back(f);
        }
    }
    return s;
}

// ---------------------------------------------------------------------------------------
// OpenMesh as a second reference.

struct OmTraits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
    typedef OpenMesh::Vec3d Normal;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<OmTraits>;

// Closed, manifold, no sharpness, no holes, Catmark triangles: OpenMesh's subdivider applies.
bool openmesh_applies(const OsdShape &s, const Sdc::Options &o) {
    if (!s.crease_sharpness.empty() || !s.corner_sharpness.empty() || !s.holes.empty()) return false;
    if (o.GetTriangleSubdivision() == Sdc::Options::TRI_SUB_SMOOTH) return false;
    auto r = profsubd_test::build_refiner(s, o);
    if (!r) return false;
    const Far::TopologyLevel &l = r->GetLevel(0);
    for (int e = 0; e < l.GetNumEdges(); ++e) {
        if (l.GetEdgeFaces(e).size() != 2 || l.IsEdgeNonManifold(e)) return false;
    }
    for (int v = 0; v < l.GetNumVertices(); ++v) {
        if (l.IsVertexNonManifold(v) || l.GetVertexFaces(v).size() == 0) return false;
    }
    return true;
}

void compare_with_openmesh(Checker &c, Stats &stats, const std::string &name, const OsdShape &s,
                           const Sdc::Options &o, int level) {
    c.set_context(name + " OpenMesh level=" + std::to_string(level));
    OmMesh om;
    std::vector<OmMesh::VertexHandle> vh;
    for (int v = 0; v < s.num_vertices(); ++v) {
        vh.push_back(om.add_vertex(OmMesh::Point(s.positions[3 * v], s.positions[3 * v + 1],
                                                 s.positions[3 * v + 2])));
    }
    size_t at = 0;
    for (int f = 0; f < s.num_faces(); ++f) {
        std::vector<OmMesh::VertexHandle> fv;
        for (int j = 0; j < s.face_sizes[f]; ++j) fv.push_back(vh[s.face_indices[at + j]]);
        at += s.face_sizes[f];
        if (!om.add_face(fv).is_valid()) {
            c.note(name + ": OpenMesh cannot build it; skipped");
            return;
        }
    }
    OpenMesh::Subdivider::Uniform::CatmullClarkT<OmMesh> cc;
    cc.attach(om);
    cc(static_cast<size_t>(level));
    cc.detach();

    profsubd_test::MeshPtr mine = refine_profsubd(c, s, o, static_cast<uint32_t>(level));
    if (!mine) return;
    profsubd_test::CapiMesh m;
    if (!c.check(profsubd_test::read_capi_mesh(mine.get(), &m).empty(), "read refined mesh")) return;
    if (!c.equal(m.num_vertices, static_cast<size_t>(om.n_vertices()), "vertex count")) return;
    const double diag = profsubd_test::bbox_diagonal(s.positions);

    // OpenMesh keeps the base vertices first, as Far does.
    for (int v = 0; v < s.num_vertices(); ++v) {
        const auto p = om.point(OmMesh::VertexHandle(v));
        double d = 0;
        for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(p[k] - m.positions[3 * v + k]));
        stats.add(d / diag, name + " OpenMesh level " + std::to_string(level) + " vertex " + std::to_string(v));
        if (d / diag > kTolerance) {
            double q[3] = {p[0], p[1], p[2]};
            c.check(false, "vertex " + std::to_string(v) + ": profsubd " +
                               point(&m.positions[3 * v]) + ", OpenMesh " + point(q));
        }
    }
    // All vertices as point sets: each profsubd vertex has an OpenMesh vertex within tolerance.
    std::vector<std::array<double, 3>> theirs;
    for (auto v : om.vertices()) {
        const auto p = om.point(v);
        theirs.push_back({p[0], p[1], p[2]});
    }
    std::sort(theirs.begin(), theirs.end());
    const double tol = kTolerance * diag;
    int missing = 0;
    double worst = 0;
    for (size_t v = 0; v < m.num_vertices; ++v) {
        const double *p = &m.positions[3 * v];
        auto lo = std::lower_bound(theirs.begin(), theirs.end(), std::array<double, 3>{p[0] - tol, -1e300, -1e300});
        double best = 1e300;
        for (auto it = lo; it != theirs.end() && (*it)[0] <= p[0] + tol; ++it) {
            double d = std::max({std::fabs((*it)[0] - p[0]), std::fabs((*it)[1] - p[1]), std::fabs((*it)[2] - p[2])});
            best = std::min(best, d);
        }
        if (best > tol) {
            if (missing++ < 5) c.check(false, "profsubd vertex " + std::to_string(v) + " " + point(p) + " has no OpenMesh vertex within tolerance");
        } else {
            worst = std::max(worst, best);
        }
    }
    stats.add(worst / diag, name + " OpenMesh point set level " + std::to_string(level));
    c.check(missing == 0, "point sets agree");
}

// Every boundary rule and crease method (the file's triangle rule), levels 1-3, against Far,
// and levels 1-3 with faces-first vertex order (the file's options);
// levels 1-2 against OpenMesh where it applies. Returns 1 if OpenMesh was compared.
int compare_file(Checker &c, Stats &far_stats, Stats &om_stats, const std::string &name,
                 const OsdShape &s) {
    for (auto b : {Sdc::Options::VTX_BOUNDARY_NONE, Sdc::Options::VTX_BOUNDARY_EDGE_ONLY,
                   Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER}) {
        for (auto m : {Sdc::Options::CREASE_UNIFORM, Sdc::Options::CREASE_CHAIKIN}) {
            Sdc::Options o = s.options;
            o.SetVtxBoundaryInterpolation(b);
            o.SetCreasingMethod(m);
            for (int level = 1; level <= 3; ++level) compare_with_far(c, far_stats, name, s, o, level);
        }
    }
    // Far's other vertex order (orderVerticesFromFacesFirst), with the file's options.
    for (int level = 1; level <= 3; ++level) compare_with_far(c, far_stats, name, s, s.options, level, true);
    if (!openmesh_applies(s, s.options)) return 0;
    for (int level = 1; level <= 2; ++level) compare_with_openmesh(c, om_stats, name, s, s.options, level);
    return 1;
}

}  // namespace

int main() {
    Checker c("conformance_refine");
    Stats far_stats, om_stats;
    const Sdc::Options::VtxBoundaryInterpolation boundaries[] = {
        Sdc::Options::VTX_BOUNDARY_NONE, Sdc::Options::VTX_BOUNDARY_EDGE_ONLY,
        Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER};
    const Sdc::Options::CreasingMethod methods[] = {Sdc::Options::CREASE_UNIFORM,
                                                    Sdc::Options::CREASE_CHAIKIN};

    const std::string dir = profsubd_test::osd_shapes_dir();
    std::vector<std::string> files;
    if (dir.empty()) {
        c.note("OpenSubdiv shapes folder not found (looked in " +
               profsubd_test::osd_shapes_dir_searched() +
               "; set PROFSUBD_OSD_SHAPES): testing randomized meshes only");
    } else {
        files = profsubd_test::list_obj_files(dir);
        c.note("shapes: " + std::to_string(files.size()) + " in " + dir);
    }
    int shapes_om = 0;
    for (const std::string &path : files) {
        OsdShape s;
        std::string err;
        c.set_context(path);
        if (!c.check(profsubd_test::read_osd_shape(path, &s, &err), "read: " + err)) continue;
        shapes_om += compare_file(c, far_stats, om_stats, profsubd_test::shape_name(path), s);
    }

    // Meshes the project generates (examples/: bundled mesh, profiles, sweeps).
    const std::string source = __FILE__;
    const std::string examples = source.substr(0, source.rfind("/cpp_tests/")) + "/examples";
    int project = 0;
    for (const char *sub : {"meshes", "profiles", "sweeps"}) {
        for (const std::string &path : profsubd_test::list_obj_files(examples + "/" + sub)) {
            OsdShape s;
            std::string err;
            c.set_context(path);
            if (!c.check(profsubd_test::read_osd_shape(path, &s, &err), "read: " + err)) continue;
            ++project;
            shapes_om += compare_file(c, far_stats, om_stats, std::string(sub) + "/" + profsubd_test::shape_name(path), s);
        }
    }
    c.set_context("");
    c.note("project meshes: " + std::to_string(project) + " in " + examples);
    c.check(project > 0, "the project's example meshes were found");

    std::mt19937 rng(20260322);
    const int kRandom = 60;
    int random_om = 0;
    for (int i = 0; i < kRandom; ++i) {
        const bool closed = i % 3 == 0;
        const bool features = i % 6 != 3 && i % 6 != 4;
        OsdShape s = random_mesh(rng, closed, features);
        const std::string name = "random" + std::to_string(i) + (closed ? "-closed" : "-open") +
                                 (features ? "-sharp" : "-smooth");
        for (auto b : boundaries) {
            for (auto m : methods) {
                for (auto t : {Sdc::Options::TRI_SUB_CATMARK, Sdc::Options::TRI_SUB_SMOOTH}) {
                    Sdc::Options o;
                    o.SetVtxBoundaryInterpolation(b);
                    o.SetCreasingMethod(m);
                    o.SetTriangleSubdivision(t);
                    for (int level = 1; level <= 3; ++level) compare_with_far(c, far_stats, name, s, o, level);
                }
            }
        }
        // Far's faces-first vertex order, profsubd's default options.
        for (int level = 1; level <= 3; ++level)
            compare_with_far(c, far_stats, name, s, profsubd_test::profsubd_default_options(), level, true);
        Sdc::Options plain;
        if (openmesh_applies(s, plain)) {
            ++random_om;
            for (int level = 1; level <= 2; ++level) compare_with_openmesh(c, om_stats, name, s, plain, level);
        }
    }
    c.set_context("");
    char line[512];
    std::snprintf(line, sizeof line,
                  "Far: %d cases, %ld vertices compared, max deviation %.3g x diagonal (%s)",
                  far_stats.cases, far_stats.compared, far_stats.max_rel, far_stats.where.c_str());
    c.note(line);
    std::snprintf(line, sizeof line,
                  "OpenMesh: %d shapes + %d random meshes, max deviation %.3g x diagonal (%s)",
                  shapes_om, random_om, om_stats.max_rel, om_stats.where.c_str());
    c.note(line);
    c.check(shapes_om > 0 || files.empty(), "some shapes were compared with OpenMesh");
    c.check(random_om > 0, "some random meshes were compared with OpenMesh");
    return c.finish();
}
