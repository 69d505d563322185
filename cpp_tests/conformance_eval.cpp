// Conformance of profsubd's (face, u, v) evaluator with OpenSubdiv 3.5, through the C API.
//
// For every shape of the OpenSubdiv regression folder, under every boundary rule and crease
// method, and over 16 randomized meshes (random_mesh.h: valences 2-8, darts, semi-sharp and
// fractional sharpness, boundaries, holes; 8,000 points each, one boundary rule / crease
// method per mesh, cycling through all six):
//  - random points (face, u, v) against Bfr::Surface<double> at approximation level 10:
//    positions within 1e-12 x bounding-box diagonal, du and dv within 1e-9 relative
//    (relative to max(|Bfr derivative|, 1e-3 x diagonal): tiny derivatives are compared
//    absolutely);
//  - where Bfr is known not to be exact it is not the reference:
//    * points within 2^-9 (in the Ptex face's [0,1]^2, i.e. 2^-10 of Bfr's sub-face domain
//      for non-quads) of a corner that is not a regular vertex (extraordinary, dart, corner of
//      a non-quad's centre, semi-sharp, non-manifold...): Bfr's level-10 approximation;
//    * Chaikin creasing on a mesh with semi-sharp features: Bfr disagrees with Far's
//      refinement; Far's PatchTable (adaptive, isolation 10) + PatchMap, which is exact there
//      (conformance_deep), is the reference then, at 1e-12 x diagonal, with the same
//      near-corner exclusion;
//    * faces at a valence-2 dart are never given to Bfr (OpenSubdiv 3.5 writes out of
//      bounds there); faces with an interior valence-2 corner use an uncached factory. On
//      the randomized meshes, as in conformance_limit_vertices, faces within two face-rings
//      of an interior valence-2 vertex with sharpness nearby are never given to Bfr and
//      faces touching one are not compared with it (bfr35_faces()); all their corners get
//      the exact reference.
//    Those points are checked against the exact reference instead: the smooth limit mask at
//    the refined vertex of Far's uniform refinement (level 3) that sits at dyadic (u, v)
//    near each irregular corner, where the refined vertex is regular and unsharpened (then
//    the mask is the exact limit). Bfr's deviation at those points and at the skipped points
//    is printed as a measured figure.
//  - Far's PatchTable (adaptive, isolation 10, Gregory end caps, inf-sharp patches) and,
//    over the same patches, Osd as viewers and DCC applications use it (osd_patches.h:
//    Osd::CpuEvaluator::EvalStencils of the refined and local points into an
//    Osd::CpuVertexBuffer, Osd::CpuEvaluator::EvalPatches over an Osd::CpuPatchTable), at
//    every random point and at the dyadic reference points below. OpenSubdiv 3.5's Osd is
//    single precision, so Osd agrees with Far's PatchTable only up to float rounding (not
//    to 1e-15): positions within kOsdPosTol x M (M = max(diagonal, largest coordinate)),
//    derivatives within kOsdDerivTol x M x 2^patch depth. Where the PatchTable is exact
//    (farther than 2^-9 from irregular corners, no valence-2 dart corner; under both crease
//    methods) it is a reference like Bfr (1e-12 x diagonal, 1e-9 relative) and Osd is
//    checked against profsubd with the float tolerances. On a non-quad's sub-face the
//    PatchTable's and Osd's derivatives are twice those with respect to the sub-face's (u, v)
//    (as Bfr's in its tiled domain; central differences of the PatchTable's own positions
//    agree with profsubd's), so profsubd's are doubled there for the comparison.
//  - Under Chaikin with semi-sharp features, Bfr off the PatchTable is allowed only on the
//    faces `profsubd check` lists for its Chaikin hazard (profsubd_mesh_get_osd_hazard_faces).
//  - Darts (dart_isolation): the PatchTable at isolation 2, 4, ..., 10 against the exact limit
//    at the vertex, at 2^-(level+2) and at 2^-(level-2) from it: measured, printed.
// Every difference above tolerance fails with shape, configuration, point and both values.
//
// Points per configuration: 10^4 for the shape's own tags, 2,000 for each of the other
// boundary-rule/crease-method combinations (CI time), all shapes covered; catmark_pole360
// (a valence-360 vertex, slow to refine) under its own tags only.

#include "capi_mesh.h"
#include "far_points.h"
#include "osd_patches.h"
#include "osd_references.h"
#include "osd_shape.h"
#include "random_mesh.h"
#include "random_points.h"
#include "test_support.h"
#include "vec3.h"

#include <profsubd.h>

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/ptexIndices.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

using namespace OpenSubdiv;
using profsubd_test::Checker;
using profsubd_test::OsdShape;
using profsubd_test::V3;

