// The exact limit of deeply refined vertices as the reference for profsubd's (face, u, v)
// evaluator (through the C API), and OpenSubdiv's own deviations from it.
//
// Meshes: every OpenSubdiv shape (*.obj of the shapes folder), the meshes of examples/ and 16
// randomized meshes (random_mesh.h), each under the 3 boundary rules x 2 crease methods.
// Points: the face-point child and the edge-point children of sampled faces of levels 0..5,
// i.e. refined vertices of levels 1..6 (at most kFacesPerLevel faces per level, taken at a
// regular stride; the deepest level is lowered for large meshes so that Far's uniform
// refinement stays below kMaxRefinedFaces faces). A level-L face covers the sub-square of its
// base face (Ptex face: a quad, or a non-quad's sub-face) that Far's child order gives (child
// quad j keeps its parent's corner j at position j; a non-quad's level-1 children are its Ptex
// sub-faces, corner 0 at the base vertex): its face point is the limit surface at the centre
// of that square, the edge point of its edge k at the middle of side k.
//
// Reference, computed here without profsubd's evaluator or limit code:
//  - Far's uniform refinement (Far::PrimvarRefinerReal<double>) to level L;
//  - the refined vertex's sharpness: a face point is smooth with smooth edges, at every level
//    after too: its limit is the Catmull-Clark smooth limit mask (n^2 v + 4 sum e + sum f) /
//    (n (n + 5)) on its level-L ring. An edge point whose two halves are infinitely sharp
//    (boundary, non-manifold and infinitely sharp edges) is a crease vertex for ever: (e_a +
//    4 v + e_b) / 6 on the two halves' ends. Smooth halves: the smooth mask. Semi-sharp halves:
//    the point's one-ring is refined further with Sdc::Crease's sharpness rules (Chaikin's
//    average at each end of each edge, using the edges around the far end as Far's level L
//    lists them) and the Catmull-Clark masks (edge: crease / smooth / Far's blend by the
//    parent sharpness; vertex: smooth, crease, corner, blended by the fractional weight of
//    Sdc::Crease) until its edges' sharpness is 0 or infinite, then the smooth or crease
//    limit mask. (Edge points are interior manifold valence-4 vertices there; their halves
//    decay together, so no dart remains at the end.)
// profsubd must match to 1e-12 x bounding-box diagonal at every point with a limit surface
// (Bfr::SurfaceFactory::FaceHasLimitSurface of the base face); points on base faces touching a
// face that repeats a vertex are not compared (profsubd is exact there only outside 2^-d of
// that vertex, see its README) and counted.
//
// OpenSubdiv, measured against the same reference and printed (not checked): Far's
// PatchTable + PatchMap (adaptive, isolation 10, Gregory end caps, infinitely sharp patches;
// exact everywhere but within 2^-10 of darts and extraordinary vertices: the only such points
// here are the centres of non-quads at level 1, left out) and Bfr::Surface<double>
// (approximation level 10; faces OpenSubdiv 3.5's Bfr must not see are left out, as in
// conformance_eval). The PatchTable is not built for meshes with a valence-2 dart (3.5's
// Far::SourcePatch writes out of bounds there).

#include "capi_mesh.h"
#include "far_points.h"
#include "osd_references.h"
#include "osd_shape.h"
#include "random_mesh.h"
#include "test_support.h"
#include "vec3.h"

#include <profsubd.h>

#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/sdc/crease.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace OpenSubdiv;
using profsubd_test::Checker;
using profsubd_test::OsdShape;
using profsubd_test::V3;

namespace {

constexpr int kMaxLevel = 6;
constexpr int kFacesPerLevel = 40;
constexpr long kMaxRefinedFaces = 250000;
constexpr double kTolerance = 1e-12;


// Where a refined face lies: Ptex face and the square [u0, u0 + size] x [v0, v0 + size].
struct Region {
    int ptex = 0;
    double u0 = 0, v0 = 0, size = 1;
};

// The largest deviation of one kind and where it occurred.
struct Worst {
    double dev = 0;
    long points = 0, above = 0;  // points compared, points above kTolerance
    std::string where;
    void add(double d, const std::string &w) {
        ++points;
        above += d > kTolerance;
        if (d > dev) {
            dev = d;
            where = w;
        }
    }
};

struct Figures {
    Worst ours;
    Worst patch[2], bfr[2];  // per crease method (0 uniform, 1 chaikin)
    long face_points = 0, edge_points = 0, continued = 0, no_surface = 0, degenerate = 0,
         unhandled = 0, patch_skipped_meshes = 0;
    long per_level[kMaxLevel + 1] = {};
    std::string shallow;  // meshes whose deepest level is below kMaxLevel
};

// One refined vertex's one-ring (interior, manifold, quads): ends x[i], the opposite corner
// o[i] of the face between x[i] and x[i+1], edge sharpness s[i] and the sharpness of every
// edge around each end (what Chaikin averages there).
struct Ring {
    V3 w;
    std::vector<V3> x, o;
    std::vector<float> s;
    std::vector<std::vector<float>> around;
};

bool is_semi(float s) { return s > 0 && s < Sdc::Crease::SHARPNESS_INFINITE; }

V3 smooth_limit(const Ring &r) {
    double n = (double)r.x.size();
    V3 p = n * n * r.w;
    for (size_t i = 0; i < r.x.size(); ++i) p = p + 4.0 * r.x[i] + r.o[i];
    return (1.0 / (n * (n + 5.0))) * p;
}

// Refine the ring until no edge around it is semi-sharp, then apply the limit mask.
// False for a dart or corner at the end (not met by edge points; reported if it is).
bool ring_limit(Ring r, const Sdc::Options &options, V3 *out) {
    Sdc::Crease crease(options);
    const int n = (int)r.x.size();
    for (int level = 0; level < 16; ++level) {
        bool semi = false;
        for (float s : r.s) semi = semi || is_semi(s);
        if (!semi) break;
        std::vector<V3> fp(n), x(n);
        for (int i = 0; i < n; ++i) fp[i] = 0.25 * (r.w + r.x[i] + r.o[i] + r.x[(i + 1) % n]);
        std::vector<float> cw(n), cx(n);
        crease.SubdivideEdgeSharpnessesAroundVertex(n, r.s.data(), cw.data());
        for (int i = 0; i < n; ++i) {
            cx[i] = crease.SubdivideEdgeSharpnessAtVertex(r.s[i], (int)r.around[i].size(), r.around[i].data());
            V3 smooth = 0.25 * (r.w + r.x[i] + fp[(i + n - 1) % n] + fp[i]);
            V3 sharp = 0.5 * (r.w + r.x[i]);
            if (r.s[i] <= 0) {
                x[i] = smooth;
            } else if (cw[i] > 0 && cx[i] > 0) {
                x[i] = sharp;  // the child is a crease
            } else {
                // Far's transition for an edge point: blend by the parent's sharpness.
                double p = r.s[i];
                x[i] = p * sharp + (1.0 - p) * smooth;
            }
        }
        auto mask = [&](Sdc::Crease::Rule rule, const std::vector<float> &s) {
            if (rule == Sdc::Crease::RULE_SMOOTH || rule == Sdc::Crease::RULE_DART) {
                V3 p = ((n - 2.0) / n) * r.w;
                for (int i = 0; i < n; ++i) p = p + (1.0 / (n * n)) * (r.x[i] + fp[i]);
                return p;
            }
            if (rule == Sdc::Crease::RULE_CREASE) {
                int ends[2];
                crease.GetSharpEdgePairOfCrease(s.data(), n, ends);
                return 0.75 * r.w + 0.125 * (r.x[ends[0]] + r.x[ends[1]]);
            }
            return r.w;
        };
        Sdc::Crease::Rule pr = crease.DetermineVertexVertexRule(0.0f, n, r.s.data());
        Sdc::Crease::Rule cr = crease.DetermineVertexVertexRule(0.0f, n, cw.data());
        V3 w = mask(pr, r.s);
        if (pr != cr && pr != Sdc::Crease::RULE_SMOOTH && pr != Sdc::Crease::RULE_DART) {
            double pw = crease.ComputeFractionalWeightAtVertex(0.0f, 0.0f, n, r.s.data(), cw.data());
            w = pw * w + (1.0 - pw) * mask(cr, cw);
        }
        r.w = w;
        r.x = x;
        r.o = fp;
        for (int i = 0; i < n; ++i) r.around[i] = {cw[i], cx[i], 0.0f, 0.0f};  // an edge point's 4 edges
        r.s = cw;
    }
    int sharp = 0, a = -1, b = -1;
    for (int i = 0; i < n; ++i) {
        if (is_semi(r.s[i])) return false;
        if (r.s[i] > 0) {
            (a < 0 ? a : b) = i;
            ++sharp;
        }
    }
    if (sharp == 0) {
        *out = smooth_limit(r);
        return true;
    }
    if (sharp == 2) {
        *out = (1.0 / 6.0) * (r.x[a] + 4.0 * r.w + r.x[b]);
        return true;
    }
    return false;
}

class DeepRun {
public:
    DeepRun(Checker &c, Figures &fig) : c_(c), fig_(fig) {}
    void run(const std::string &label, const OsdShape &shape, const Sdc::Options &opts);

private:
    // The exact limit of vertex w of level `l`; false if not handled.
    bool exact_limit(int l, int w, V3 *out);
    V3 pos(int l, int v) const {
        const auto &p = points_[offsets_[l] + v].p;
        return {p[0], p[1], p[2]};
    }