namespace {

std::string str(V3 a) {
    char b[128];
    std::snprintf(b, sizeof b, "(%.17g %.17g %.17g)", a.x, a.y, a.z);
    return b;
}

using Pt = profsubd_test::FarPoint;

struct Sample {
    V3 p, du, dv;
};

// Figures accumulated over the whole run.
struct Figures {
    long bfr_points = 0, patch_points = 0, ref_points = 0, near_points = 0;
    double worst_pos_bfr = 0, worst_deriv_bfr = 0, worst_pos_patch = 0, worst_ref = 0;
    double bfr_near_dev = 0;  // max |Bfr - profsubd| / diag where Bfr is not exact
    std::string bfr_near_where;
    double bfr_ref_dev = 0;  // max |Bfr - reference| / diag at reference points
    long bfr_declined = 0, bfr_declined_ours_ok = 0;
    long bfr35_avoided = 0;  // points on faces OpenSubdiv 3.5's Bfr must not see
    double worst_pos_random = 0, worst_deriv_random = 0, worst_ref_random = 0;
    long random_bfr_points = 0, random_ref_points = 0;
    std::string patch_where;
    // Osd::CpuEvaluator::EvalPatches (single precision in 3.5) beside Far's PatchTable.
    long osd_points = 0, osd_exact_points = 0, osd_ref_points = 0, osd_chaikin_points = 0;
    double osd_far_pos = 0, osd_far_deriv = 0;   // |Osd - Far's PatchTable| at the same patch
    double osd_pos = 0, osd_deriv = 0;           // |Osd - profsubd| where the PatchTable is exact
    double patch_pos = 0, patch_deriv = 0;       // |PatchTable - profsubd| there (doubles)
    double osd_ref = 0, patch_ref = 0;           // vs exact refinement at the dyadic points
    double osd_chaikin_dev = 0;                  // |Osd - profsubd| / M, Chaikin + semi-sharp
    std::string osd_far_where, osd_where;
    // Far's PatchTable at darts vs profsubd's exact limit, per isolation level 2, 4, ..., 10:
    // at the vertex, at 2^-(level+2) from it and at 2^-(level-2) from it (along the diagonal).
    double dart_at[11] = {0}, dart_inside[11] = {0}, dart_outside[11] = {0};
    std::string dart_where[11];
    long darts = 0;
    long chaikin_bfr_off = 0, chaikin_listed_faces = 0;  // Bfr vs PatchTable under Chaikin
    double chaikin_bfr_max = 0;
    std::string chaikin_bfr_where;
    // Faces (not holes) repeating a vertex, "shape/face", and those Bfr declines (no surface).
    std::set<std::string> repeat_faces, repeat_declined;
};

double max_abs_coordinate(const std::vector<double> &xyz) {
    double m = 0;
    for (double x : xyz) m = std::max(m, std::fabs(x));
    return m;
}

// Osd's single precision: float rounding of coordinates, stencil weights and (u, v), relative
// to the largest coordinate (or the diagonal if larger); for derivatives also times the
// patch's derivative scale 2^depth.
constexpr double kOsdPosTol = 1e-4, kOsdDerivTol = 1e-4;

bool has_semi_sharp(const OsdShape &s) {
    for (float x : s.crease_sharpness) {
        if (x > 0 && x < 10) return true;
    }
    for (float x : s.corner_sharpness) {
        if (x > 0 && x < 10) return true;
    }
    return false;
}

// A vertex whose limit surface Bfr evaluates exactly in its neighbourhood: manifold, no
// vertex sharpness, quads only, and interior valence 4 with smooth edges or boundary
// valence 3 with a smooth interior edge.
std::vector<bool> regular_vertices(const Far::TopologyLevel &l) {
    std::vector<bool> out(l.GetNumVertices(), false);
    for (int v = 0; v < l.GetNumVertices(); ++v) {
        if (l.IsVertexNonManifold(v) || l.GetVertexSharpness(v) > 0) continue;
        auto faces = l.GetVertexFaces(v);
        auto edges = l.GetVertexEdges(v);
        bool quads = true;
        for (int i = 0; i < faces.size(); ++i) quads = quads && l.GetFaceVertices(faces[i]).size() == 4;
        if (!quads) continue;
        int sharp = 0, boundary = 0;
        for (int i = 0; i < edges.size(); ++i) {
            boundary += l.IsEdgeBoundary(edges[i]);
            sharp += !l.IsEdgeBoundary(edges[i]) && l.GetEdgeSharpness(edges[i]) > 0;
        }
        out[v] = sharp == 0 && ((boundary == 0 && edges.size() == 4 && faces.size() == 4) ||
                                (boundary == 2 && edges.size() == 3 && faces.size() == 2));
    }
    return out;
}

// Interior vertices with two faces: `dart` when exactly one incident edge is infinitely sharp.
void valence2(const Far::TopologyLevel &l, std::vector<bool> *interior2, std::vector<bool> *dart2) {
    interior2->assign(l.GetNumVertices(), false);
    dart2->assign(l.GetNumVertices(), false);
    for (int v = 0; v < l.GetNumVertices(); ++v) {
        auto edges = l.GetVertexEdges(v);
        if (l.IsVertexBoundary(v) || l.GetVertexFaces(v).size() != 2) continue;
        (*interior2)[v] = true;
        int inf = 0;
        for (int i = 0; i < edges.size(); ++i) inf += l.GetEdgeSharpness(edges[i]) >= 10.0f;
        (*dart2)[v] = inf == 1;
    }
}

struct Config {
    Sdc::Options::VtxBoundaryInterpolation boundary;
    Sdc::Options::CreasingMethod crease;
};

const char *name(Config c) {
    static const char *b[] = {"none", "edge-only", "edge-and-corner"};
    static const char *m[] = {"uniform", "chaikin"};
    static std::string s;
    s = std::string(b[c.boundary]) + "/" + m[c.crease];
    return s.c_str();
}

// The level-`level` descendant (Far's child order) whose corner 0 is at (i, j)/2^k of Ptex
// face `ptex` (k = level for quads, level - 1 for a non-quad's sub-face).
int descendant(const Far::TopologyLevel &base, int face, int sub, int i, int j, int level) {
    int offset = 0;
    for (int f = 0; f < face; ++f) offset += base.GetFaceVertices(f).size();
    auto quadrant = [&](int b) {
        int r = (i >> b) & 1, t = (j >> b) & 1;
        return r ? (t ? 2 : 1) : (t ? 3 : 0);
    };
    int idx = sub >= 0 ? offset + sub : offset + quadrant(level - 1);
    for (int b = level - 2; b >= 0; --b) idx = idx * 4 + quadrant(b);
    return idx;
}

// Exact limit at refined vertex w if its neighbourhood is regular and unsharpened.
bool smooth_limit(const Far::TopologyLevel &l, const std::vector<Pt> &p, int w, V3 *out) {
    auto faces = l.GetVertexFaces(w);
    auto edges = l.GetVertexEdges(w);
    if (l.IsVertexBoundary(w) || l.IsVertexNonManifold(w) || faces.size() != 4 || edges.size() != 4 ||
        l.GetVertexSharpness(w) > 0)
        return false;
    V3 sum = 16.0 * V3{p[w].p[0], p[w].p[1], p[w].p[2]};
    for (int i = 0; i < 4; ++i) {
        if (l.GetEdgeSharpness(edges[i]) > 0) return false;
        auto ev = l.GetEdgeVertices(edges[i]);
        int o = ev[0] == w ? ev[1] : ev[0];
        sum = sum + 4.0 * V3{p[o].p[0], p[o].p[1], p[o].p[2]};
        auto fv = l.GetFaceVertices(faces[i]);
        if (fv.size() != 4) return false;
        int k = fv.FindIndex(w);
        int d = fv[(k + 2) % 4];
        sum = sum + V3{p[d].p[0], p[d].p[1], p[d].p[2]};
    }
    *out = (1.0 / 36.0) * sum;
    return true;
}

// Darts (interior, one infinitely sharp edge, not an infinitely sharp vertex, more than two
// faces): Far's PatchTable (double local points) at isolation 2, 4, ..., 10 against profsubd,
// which takes the exact limit (the dart's eigenvector) at the vertex and is exact nearby.
void dart_isolation(const std::string &label, const OsdShape &shape, const Sdc::Options &opts,
                    const Far::TopologyLevel &base, profsubd_evaluator *ev, Figures &fig) {
    std::vector<int> darts;
    for (int v = 0; v < base.GetNumVertices(); ++v) {
        if (base.IsVertexBoundary(v) || base.IsVertexNonManifold(v) || base.GetVertexSharpness(v) >= 10.0f ||
            base.GetVertexFaces(v).size() <= 2)
            continue;
        int inf = 0;
        for (int e : base.GetVertexEdges(v)) inf += base.GetEdgeSharpness(e) >= 10.0f;
        if (inf == 1) darts.push_back(v);
    }
    if (darts.empty()) return;
    fig.darts += (long)darts.size();
    double diag = profsubd_test::bbox_diagonal(shape.positions);
    std::unique_ptr<Far::TopologyRefiner> plain = profsubd_test::build_refiner(shape, opts);
    Far::PtexIndices ptex(*plain);
    for (int level = 2; level <= 10; level += 2) {
        profsubd_test::PatchTableEvaluator table(shape, opts, level, true);
        for (int v : darts) {
            for (int f : base.GetVertexFaces(v)) {
                if (base.IsFaceHole(f)) continue;
                auto fv = base.GetFaceVertices(f);
                int k = fv.FindIndex(v), pf = ptex.GetFaceId(f);
                double cu = 0, cv = 0, du = 1, dv = 1;  // corner and inward direction
                if (fv.size() == 4) {
                    cu = (k == 1 || k == 2), cv = k >= 2;
                    du = cu ? -1 : 1, dv = cv ? -1 : 1;
                } else {
                    pf += k;
                }
                const double dist[3] = {0, std::ldexp(1.0, -(level + 2)), std::ldexp(1.0, -(level - 2))};
                for (int d = 0; d < 3; ++d) {
                    if (d == 2 && level == 2) continue;
                    uint32_t face = (uint32_t)pf;
                    double u = cu + du * dist[d], w = cv + dv * dist[d], p[3];
                    if (profsubd_evaluator_evaluate(ev, &face, &u, &w, 1, p, nullptr, nullptr) != PROFSUBD_OK) continue;
                    double q[3];
                    if (!table.evaluate(pf, u, w, q)) continue;
                    double e = norm(V3{q[0], q[1], q[2]} - V3{p[0], p[1], p[2]}) / diag;
                    double *slot = d == 0 ? &fig.dart_at[level] : d == 1 ? &fig.dart_inside[level] : &fig.dart_outside[level];
                    if (e > *slot) {
                        *slot = e;
                        if (d == 0) fig.dart_where[level] = label + " vertex " + std::to_string(v);
                    }
                }
            }
        }
    }
}

class ShapeRun {
public:
    ShapeRun(Checker &c, Figures &fig) : c_(c), fig_(fig) {}

    // `bfr35_rules`: also keep from Bfr the faces bfr35_faces() marks (randomized meshes),
    // checking them against the exact refinement reference at every corner instead.
    void run(const std::string &label, const OsdShape &shape, const Sdc::Options &opts, int npoints,
             unsigned seed, bool bfr35_rules = false);

private:
    Checker &c_;
    Figures &fig_;
};

void ShapeRun::run(const std::string &label, const OsdShape &shape, const Sdc::Options &opts, int npoints,
                   unsigned seed, bool bfr35_rules) {
    std::unique_ptr<Far::TopologyRefiner> refiner = profsubd_test::build_refiner(shape, opts);
    if (!c_.check(refiner != nullptr, label + ": Far rejects the mesh")) return;
    const Far::TopologyLevel &base = refiner->GetLevel(0);
    double diag = profsubd_test::bbox_diagonal(shape.positions);

    std::string err;
    profsubd_test::EvaluatorPtr ev = profsubd_test::new_evaluator_capi(shape, opts, &err);
    if (!c_.check(ev != nullptr, label + ": " + err)) return;
    profsubd_status st = PROFSUBD_OK;

    Far::PtexIndices ptex(*refiner);
    size_t nptex = 0;
    profsubd_evaluator_num_parametric_faces(ev.get(), &nptex);
    c_.equal(nptex, (size_t)ptex.GetNumFaces(), label + ": number of parametric faces");

    std::vector<bool> regular = regular_vertices(base), interior2, dart2;
    valence2(base, &interior2, &dart2);
    bool chaikin_semi = opts.GetCreasingMethod() == Sdc::Options::CREASE_CHAIKIN && has_semi_sharp(shape);
    profsubd_test::Bfr35Faces bfr35;
    if (bfr35_rules) {
        bfr35 = profsubd_test::bfr35_faces(base);
    } else {
        bfr35.avoid.assign(base.GetNumFaces(), false);
        bfr35.near_val2.assign(base.GetNumFaces(), false);
    }
    const long bfr_points_before = fig_.bfr_points, ref_points_before = fig_.ref_points;
    const double worst_pos_before = fig_.worst_pos_bfr, worst_deriv_before = fig_.worst_deriv_bfr,
                 worst_ref_before = fig_.worst_ref;
    if (bfr35_rules) fig_.worst_pos_bfr = fig_.worst_deriv_bfr = fig_.worst_ref = 0;

    // Reference evaluators.
    profsubd_test::BfrFactories bfr_factories(*refiner);
    Bfr::RefinerSurfaceFactory<> &cached = bfr_factories.cached, &uncached = bfr_factories.uncached;
    // Far's PatchTable (isolation 10, Gregory end caps, inf-sharp patches) and Osd over it.
    profsubd_test::PatchTableEvaluator patch_table(shape, opts);
    profsubd_test::OsdPatches osd(patch_table, shape.positions);
    const double mag = std::max(diag, max_abs_coordinate(shape.positions));
    // The faces `profsubd check` lists for its Chaikin hazard (profsubd_mesh_get_osd_hazard_faces).
    std::vector<bool> chaikin_faces(base.GetNumFaces(), false);
    {
        profsubd_test::MeshPtr mesh = profsubd_test::new_mesh_capi(shape, &err);
        profsubd_test::OptionsPtr o = profsubd_test::capi_options(opts);
        if (!c_.check(mesh && o, label + ": profsubd_mesh_new / options: " + err)) return;
        size_t n = 0;
        profsubd_mesh_get_osd_hazard_faces(mesh.get(), o.get(), PROFSUBD_OSD_HAZARD_CHAIKIN, nullptr, 0, &n);
        std::vector<uint32_t> list(n);
        st = profsubd_mesh_get_osd_hazard_faces(mesh.get(), o.get(), PROFSUBD_OSD_HAZARD_CHAIKIN, list.data(), n, &n);
        c_.check(st == PROFSUBD_OK, label + ": profsubd_mesh_get_osd_hazard_faces");
        for (uint32_t x : list) chaikin_faces[x] = true;
        fig_.chaikin_listed_faces += (long)n;
    }
    // Far's PatchTable as a Sample; `scale`: 2^depth of the patch, by which its derivative
    // weights multiply the points: float rounding of the points grows as much in derivatives.
    auto patch_eval = [&](int pf, double u, double v, Sample *out, double *scale = nullptr) {
        double p[3], du[3], dv[3];
        int depth = 0;
        if (!patch_table.evaluate(pf, u, v, p, du, dv, &depth)) return false;
        if (scale) *scale = std::ldexp(1.0, depth);
        *out = Sample{{p[0], p[1], p[2]}, {du[0], du[1], du[2]}, {dv[0], dv[1], dv[2]}};
        return true;
    };
    auto osd_eval = [&](int pf, double u, double v, Sample *out) {
        double p[3], du[3], dv[3];
        if (!osd.evaluate(pf, u, v, p, du, dv)) return false;
        *out = Sample{{p[0], p[1], p[2]}, {du[0], du[1], du[2]}, {dv[0], dv[1], dv[2]}};
        return true;
    };
    auto rel = [&](V3 a, V3 b) { return norm(a - b) / std::max(norm(b), 1e-3 * diag); };

    std::vector<bool> repeats(base.GetNumFaces(), false);
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        auto fv = base.GetFaceVertices(f);
        for (int a = 0; a < fv.size(); ++a)
            for (int b = a + 1; b < fv.size(); ++b) repeats[f] = repeats[f] || fv[a] == fv[b];
        if (repeats[f] && !base.IsFaceHole(f)) fig_.repeat_faces.insert(label + "/" + std::to_string(f));
    }