    Checker &c_;
    Figures &fig_;
    const Far::TopologyRefiner *refiner_ = nullptr;
    Sdc::Options options_;
    std::vector<profsubd_test::FarPoint> points_;
    std::vector<int> offsets_;
};

bool DeepRun::exact_limit(int l, int w, V3 *out) {
    const Far::TopologyLevel &L = refiner_->GetLevel(l);
    auto edges = L.GetVertexEdges(w);
    auto faces = L.GetVertexFaces(w);
    const int n = edges.size();
    int sharp = 0, semi = 0, ends[2] = {-1, -1};
    for (int i = 0; i < n; ++i) {
        float s = L.GetEdgeSharpness(edges[i]);
        auto ev = L.GetEdgeVertices(edges[i]);
        if (s >= Sdc::Crease::SHARPNESS_INFINITE && sharp < 2) ends[sharp] = ev[0] == w ? ev[1] : ev[0];
        sharp += s > 0;
        semi += is_semi(s);
    }
    if (L.GetVertexSharpness(w) > 0) return false;
    if (semi == 0 && sharp == 2 && ends[1] >= 0) {
        *out = (1.0 / 6.0) * (pos(l, ends[0]) + 4.0 * pos(l, w) + pos(l, ends[1]));
        return true;
    }
    if ((semi == 0 && sharp != 0) || L.IsVertexBoundary(w) || L.IsVertexNonManifold(w) ||
        faces.size() != n)
        return false;
    // Interior manifold: order the faces round w, each face after the one whose edge out of w
    // it comes back in by (face i: w, x[i+1], o[i], x[i]).
    Ring r;
    r.w = pos(l, w);
    std::vector<int> next(n), opp(n), prev(n);
    for (int i = 0; i < n; ++i) {
        auto fv = L.GetFaceVertices(faces[i]);
        if (fv.size() != 4) return false;
        int k = fv.FindIndex(w);
        next[i] = fv[(k + 1) % 4];
        opp[i] = fv[(k + 2) % 4];
        prev[i] = fv[(k + 3) % 4];
    }
    std::vector<int> xs;
    int f = 0;
    for (int step = 0; step < n; ++step) {
        xs.push_back(prev[f]);
        r.o.push_back(pos(l, opp[f]));
        int g = -1;
        for (int j = 0; j < n; ++j)
            if (prev[j] == next[f]) g = j;
        if (g < 0) return false;
        f = g;
    }
    if (f != 0) return false;
    for (int x : xs) {
        r.x.push_back(pos(l, x));
        r.s.push_back(L.GetEdgeSharpness(L.FindEdge(w, x)));
        std::vector<float> around;
        auto xe = L.GetVertexEdges(x);
        for (int i = 0; i < xe.size(); ++i) around.push_back(L.GetEdgeSharpness(xe[i]));
        r.around.push_back(around);
    }
    if (semi == 0) {
        *out = smooth_limit(r);
        return true;
    }
    ++fig_.continued;
    return ring_limit(r, options_, out);
}

void DeepRun::run(const std::string &label, const OsdShape &shape, const Sdc::Options &opts) {
    static const char *bnames[] = {"none", "edge-only", "edge-and-corner"};
    static const char *mnames[] = {"uniform", "chaikin"};
    const int method = opts.GetCreasingMethod() == Sdc::Options::CREASE_CHAIKIN;
    const std::string config =
        label + " [" + bnames[opts.GetVtxBoundaryInterpolation()] + "/" + mnames[method] + "]";
    std::unique_ptr<Far::TopologyRefiner> refiner = profsubd_test::build_refiner(shape, opts);
    if (!c_.check(refiner != nullptr, config + ": Far rejects the mesh")) return;
    const Far::TopologyLevel &base = refiner->GetLevel(0);
    const double diag = profsubd_test::bbox_diagonal(shape.positions);
    options_ = opts;

    int levels = kMaxLevel;
    while (levels > 1 && (long)base.GetNumFaceVertices() << (2 * (levels - 1)) > kMaxRefinedFaces) --levels;
    if (levels < kMaxLevel && method == 0 && opts.GetVtxBoundaryInterpolation() == 0)
        fig_.shallow += " " + label + " (" + std::to_string(levels) + ")";
    Far::TopologyRefiner::UniformOptions uo(levels);
    uo.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uo);
    refiner_ = refiner.get();
    points_ = profsubd_test::refine_points(*refiner, shape.positions);
    offsets_.assign(levels + 1, 0);
    for (int l = 1; l <= levels; ++l) offsets_[l] = offsets_[l - 1] + refiner->GetLevel(l - 1).GetNumVertices();

    std::string err;
    profsubd_test::EvaluatorPtr ev = profsubd_test::new_evaluator_capi(shape, opts, &err);
    if (!c_.check(ev != nullptr, config + ": " + err)) return;

    // OpenSubdiv's evaluators, measured.
    std::unique_ptr<Far::TopologyRefiner> base_refiner = profsubd_test::build_refiner(shape, opts);
    profsubd_test::Bfr35Faces bfr35 = profsubd_test::bfr35_faces(base_refiner->GetLevel(0));
    std::vector<bool> dart2_face(base.GetNumFaces(), false), int2_face(base.GetNumFaces(), false);
    bool has_dart2 = false;
    for (int v = 0; v < base.GetNumVertices(); ++v) {
        auto vf = base.GetVertexFaces(v);
        if (base.IsVertexBoundary(v) || vf.size() != 2) continue;
        int inf = 0;
        auto ve = base.GetVertexEdges(v);
        for (int i = 0; i < ve.size(); ++i) inf += base.GetEdgeSharpness(ve[i]) >= 10.0f;
        has_dart2 = has_dart2 || inf == 1;
        for (int i = 0; i < vf.size(); ++i) {
            dart2_face[vf[i]] = dart2_face[vf[i]] || inf == 1;
            int2_face[vf[i]] = true;
        }
    }
    profsubd_test::BfrFactories bfr_factories(*base_refiner);
    Bfr::RefinerSurfaceFactory<> &cached = bfr_factories.cached, &uncached = bfr_factories.uncached;
    std::unique_ptr<profsubd_test::PatchTableEvaluator> patch_table;
    if (has_dart2) {
        ++fig_.patch_skipped_meshes;
    } else {
        patch_table.reset(new profsubd_test::PatchTableEvaluator(shape, opts));
    }