    // Random points, grouped by base face for the Bfr side.
    profsubd_test::FacePoints points = profsubd_test::random_face_points(npoints, (int)nptex, seed);
    std::vector<uint32_t> &faces = points.faces;
    std::vector<double> &us = points.us, &vs = points.vs;
    // A few exact corners and edges too.
    for (int i = 0; i < std::min(npoints, 40); ++i) {
        us[i] = (double)(i % 3) / 2.0;
        vs[i] = (double)((i / 3) % 3) / 2.0;
    }

    // Base face and sub-face of each Ptex face.
    std::vector<int> ptex_face(nptex), ptex_sub(nptex);
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        int n = base.GetFaceVertices(f).size();
        int first = ptex.GetFaceId(f);
        for (int k = 0; k < (n == 4 ? 1 : n); ++k) {
            ptex_face[first + k] = f;
            ptex_sub[first + k] = n == 4 ? -1 : k;
        }
    }
    auto corner_regular = [&](int pf, int corner) {
        int f = ptex_face[pf], sub = ptex_sub[pf];
        auto fv = base.GetFaceVertices(f);
        if (sub < 0) return (bool)regular[fv[corner]];
        if (corner == 0) return (bool)regular[fv[sub]];
        return corner != 2;  // edge midpoints are regular, the centre of a non-quad is not
    };
    // Faces next to a face that repeats a vertex (non-manifold inputs) are exact in profsubd
    // only outside 2^-2 of that vertex (see Evaluator::build_from_root): wider exclusion.
    std::vector<bool> degenerate_vertex(base.GetNumVertices(), false);
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        auto fv = base.GetFaceVertices(f);
        for (int a = 0; a < fv.size(); ++a)
            for (int b = a + 1; b < fv.size(); ++b)
                if (fv[a] == fv[b]) degenerate_vertex[fv[a]] = true;
    }
    for (int v = 0; v < base.GetNumVertices(); ++v)
        if (degenerate_vertex[v]) regular[v] = false;
    auto near_irregular = [&](int pf, double u, double v) {
        auto fv = base.GetFaceVertices(ptex_face[pf]);
        bool degenerate = false;
        for (int k = 0; k < fv.size(); ++k) degenerate = degenerate || degenerate_vertex[fv[k]];
        const double d = degenerate ? 0.25 : 1.0 / 512.0;
        double cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1};
        for (int k = 0; k < 4; ++k)
            if (!corner_regular(pf, k) && std::fabs(u - cu[k]) <= d && std::fabs(v - cv[k]) <= d) return true;
        return false;
    };

    // Osd beside Far's PatchTable at (pf, u, v): both always (same patches, Osd in float);
    // against profsubd (`p`, null where it has no surface) where the PatchTable is exact:
    // farther than 2^-9 from irregular corners, not at a valence-2 dart (3.5's SourcePatch
    // writes out of bounds there), under both crease methods (the PatchTable and profsubd are
    // exact under Chaikin too; its points are also counted apart).
    auto compare_osd = [&](int pf, double u, double v, const double *p, const double *du, const double *dv,
                           bool at_dart2) {
        Sample far, os;
        double scale = 1;
        bool has_far = patch_eval(pf, u, v, &far, &scale), has_osd = osd_eval(pf, u, v, &os);
        std::ostringstream where;
        where << label << " [" << name(Config{opts.GetVtxBoundaryInterpolation(), opts.GetCreasingMethod()})
              << "] face " << pf << " (u, v) = (" << u << ", " << v << ")";
        if (!c_.check(has_far == has_osd, where.str() + ": PatchMap and Osd disagree on a patch")) return;
        if (!has_far) return;
        ++fig_.osd_points;
        // Osd against `ref` (named `what`) within the float tolerances; worst figures kept.
        auto check_osd = [&](const Sample &ref, const std::string &what, double *pos, std::string *pos_where,
                             double *deriv) {
            double e = norm(os.p - ref.p) / mag;
            if (e > *pos) {
                *pos = e;
                *pos_where = where.str();
            }
            c_.check(e <= kOsdPosTol, where.str() + ": Osd " + str(os.p) + " vs " + what + " " + str(ref.p));
            double r = std::max(norm(os.du - ref.du), norm(os.dv - ref.dv)) / (scale * mag);
            *deriv = std::max(*deriv, r);
            c_.check(r <= kOsdDerivTol, where.str() + ": Osd du, dv " + str(os.du) + " " + str(os.dv) + " vs " + what +
                                             " " + str(ref.du) + " " + str(ref.dv));
        };
        check_osd(far, "Far's PatchTable", &fig_.osd_far_pos, &fig_.osd_far_where, &fig_.osd_far_deriv);
        if (!p || at_dart2 || near_irregular(pf, u, v)) return;
        // On a non-quad's sub-face Far's PatchTable (and Osd) give twice the derivative with
        // respect to the sub-face's (u, v) (checked by central differences of the PatchTable's
        // own positions), as Bfr does in its tiled domain.
        const double k = ptex_sub[pf] >= 0 ? 2.0 : 1.0;
        Sample ours{{p[0], p[1], p[2]}, k * V3{du[0], du[1], du[2]}, k * V3{dv[0], dv[1], dv[2]}};
        ++fig_.osd_exact_points;
        if (chaikin_semi) {
            ++fig_.osd_chaikin_points;
            fig_.osd_chaikin_dev = std::max(fig_.osd_chaikin_dev, norm(os.p - ours.p) / mag);
        }
        check_osd(ours, "profsubd", &fig_.osd_pos, &fig_.osd_where, &fig_.osd_deriv);
        double ef = norm(far.p - ours.p) / diag;
        fig_.patch_pos = std::max(fig_.patch_pos, ef);
        c_.check(ef <= 1e-12, where.str() + ": Far's PatchTable " + str(far.p) + " vs profsubd " + str(ours.p));
        double rf = std::max(rel(far.du, ours.du), rel(far.dv, ours.dv));
        fig_.patch_deriv = std::max(fig_.patch_deriv, rf);
        c_.check(rf <= 1e-9, where.str() + ": Far's PatchTable du, dv " + str(far.du) + " " + str(far.dv) +
                                 " vs profsubd " + str(ours.du) + " " + str(ours.dv));
    };

    std::vector<double> P(3 * npoints), DU(3 * npoints), DV(3 * npoints);
    std::vector<int> order(npoints);
    for (int i = 0; i < npoints; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return faces[a] < faces[b]; });

    Bfr::Surface<double> surface;
    std::vector<double> bfr_points;
    int current = -1;
    bool valid = false;
    for (int i : order) {
        int pf = (int)faces[i], f = ptex_face[pf], sub = ptex_sub[pf];
        auto fv = base.GetFaceVertices(f);
        bool at_dart2 = false, at_int2 = false;
        for (int k = 0; k < fv.size(); ++k) {
            at_dart2 = at_dart2 || dart2[fv[k]];
            at_int2 = at_int2 || interior2[fv[k]];
        }
        double p[3], du[3], dv[3];
        st = profsubd_evaluator_evaluate(ev.get(), &faces[i], &us[i], &vs[i], 1, p, du, dv);
        compare_osd(pf, us[i], vs[i], st == PROFSUBD_OK ? p : nullptr, du, dv, at_dart2);
        if (at_dart2 || bfr35.avoid[f]) {
            fig_.bfr35_avoided += bfr35.avoid[f];
            continue;  // never given to Bfr (OpenSubdiv 3.5 writes out of bounds)
        }
        if (f != current) {
            current = f;
            valid = (at_int2 || bfr35.near_val2[f] ? uncached : cached).InitVertexSurface(f, &surface);
            if (valid) {
                bfr_points.resize(3 * surface.GetNumPatchPoints());
                surface.PreparePatchPoints(shape.positions.data(), 3, bfr_points.data(), 3);
            }
        }
        std::ostringstream where;
        where << label << " [" << name(Config{opts.GetVtxBoundaryInterpolation(), opts.GetCreasingMethod()})
              << "] face " << pf << " (u, v) = (" << us[i] << ", " << vs[i] << ")";
        if (!valid) {
            // Holes and faces without limit surface; Bfr also declines some degenerate faces.
            fig_.bfr_declined += 1;
            fig_.bfr_declined_ours_ok += st == PROFSUBD_OK;
            if (repeats[f] && !base.IsFaceHole(f)) fig_.repeat_declined.insert(label + "/" + std::to_string(f));
            continue;
        }
        if (!c_.check(st == PROFSUBD_OK, where.str() + ": " + profsubd_test::describe_status(st))) continue;
        Sample ours{{p[0], p[1], p[2]}, {du[0], du[1], du[2]}, {dv[0], dv[1], dv[2]}};

        double uv[2] = {us[i], vs[i]}, bp[3], bu[3], bv[3];
        double scale = 1.0;
        if (sub >= 0) {
            double s[2] = {us[i], vs[i]};
            surface.GetParameterization().ConvertNormalizedSubFaceToCoord(sub, s, uv);
            scale = 0.5;  // d/d(sub-face u) = 1/2 d/d(Bfr u)
        }
        surface.Evaluate(uv, bfr_points.data(), 3, bp, bu, bv);
        Sample bfr{{bp[0], bp[1], bp[2]}, scale * V3{bu[0], bu[1], bu[2]}, scale * V3{bv[0], bv[1], bv[2]}};

        bool near = near_irregular(pf, us[i], vs[i]) || bfr35.near_val2[f];
        if (near || chaikin_semi) {
            double dev = norm(bfr.p - ours.p) / diag;
            if (dev > fig_.bfr_near_dev) {
                fig_.bfr_near_dev = dev;
                fig_.bfr_near_where = where.str();
            }
        }
        if (near) {
            ++fig_.near_points;
            continue;
        }
        if (chaikin_semi) {
            // Bfr off Far's PatchTable (exact under Chaikin) only on faces `profsubd check`
            // lists for its Chaikin hazard.
            Sample far;
            if (!c_.check(patch_eval(pf, us[i], vs[i], &far), where.str() + ": no PatchTable patch")) continue;
            if (norm(bfr.p - far.p) / diag > 1e-12) {
                ++fig_.chaikin_bfr_off;
                if (norm(bfr.p - far.p) / diag > fig_.chaikin_bfr_max) {
                    fig_.chaikin_bfr_max = norm(bfr.p - far.p) / diag;
                    fig_.chaikin_bfr_where = where.str();
                }
                c_.check(chaikin_faces[f], where.str() + ": Bfr off Far's PatchTable by " +
                                               std::to_string(norm(bfr.p - far.p) / diag) +
                                               " x diagonal on a face `profsubd check` does not list (chaikin)");
            }
            V3 tp = far.p;
            double e = norm(tp - ours.p) / diag;
            if (e > fig_.worst_pos_patch) {
                fig_.worst_pos_patch = e;
                fig_.patch_where = where.str();
            }
            ++fig_.patch_points;
            // Exact under Chaikin away from irregular corners (conformance_deep measures it
            // against the exact limit of refined vertices).
            c_.check(e <= 1e-12, where.str() + ": position " + str(ours.p) + " vs PatchTable " + str(tp));
            continue;
        }
        ++fig_.bfr_points;
        double e = norm(bfr.p - ours.p) / diag;
        fig_.worst_pos_bfr = std::max(fig_.worst_pos_bfr, e);
        c_.check(e <= 1e-12, where.str() + ": position " + str(ours.p) + " vs Bfr " + str(bfr.p));
        for (int d = 0; d < 2; ++d) {
            V3 a = d ? ours.dv : ours.du, b = d ? bfr.dv : bfr.du;
            double r = norm(a - b) / std::max(norm(b), 1e-3 * diag);
            fig_.worst_deriv_bfr = std::max(fig_.worst_deriv_bfr, r);
            c_.check(r <= 1e-9, where.str() + (d ? ": dv " : ": du ") + str(a) + " vs Bfr " + str(b));
        }
    }

    // Exact reference near irregular corners: refined vertices at dyadic points (level 3).
    const int level = 3;
    std::unique_ptr<Far::TopologyRefiner> uniform = profsubd_test::build_refiner(shape, opts);
    Far::TopologyRefiner::UniformOptions uo(level);
    uo.fullTopologyInLastLevel = true;  // vertex-face and vertex-edge relations at the last level
    uniform->RefineUniform(uo);
    std::vector<Pt> rp = profsubd_test::refine_points(*uniform, shape.positions);
    int last_offset = (int)rp.size() - uniform->GetLevel(level).GetNumVertices();
    std::vector<Pt> last(rp.begin() + last_offset, rp.end());
    const Far::TopologyLevel &fine = uniform->GetLevel(level);
    for (int pf = 0; pf < (int)nptex; ++pf) {
        int f = ptex_face[pf], sub = ptex_sub[pf];
        int n = 1 << (level - (sub >= 0));
        for (int k = 0; k < 4; ++k) {
            // Near irregular corners always; everywhere when Chaikin creasing has semi-sharp
            // features to act on (there OpenSubdiv's Bfr is not a reference).
            if (corner_regular(pf, k) && !chaikin_semi && !bfr35.avoid[f] && !bfr35.near_val2[f]) continue;
            int ci = (k == 1 || k == 2) ? n : 0, cj = k >= 2 ? n : 0;
            for (int a = 1; a <= 2; ++a)
                for (int b = 1; b <= 2; ++b) {
                    int i = ci ? ci - a : a, j = cj ? cj - b : b;
                    if (i <= 0 || j <= 0 || i >= n || j >= n) continue;
                    if (near_irregular(pf, (double)i / n, (double)j / n) &&
                        std::fabs((double)i / n - (k == 1 || k == 2)) + std::fabs((double)j / n - (k >= 2)) < 0.5 &&
                        degenerate_vertex[base.GetFaceVertices(f)[sub >= 0 ? sub : k]])
                        continue;  // next to a repeated vertex: see near_irregular
                    int w = fine.GetFaceVertices(descendant(base, f, sub, i, j, level))[0];
                    V3 want;
                    if (!smooth_limit(fine, last, w, &want)) continue;
                    uint32_t face = (uint32_t)pf;
                    double u = (double)i / n, v = (double)j / n, p[3];
                    st = profsubd_evaluator_evaluate(ev.get(), &face, &u, &v, 1, p, nullptr, nullptr);
                    if (st != PROFSUBD_OK) continue;  // no limit surface there
                    V3 got{p[0], p[1], p[2]};
                    double e = norm(got - want) / diag;
                    fig_.worst_ref = std::max(fig_.worst_ref, e);
                    ++fig_.ref_points;
                    std::ostringstream where;
                    where << label << " face " << pf << " (" << u << ", " << v << ")";
                    c_.check(e <= 1e-12, where.str() + ": " + str(got) + " vs refinement " + str(want));
                    bool skip_bfr = false, int2 = false;
                    for (int q = 0; q < base.GetFaceVertices(f).size(); ++q) {
                        skip_bfr = skip_bfr || dart2[base.GetFaceVertices(f)[q]];
                        int2 = int2 || interior2[base.GetFaceVertices(f)[q]];
                    }
                    Sample far, os;
                    if (!skip_bfr && patch_eval(pf, u, v, &far) && osd_eval(pf, u, v, &os)) {
                        // Farther than 2^-3 from the corner: the PatchTable is exact there.
                        ++fig_.osd_ref_points;
                        double ef = norm(far.p - want) / diag, eo = norm(os.p - want) / mag;
                        fig_.patch_ref = std::max(fig_.patch_ref, ef);
                        fig_.osd_ref = std::max(fig_.osd_ref, eo);
                        c_.check(ef <= 1e-12, where.str() + ": Far's PatchTable " + str(far.p) + " vs refinement " +
                                                  str(want));
                        c_.check(eo <= kOsdPosTol, where.str() + ": Osd " + str(os.p) + " vs refinement " + str(want));
                    }
                    if (skip_bfr || bfr35.avoid[f]) continue;
                    bool ok = (int2 || bfr35.near_val2[f] ? uncached : cached).InitVertexSurface(f, &surface);
                    if (!ok) continue;
                    bfr_points.resize(3 * surface.GetNumPatchPoints());
                    surface.PreparePatchPoints(shape.positions.data(), 3, bfr_points.data(), 3);
                    double uv[2] = {u, v}, bp[3];
                    if (sub >= 0) {
                        double s[2] = {u, v};
                        surface.GetParameterization().ConvertNormalizedSubFaceToCoord(sub, s, uv);
                    }
                    surface.Evaluate(uv, bfr_points.data(), 3, bp);
                    fig_.bfr_ref_dev = std::max(fig_.bfr_ref_dev, norm(V3{bp[0], bp[1], bp[2]} - want) / diag);
                }
        }
    }
    dart_isolation(label, shape, opts, base, ev.get(), fig_);
    if (bfr35_rules) {
        fig_.random_bfr_points += fig_.bfr_points - bfr_points_before;
        fig_.random_ref_points += fig_.ref_points - ref_points_before;
        fig_.worst_pos_random = std::max(fig_.worst_pos_random, fig_.worst_pos_bfr);
        fig_.worst_deriv_random = std::max(fig_.worst_deriv_random, fig_.worst_deriv_bfr);
        fig_.worst_ref_random = std::max(fig_.worst_ref_random, fig_.worst_ref);
        fig_.worst_pos_bfr = std::max(fig_.worst_pos_bfr, worst_pos_before);
        fig_.worst_deriv_bfr = std::max(fig_.worst_deriv_bfr, worst_deriv_before);
        fig_.worst_ref = std::max(fig_.worst_ref, worst_ref_before);
    }
}

}  // namespace