    // Base faces touching a face that repeats a vertex.
    std::vector<bool> degenerate_vertex(base.GetNumVertices(), false), near_degenerate(base.GetNumFaces(), false);
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        auto fv = base.GetFaceVertices(f);
        for (int a = 0; a < fv.size(); ++a)
            for (int b = a + 1; b < fv.size(); ++b)
                if (fv[a] == fv[b]) degenerate_vertex[fv[a]] = true;
    }
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        auto fv = base.GetFaceVertices(f);
        for (int a = 0; a < fv.size(); ++a) near_degenerate[f] = near_degenerate[f] || degenerate_vertex[fv[a]];
    }

    Far::PtexIndices ptex(*refiner);
    std::vector<int> ptex_base(ptex.GetNumFaces()), ptex_sub(ptex.GetNumFaces());
    for (int f = 0; f < base.GetNumFaces(); ++f) {
        int n = base.GetFaceVertices(f).size();
        for (int k = 0; k < (n == 4 ? 1 : n); ++k) {
            ptex_base[ptex.GetFaceId(f) + k] = f;
            ptex_sub[ptex.GetFaceId(f) + k] = n == 4 ? -1 : k;
        }
    }

    Bfr::Surface<double> surface;
    std::vector<double> bfr_points;
    // `patch_exact`: false at the centre of a non-quad (an extraordinary vertex).
    auto check_point = [&](int level, int w, bool face_point, int ptex_face, double u, double v,
                           bool patch_exact = true) {
        int f = ptex_base[ptex_face];
        if (!cached.FaceHasLimitSurface(f)) {
            ++fig_.no_surface;
            return;
        }
        if (near_degenerate[f]) {
            ++fig_.degenerate;
            return;
        }
        V3 want;
        if (!exact_limit(level, w, &want)) {
            ++fig_.unhandled;
            c_.check(false, config + ": no exact limit for vertex " + std::to_string(w) + " of level " +
                                std::to_string(level));
            return;
        }
        ++fig_.per_level[level];
        ++(face_point ? fig_.face_points : fig_.edge_points);
        std::ostringstream where;
        where << config << " L" << level << (face_point ? " face point" : " edge point") << " at face " << ptex_face
              << " (" << u << ", " << v << ")";
        uint32_t face = (uint32_t)ptex_face;
        double p[3];
        profsubd_status s = profsubd_evaluator_evaluate(ev.get(), &face, &u, &v, 1, p, nullptr, nullptr);
        if (!c_.check(s == PROFSUBD_OK, where.str() + ": " + profsubd_test::describe_status(s))) return;
        double d = norm(V3{p[0], p[1], p[2]} - want) / diag;
        fig_.ours.add(d, where.str());
        if (!c_.check(d <= kTolerance, where.str() + ": profsubd off by " + std::to_string(d) + " x diagonal")) return;
        double tp[3];
        if (patch_table && patch_exact && patch_table->evaluate(ptex_face, u, v, tp))
            fig_.patch[method].add(norm(V3{tp[0], tp[1], tp[2]} - want) / diag, where.str());
        if (dart2_face[f] || bfr35.avoid[f]) return;  // never given to 3.5's Bfr
        if ((int2_face[f] || bfr35.near_val2[f] ? uncached : cached).InitVertexSurface(f, &surface)) {
            bfr_points.resize(3 * surface.GetNumPatchPoints());
            surface.PreparePatchPoints(shape.positions.data(), 3, bfr_points.data(), 3);
            double uv[2] = {u, v}, bp[3];
            if (ptex_sub[ptex_face] >= 0) {
                double sv[2] = {u, v};
                surface.GetParameterization().ConvertNormalizedSubFaceToCoord(ptex_sub[ptex_face], sv, uv);
            }
            surface.Evaluate(uv, bfr_points.data(), 3, bp);
            fig_.bfr[method].add(norm(V3{bp[0], bp[1], bp[2]} - want) / diag, where.str());
        }
    };

    // Regions of the faces of the current level (level >= 1).
    std::vector<Region> regions;
    for (int level = 1; level <= levels; ++level) {
        const Far::TopologyLevel &parent = refiner->GetLevel(level - 1);
        const int nf = parent.GetNumFaces();
        const int stride = std::max(1, (nf + kFacesPerLevel - 1) / kFacesPerLevel);
        for (int g = 0; g < nf; g += stride) {
            auto fe = parent.GetFaceEdges(g);
            const int n = fe.size();
            if (level == 1) {
                int first = ptex.GetFaceId(g);
                if (n == 4) {
                    check_point(1, parent.GetFaceChildVertex(g), true, first, 0.5, 0.5);
                    const double mu[4] = {0.5, 1, 0.5, 0}, mv[4] = {0, 0.5, 1, 0.5};
                    for (int k = 0; k < 4; ++k) check_point(1, parent.GetEdgeChildVertex(fe[k]), false, first, mu[k], mv[k]);
                } else {
                    // The centre of a non-quad is an extraordinary vertex (valence n): exact in
                    // profsubd, not in the PatchTable; its edge midpoints are (1, 0) of sub-face k.
                    check_point(1, parent.GetFaceChildVertex(g), true, first, 1.0, 1.0, false);
                    for (int k = 0; k < n; ++k) check_point(1, parent.GetEdgeChildVertex(fe[k]), false, first + k, 1.0, 0.0);
                }
                continue;
            }
            const Region &r = regions[g];
            const double h = 0.5 * r.size;
            check_point(level, parent.GetFaceChildVertex(g), true, r.ptex, r.u0 + h, r.v0 + h);
            const double mu[4] = {h, 2 * h, h, 0}, mv[4] = {0, h, 2 * h, h};
            for (int k = 0; k < 4; ++k)
                check_point(level, parent.GetEdgeChildVertex(fe[k]), false, r.ptex, r.u0 + mu[k], r.v0 + mv[k]);
        }
        // Regions of this level's faces, for the next.
        const Far::TopologyLevel &child = refiner->GetLevel(level);
        std::vector<Region> next(child.GetNumFaces());
        for (int g = 0; g < nf; ++g) {
            auto kids = parent.GetFaceChildFaces(g);
            for (int j = 0; j < kids.size(); ++j) {
                Region q;
                if (level == 1) {
                    q.ptex = ptex.GetFaceId(g) + (kids.size() == 4 ? 0 : j);
                    if (kids.size() != 4) {
                        next[kids[j]] = q;
                        continue;
                    }
                } else {
                    q = regions[g];
                }
                q.size *= 0.5;
                q.u0 += (j == 1 || j == 2) ? q.size : 0.0;
                q.v0 += (j == 2 || j == 3) ? q.size : 0.0;
                next[kids[j]] = q;
            }
        }
        regions.swap(next);
    }
}

void print_worst(const Checker &c, const std::string &what, const Worst &w) {
    char b[256];
    std::snprintf(b, sizeof b, "%s: %ld points, max %.2e x diagonal, %ld above 1e-12; worst at ", what.c_str(),
                  w.points, w.dev, w.above);
    c.note(b + w.where);
}

}  // namespace

int main() {
    Checker c("conformance_deep");
    Figures fig;
    DeepRun runner(c, fig);
    auto t0 = std::chrono::steady_clock::now();
    auto all_configs = [&](const std::string &label, OsdShape shape) {
        c.set_context(label);
        for (int b = 0; b < 3; ++b)
            for (int m = 0; m < 2; ++m) {
                shape.options.SetVtxBoundaryInterpolation((Sdc::Options::VtxBoundaryInterpolation)b);
                shape.options.SetCreasingMethod((Sdc::Options::CreasingMethod)m);
                runner.run(label, shape, shape.options);
            }
    };
    int meshes = 0;
    std::string dir = profsubd_test::osd_shapes_dir();
    if (dir.empty()) {
        c.note("OpenSubdiv shapes not found at " + profsubd_test::osd_shapes_dir_searched() +
               " (set PROFSUBD_OSD_SHAPES): testing project and randomized meshes only");
    } else {
        int shapes = 0;
        for (const std::string &path : profsubd_test::list_obj_files(dir)) {
            OsdShape shape;
            std::string err;
            if (!c.check(profsubd_test::read_osd_shape(path, &shape, &err), path + ": " + err)) continue;
            ++shapes;
            all_configs(profsubd_test::shape_name(path), shape);
        }
        c.check(shapes == (int)profsubd_test::kExpectedShapeCount, "all shapes read");
        meshes += shapes;
    }
    const std::string source = __FILE__;
    const std::string examples = source.substr(0, source.rfind("/cpp_tests/")) + "/examples";
    for (const char *sub : {"meshes", "profiles", "sweeps"}) {
        for (const std::string &path : profsubd_test::list_obj_files(examples + "/" + sub)) {
            OsdShape shape;
            std::string err;
            if (!c.check(profsubd_test::read_osd_shape(path, &shape, &err), path + ": " + err)) continue;
            ++meshes;
            all_configs(profsubd_test::shape_name(path), shape);
        }
    }
    for (unsigned seed = 1; seed <= 16; ++seed) {
        ++meshes;
        all_configs("random" + std::to_string(seed), profsubd_test::random_mesh(seed));
    }
    c.set_context("");
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char b[512];
    std::snprintf(b, sizeof b,
                  "%d meshes x 6 configurations (%.0f s): %ld face points and %ld edge points (levels 1-6: %ld %ld "
                  "%ld %ld %ld %ld), %ld of them refined further until their sharpness decayed; skipped: %ld without "
                  "limit surface, %ld next to a face repeating a vertex, %ld unhandled",
                  meshes, seconds, fig.face_points, fig.edge_points, fig.per_level[1], fig.per_level[2],
                  fig.per_level[3], fig.per_level[4], fig.per_level[5], fig.per_level[6], fig.continued,
                  fig.no_surface, fig.degenerate, fig.unhandled);
    c.note(b);
    c.note("deepest level below 6 (refined faces capped):" + fig.shallow);
    print_worst(c, "profsubd vs exact", fig.ours);
    static const char *m[] = {"uniform", "chaikin"};
    for (int k = 0; k < 2; ++k) {
        print_worst(c, std::string("Far PatchTable (isolation 10) vs exact, ") + m[k], fig.patch[k]);
        print_worst(c, std::string("Bfr (level 10) vs exact, ") + m[k], fig.bfr[k]);
    }
    std::snprintf(b, sizeof b, "PatchTable not built for %ld mesh configurations with a valence-2 dart",
                  fig.patch_skipped_meshes);
    c.note(b);
    return c.finish();
}