int main() {
    Checker c("conformance_eval");
    Figures fig;
    ShapeRun runner(c, fig);
    const Config configs[] = {
        {Sdc::Options::VTX_BOUNDARY_NONE, Sdc::Options::CREASE_UNIFORM},
        {Sdc::Options::VTX_BOUNDARY_EDGE_ONLY, Sdc::Options::CREASE_UNIFORM},
        {Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER, Sdc::Options::CREASE_UNIFORM},
        {Sdc::Options::VTX_BOUNDARY_NONE, Sdc::Options::CREASE_CHAIKIN},
        {Sdc::Options::VTX_BOUNDARY_EDGE_ONLY, Sdc::Options::CREASE_CHAIKIN},
        {Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER, Sdc::Options::CREASE_CHAIKIN},
    };
    std::string dir = profsubd_test::osd_shapes_dir();
    int shapes = 0;
    if (dir.empty()) {
        c.note("OpenSubdiv shapes not found at " + profsubd_test::osd_shapes_dir_searched() +
               " (set PROFSUBD_OSD_SHAPES): testing generated meshes only");
    } else {
        for (const std::string &path : profsubd_test::list_obj_files(dir)) {
            OsdShape shape;
            std::string err;
            if (!c.check(profsubd_test::read_osd_shape(path, &shape, &err), path + ": " + err)) continue;
            ++shapes;
            std::string label = profsubd_test::shape_name(path);
            c.set_context(label);
            auto t0 = std::chrono::steady_clock::now();
            runner.run(label, shape, shape.options, 10000, 17u * shapes);
            for (const Config &k : configs) {
                if (label == "catmark_pole360") break;
                Sdc::Options o = shape.options;
                if (o.GetVtxBoundaryInterpolation() == k.boundary && o.GetCreasingMethod() == k.crease) continue;
                o.SetVtxBoundaryInterpolation(k.boundary);
                o.SetCreasingMethod(k.crease);
                runner.run(label, shape, o, 2000, 31u * shapes + k.boundary * 2 + k.crease);
            }
            if (std::getenv("PROFSUBD_VERBOSE"))
                std::printf("%s: %.2f s\n", label.c_str(),
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        c.check(shapes == (int)profsubd_test::kExpectedShapeCount, "all shapes read");
    }
    // Randomized meshes (random_mesh.h), each under one boundary rule / crease method.
    auto t_random = std::chrono::steady_clock::now();
    for (unsigned seed = 1; seed <= 16; ++seed) {
        std::string label = "random" + std::to_string(seed);
        c.set_context(label);
        OsdShape shape = profsubd_test::random_mesh(seed);
        const Config &k = configs[seed % 6];
        shape.options.SetVtxBoundaryInterpolation(k.boundary);
        shape.options.SetCreasingMethod(k.crease);
        runner.run(label, shape, shape.options, 8000, 1000u + seed, true);
    }
    double random_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_random).count();
    c.set_context("");
    char b[1024];
    std::snprintf(b, sizeof b,
                  "%d shapes; %ld points vs Bfr (worst position %.2e x diagonal, "
                  "worst derivative %.2e relative), %ld under Chaikin with semi-sharp creases vs Far's "
                  "PatchTable (worst %.2e x diagonal), "
                  "%ld vs exact refinement near irregular corners (worst %.2e); %ld points near irregular "
                  "corners not compared with Bfr; Bfr declined %ld points (profsubd evaluated %ld of them)",
                  shapes, fig.bfr_points, fig.worst_pos_bfr, fig.worst_deriv_bfr, fig.patch_points,
                  fig.worst_pos_patch, fig.ref_points, fig.worst_ref, fig.near_points,
                  fig.bfr_declined, fig.bfr_declined_ours_ok);
    c.note(b);
    c.note("PatchTable's largest deviation under Chaikin at: " + fig.patch_where);
    std::snprintf(b, sizeof b,
                  "16 randomized meshes (%.1f s): %ld points vs Bfr (worst position %.2e x diagonal, worst "
                  "derivative %.2e relative), %ld vs exact refinement (worst %.2e); %ld random points on faces "
                  "OpenSubdiv 3.5's Bfr must not see (those faces are checked at dyadic points against the exact "
                  "refinement only)",
                  random_seconds, fig.random_bfr_points, fig.worst_pos_random, fig.worst_deriv_random,
                  fig.random_ref_points, fig.worst_ref_random, fig.bfr35_avoided);
    c.note(b);
    std::snprintf(b, sizeof b,
                  "measured OpenSubdiv deviation: Bfr vs profsubd where Bfr is not exact (near irregular "
                  "corners, Chaikin with semi-sharp creases): max %.3e x diagonal at %s; Bfr vs exact "
                  "refinement at the reference points: max %.3e x diagonal",
                  fig.bfr_near_dev, fig.bfr_near_where.c_str(), fig.bfr_ref_dev);
    c.note(b);
    std::snprintf(b, sizeof b,
                  "Osd::CpuEvaluator::EvalPatches over Osd::CpuPatchTable (float, as in 3.5): %ld points; vs Far's "
                  "PatchTable (same patches, doubles) worst position %.2e x max(diagonal, largest coordinate) M, "
                  "derivative %.2e x M x 2^patch depth (%s): Osd must agree with the PatchTable up to float rounding, not "
                  "to 1e-15, since 3.5's Osd has no double path",
                  fig.osd_points, fig.osd_far_pos, fig.osd_far_deriv, fig.osd_far_where.c_str());
    c.note(b);
    std::snprintf(b, sizeof b,
                  "where the PatchTable is exact (%ld points): Osd vs profsubd worst position %.2e x M, derivative %.2e "
                  "x M x 2^depth (%s); Far's PatchTable vs profsubd %.2e x diagonal, derivative %.2e relative; at %ld "
                  "dyadic points vs exact refinement: PatchTable %.2e, Osd %.2e; of those points %ld under Chaikin "
                  "with semi-sharp features, Osd vs profsubd there %.2e x M",
                  fig.osd_exact_points, fig.osd_pos, fig.osd_deriv, fig.osd_where.c_str(), fig.patch_pos,
                  fig.patch_deriv, fig.osd_ref_points, fig.patch_ref, fig.osd_ref, fig.osd_chaikin_points,
                  fig.osd_chaikin_dev);
    c.note(b);
    std::snprintf(b, sizeof b,
                  "under Chaikin with semi-sharp features Bfr is off Far's PatchTable (> 1e-12 x diagonal) at %ld "
                  "random points, up to %.2e x diagonal (%s), all on the %ld faces (summed over runs) `profsubd "
                  "check` lists for its Chaikin hazard; faces repeating a vertex: Bfr declines %zu of %zu (no surface)",
                  fig.chaikin_bfr_off, fig.chaikin_bfr_max, fig.chaikin_bfr_where.c_str(), fig.chaikin_listed_faces,
                  fig.repeat_declined.size(), fig.repeat_faces.size());
    c.note(b);
    std::string darts = "Far's PatchTable at " + std::to_string(fig.darts) +
                        " darts (all runs) vs the exact limit, x diagonal, by isolation level: at the vertex / at "
                        "2^-(level+2) from it / at 2^-(level-2) from it:";
    for (int level = 2; level <= 10; level += 2) {
        std::snprintf(b, sizeof b, " %d: %.2e / %.2e / %.2e (%s);", level, fig.dart_at[level], fig.dart_inside[level],
                      fig.dart_outside[level], fig.dart_where[level].c_str());
        darts += b;
    }
    c.note(darts);
    return c.finish();
}
