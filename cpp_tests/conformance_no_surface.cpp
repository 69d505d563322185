// Points without limit surface and Bfr's parameterization, profsubd (C API) against
// OpenSubdiv 3.5, over every regression shape under the 3 boundary rules x 2 crease methods:
//
//  1. Faces: a face has a limit surface in profsubd (profsubd_evaluator_evaluate_points'
//     mask, in both domains) exactly when Bfr::SurfaceFactory::FaceHasLimitSurface says so,
//     when InitVertexSurface succeeds, and when Far's PatchTable has a patch at the centre of
//     each of its Ptex faces (PatchMap). Points without surface are NaN; strict mode fails.
//  2. Control vertices: profsubd gives a vertex a limit (mask of
//     profsubd_evaluator_limit_vertices_masked, non-empty stencil rows) exactly when one of its
//     faces has a Bfr surface; the others are NaN. On the shapes of issue 9 (isolated
//     vertices, holes, boundary rule none, non-manifold vertices) the limit of every other
//     vertex equals Bfr at the vertex's corner of *every* face around it that has a surface,
//     where Bfr is exact (not at darts, not under Chaikin creasing with semi-sharp edges).
//  3. Bfr's domain: on every face with a surface (where Bfr is exact: no Chaikin creasing
//     with semi-sharp edges, no faces OpenSubdiv 3.5's Bfr is wrong on, no faces touching a
//     repeated vertex), profsubd at Bfr's own (face, u, v) (PROFSUBD_DOMAIN_BFR) equals
//     Bfr::Surface<double> (approximation level 10) in position and derivatives to 1e-12 x
//     diagonal, at 16 points of each sub-face (Ptex coordinates (2i+1)/8, 1/8 away from every
//     corner); and the same point through Bfr's ConvertCoordToNormalizedSubFace in the Ptex
//     domain gives the same position and half the derivatives, bit for bit.

#include "capi_mesh.h"
#include "osd_shape.h"
#include "random_mesh.h"
#include "test_support.h"

#include <profsubd.h>

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/ptexIndices.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <string>
#include <vector>

using namespace OpenSubdiv;
using profsubd_test::Checker;
using profsubd_test::OsdShape;

namespace {

using Factory = Bfr::RefinerSurfaceFactory<>;

struct EvaluatorDeleter {
    void operator()(profsubd_evaluator *e) const { profsubd_evaluator_free(e); }
};
using EvaluatorPtr = std::unique_ptr<profsubd_evaluator, EvaluatorDeleter>;

struct Figures {
    long faces = 0, faces_without = 0, vertices = 0, vertices_without = 0;
    long corner_checks = 0, bfr_points = 0;
    double worst_corner = 0, worst_pos = 0, worst_deriv = 0;
    std::string worst_deriv_where;
};

double dist3(const double *a, const double *b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

bool has_semi_sharp(const OsdShape &s) {
    for (float x : s.crease_sharpness)
        if (x > 0 && x < 10) return true;
    for (float x : s.corner_sharpness)
        if (x > 0 && x < 10) return true;
    return false;
}

// An interior vertex with exactly one sharp edge (a dart, also a semi-sharp one): Bfr is not
// exact at it.
bool is_dart(const Far::TopologyLevel &L, int v) {
    if (L.IsVertexBoundary(v) || L.IsVertexNonManifold(v)) return false;
    int sharp = 0;
    for (int e : L.GetVertexEdges(v)) sharp += L.GetEdgeSharpness(e) > 0;
    return sharp == 1;
}

const std::set<std::string> kIssueShapes = {"catmark_nonman_bareverts", "catmark_hole_test2", "catmark_edgenone",
                                            "catmark_val2_nonman", "catmark_nonman_verts"};

void check_config(Checker &ck, const std::string &label, const std::string &name, const OsdShape &shape,
                  Figures &fig) {
    std::unique_ptr<Far::TopologyRefiner> refiner = profsubd_test::build_refiner(shape, shape.options);
    if (!ck.check(refiner != nullptr, label + ": Far rejects the shape")) return;
    const Far::TopologyLevel &L = refiner->GetLevel(0);
    const int nf = L.GetNumFaces(), nv = L.GetNumVertices();
    double diag = profsubd_test::bbox_diagonal(shape.positions);
    if (diag == 0.0) diag = 1.0;

    std::string err;
    profsubd_test::MeshPtr mesh = profsubd_test::new_mesh_capi(shape, &err);
    if (!ck.check(mesh != nullptr, label + ": profsubd_mesh_new: " + err)) return;
    profsubd_test::OptionsPtr opts = profsubd_test::capi_options(shape.options);
    profsubd_evaluator *raw = nullptr;
    profsubd_status st = profsubd_evaluator_new(mesh.get(), opts.get(), &raw);
    if (!ck.check(st == PROFSUBD_OK, label + ": evaluator_new: " + profsubd_test::describe_status(st))) return;
    EvaluatorPtr ev(raw);

    Factory::Options fo;
    fo.EnableCaching(false).SetApproxLevelSmooth(10).SetApproxLevelSharp(10);
    Factory factory(*refiner, fo);
    const profsubd_test::Bfr35Faces bfr35 = profsubd_test::bfr35_faces(L);

    // Far's PatchTable (adaptive, isolation 2 is enough to know where patches are).
    std::unique_ptr<Far::TopologyRefiner> adaptive = profsubd_test::build_refiner(shape, shape.options);
    Far::PatchTableFactory::Options po(2);
    po.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    adaptive->RefineAdaptive(po.GetRefineAdaptiveOptions());
    std::unique_ptr<Far::PatchTable> table(Far::PatchTableFactory::Create(*adaptive, po));
    Far::PatchMap pmap(*table);
    Far::PtexIndices ptex(*refiner);

    // 1. Faces.
    std::vector<char> bfr_has(nf, 0);
    std::vector<uint32_t> pfaces, bfaces;
    std::vector<int> pbase;  // base face of each Ptex face in pfaces
    std::vector<double> pu, pv, bu, bv;
    for (int f = 0; f < nf; ++f) {
        bfr_has[f] = factory.FaceHasLimitSurface(f);
        std::string where = label + " face " + std::to_string(f);
        if (!bfr35.avoid[f]) {
            Bfr::Surface<double> surface;
            ck.check(factory.InitVertexSurface(f, &surface) == (bool)bfr_has[f],
                     where + ": InitVertexSurface disagrees with FaceHasLimitSurface");
        }
        int n = L.GetFaceVertices(f).size(), first = ptex.GetFaceId(f);
        for (int k = 0; k < (n == 4 ? 1 : n); ++k) {
            bool patch = pmap.FindPatch(first + k, 0.5, 0.5) != nullptr;
            ck.check(patch == (bool)bfr_has[f], where + " sub-face " + std::to_string(k) +
                                                    ": PatchTable patch " + std::to_string(patch) + ", Bfr " +
                                                    std::to_string(bfr_has[f]));
            pfaces.push_back(first + k);
            pbase.push_back(f);
            pu.push_back(0.5);
            pv.push_back(0.5);
        }
        bfaces.push_back(f);
        bu.push_back(0.25);  // in sub-face 0 of an N-gon, inside a quad
        bv.push_back(0.25);
        fig.faces += 1;
        fig.faces_without += !bfr_has[f];
    }
    for (int domain = 0; domain < 2; ++domain) {
        std::vector<uint32_t> &fs = domain ? bfaces : pfaces;
        std::vector<double> &us = domain ? bu : pu, &vs = domain ? bv : pv;
        size_t n = fs.size();
        std::vector<double> p(3 * n), du(3 * n);
        std::vector<uint8_t> mask(n, 7);
        st = profsubd_evaluator_evaluate_points(ev.get(), domain ? PROFSUBD_DOMAIN_BFR : PROFSUBD_DOMAIN_PTEX, 0,
                                                fs.data(), us.data(), vs.data(), n, p.data(), du.data(), nullptr,
                                                mask.data());
        if (!ck.check(st == PROFSUBD_OK, label + ": evaluate_points: " + profsubd_test::describe_status(st))) continue;
        bool any_without = false;
        for (size_t i = 0; i < n; ++i) {
            bool has = bfr_has[domain ? (int)fs[i] : pbase[i]];
            any_without = any_without || !has;
            ck.check(mask[i] == (has ? 1 : 0) && std::isnan(p[3 * i]) == !has && std::isnan(du[3 * i + 2]) == !has,
                     label + (domain ? " Bfr" : " Ptex") + " face " + std::to_string(fs[i]) + ": profsubd mask " +
                         std::to_string(mask[i]) + ", OpenSubdiv " + std::to_string(has));
        }
        if (any_without) {
            std::vector<double> q(3 * n, 5.0);
            st = profsubd_evaluator_evaluate_points(ev.get(), domain ? PROFSUBD_DOMAIN_BFR : PROFSUBD_DOMAIN_PTEX, 1,
                                                    fs.data(), us.data(), vs.data(), n, q.data(), nullptr, nullptr,
                                                    nullptr);
            ck.check(st == PROFSUBD_ERROR_INVALID_ARGUMENT &&
                         std::string(profsubd_last_error_message()).find("no limit surface") != std::string::npos &&
                         std::all_of(q.begin(), q.end(), [](double x) { return x == 5.0; }),
                     label + ": strict mode fails the batch and writes nothing");
        }
    }

    // 2. Control vertices.
    std::vector<double> vp(3 * nv, 0.0), sp(3 * nv, 0.0);
    std::vector<uint8_t> vmask(nv, 7);
    size_t needed = 0;
    st = profsubd_evaluator_limit_vertices_masked(ev.get(), 0, vp.data(), nullptr, nullptr, vmask.data(), nv, &needed);
    if (!ck.check(st == PROFSUBD_OK, label + ": limit_vertices_masked: " + profsubd_test::describe_status(st))) return;
    profsubd_stencil_table *stencils = nullptr;
    st = profsubd_limit_stencils_new(mesh.get(), opts.get(), PROFSUBD_LIMIT_POSITION, &stencils);
    if (!ck.check(st == PROFSUBD_OK, label + ": limit_stencils_new")) return;
    std::vector<uint32_t> offsets(nv + 1);
    profsubd_stencil_table_get_offsets(stencils, offsets.data(), nv + 1, &needed);
    profsubd_stencil_table_apply(stencils, shape.positions.data(), nv, sp.data(), nv, &needed);
    profsubd_stencil_table_free(stencils);
    const bool chaikin_semi = shape.options.GetCreasingMethod() == Sdc::Options::CREASE_CHAIKIN && has_semi_sharp(shape);
    for (int v = 0; v < nv; ++v) {
        bool has = false;
        for (int f : L.GetVertexFaces(v)) has = has || bfr_has[f];
        std::string where = label + " vertex " + std::to_string(v);
        fig.vertices += 1;
        fig.vertices_without += !has;
        ck.check(vmask[v] == (has ? 1 : 0) && std::isnan(vp[3 * v]) == !has,
                 where + ": profsubd mask " + std::to_string(vmask[v]) + ", OpenSubdiv " + std::to_string(has));
        ck.check((offsets[v] == offsets[v + 1]) == !has && std::isnan(sp[3 * v + 1]) == !has,
                 where + ": empty stencil row iff no surface");
        if (!has || !kIssueShapes.count(name) || chaikin_semi || is_dart(L, v)) continue;
        // Bfr at this vertex's corner of every face around it with a surface.
        auto faces = L.GetVertexFaces(v);
        auto corners = L.GetVertexFaceLocalIndices(v);
        for (int i = 0; i < faces.size(); ++i) {
            int f = faces[i];
            if (!bfr_has[f] || bfr35.avoid[f] || bfr35.near_val2[f]) continue;
            Bfr::Surface<double> surface;
            if (!ck.check(factory.InitVertexSurface(f, &surface), where + ": Bfr declines face " + std::to_string(f)))
                continue;
            std::vector<double> patch(3 * surface.GetNumPatchPoints());
            surface.PreparePatchPoints(shape.positions.data(), 3, patch.data(), 3);
            double uv[2], b[3];
            surface.GetParameterization().GetVertexCoord(corners[i], uv);
            surface.Evaluate(uv, patch.data(), 3, b);
            double d = dist3(&vp[3 * v], b) / diag;
            fig.worst_corner = std::max(fig.worst_corner, d);
            fig.corner_checks += 1;
            char buf[96];
            std::snprintf(buf, sizeof buf, " (%.3g x diagonal)", d);
            ck.check(d <= 1e-12, where + ": limit vs Bfr at its corner of face " + std::to_string(f) + buf);
        }
    }

    // 3. Bfr's domain against Bfr itself, and the round trip through Ptex.
    if (chaikin_semi) return;
    std::vector<char> repeated(nv, 0);
    for (int f = 0; f < nf; ++f) {
        auto fv = L.GetFaceVertices(f);
        for (int a = 0; a < fv.size(); ++a)
            for (int b = a + 1; b < fv.size(); ++b)
                if (fv[a] == fv[b]) repeated[fv[a]] = 1;
    }
    const int stride = std::max(1, nf / 150);  // at most ~150 faces per configuration
    for (int f = 0; f < nf; f += stride) {
        auto fv = L.GetFaceVertices(f);
        bool skip = !bfr_has[f] || bfr35.avoid[f] || bfr35.near_val2[f];
        for (int k = 0; k < fv.size(); ++k) skip = skip || repeated[fv[k]];
        if (skip) continue;
        Bfr::Surface<double> surface;
        if (!factory.InitVertexSurface(f, &surface)) continue;
        std::vector<double> patch(3 * surface.GetNumPatchPoints());
        surface.PreparePatchPoints(shape.positions.data(), 3, patch.data(), 3);
        const Bfr::Parameterization param = surface.GetParameterization();
        const int n = fv.size(), subs = n == 4 ? 1 : n;
        const int sub_stride = std::max(1, subs / 12);
        for (int k = 0; k < subs; k += sub_stride) {
            for (int i = 0; i < 4; ++i) {
                for (int j = 0; j < 4; ++j) {
                    double st2[2] = {(2 * i + 1) / 8.0, (2 * j + 1) / 8.0}, uv[2];
                    if (n == 4) {
                        uv[0] = st2[0];
                        uv[1] = st2[1];
                    } else {
                        param.ConvertNormalizedSubFaceToCoord(k, st2, uv);
                    }
                    double bp[3], bdu[3], bdv[3];
                    surface.Evaluate(uv, patch.data(), 3, bp, bdu, bdv);
                    uint32_t face = f;
                    double p[3], du[3], dv[3];
                    st = profsubd_evaluator_evaluate_points(ev.get(), PROFSUBD_DOMAIN_BFR, 1, &face, &uv[0], &uv[1], 1,
                                                            p, du, dv, nullptr);
                    char where[160];
                    std::snprintf(where, sizeof where, "%s face %d (u, v) = (%.17g, %.17g)", label.c_str(), f, uv[0],
                                  uv[1]);
                    if (!ck.check(st == PROFSUBD_OK, std::string(where) + ": " + profsubd_test::describe_status(st)))
                        continue;
                    fig.bfr_points += 1;
                    double e = dist3(p, bp) / diag;
                    double ed = std::max(dist3(du, bdu), dist3(dv, bdv)) / diag;
                    fig.worst_pos = std::max(fig.worst_pos, e);
                    if (ed > fig.worst_deriv) {
                        fig.worst_deriv = ed;
                        fig.worst_deriv_where = where;
                    }
                    ck.check(e <= 1e-12, std::string(where) + ": position vs Bfr");
                    ck.check(ed <= 1e-12, std::string(where) + ": derivatives vs Bfr");
                    if (n == 4) continue;
                    // Round trip: Bfr's own conversion to the Ptex sub-face.
                    double back[2];
                    int sub = param.ConvertCoordToNormalizedSubFace(uv, back);
                    uint32_t pf = ptex.GetFaceId(f) + sub;
                    double q[3], qu[3], qv[3];
                    st = profsubd_evaluator_evaluate_points(ev.get(), PROFSUBD_DOMAIN_PTEX, 1, &pf, &back[0], &back[1],
                                                            1, q, qu, qv, nullptr);
                    bool same = st == PROFSUBD_OK && sub == k;
                    for (int c = 0; c < 3 && same; ++c)
                        same = q[c] == p[c] && 2.0 * qu[c] == du[c] && 2.0 * qv[c] == dv[c];
                    ck.check(same, std::string(where) + ": Ptex sub-face " + std::to_string(sub) +
                                       " gives the same point and half the derivatives");
                }
            }
        }
    }
}

}  // namespace

int main() {
    Checker ck("conformance_no_surface");
    std::string dir = profsubd_test::osd_shapes_dir();
    if (dir.empty()) {
        ck.note("OpenSubdiv shapes not found (looked in " + profsubd_test::osd_shapes_dir_searched() +
                "); set PROFSUBD_OSD_SHAPES. Nothing to check.");
        return ck.finish();
    }
    const Sdc::Options::VtxBoundaryInterpolation boundaries[] = {
        Sdc::Options::VTX_BOUNDARY_NONE, Sdc::Options::VTX_BOUNDARY_EDGE_ONLY,
        Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER};
    const Sdc::Options::CreasingMethod methods[] = {Sdc::Options::CREASE_UNIFORM, Sdc::Options::CREASE_CHAIKIN};
    const char *bnames[] = {"none", "edge-only", "edge-and-corner"};
    const char *mnames[] = {"uniform", "chaikin"};
    Figures fig;
    auto files = profsubd_test::list_obj_files(dir);
    ck.check(files.size() == profsubd_test::kExpectedShapeCount, "shape count " + std::to_string(files.size()));
    for (const auto &path : files) {
        OsdShape shape;
        std::string err;
        ck.set_context(path);
        if (!ck.check(profsubd_test::read_osd_shape(path, &shape, &err), "read: " + err)) continue;
        std::string name = profsubd_test::shape_name(path);
        for (int b = 0; b < 3; ++b) {
            for (int m = 0; m < 2; ++m) {
                OsdShape s = shape;
                s.options.SetVtxBoundaryInterpolation(boundaries[b]);
                s.options.SetCreasingMethod(methods[m]);
                bool own = s.options.GetVtxBoundaryInterpolation() == shape.options.GetVtxBoundaryInterpolation() &&
                           s.options.GetCreasingMethod() == shape.options.GetCreasingMethod();
                if (name == "catmark_pole360" && !own) continue;  // a valence-360 vertex: slow
                check_config(ck, name + " [" + bnames[b] + ", " + mnames[m] + "]", name, s, fig);
            }
        }
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "faces: %ld (%ld without limit surface, same in Bfr, PatchTable and profsubd); vertices: %ld "
                  "(%ld without)",
                  fig.faces, fig.faces_without, fig.vertices, fig.vertices_without);
    ck.note(line);
    std::snprintf(line, sizeof line,
                  "issue-9 shapes: %ld vertex limits vs Bfr at every surfaced face corner, worst %.3g x diagonal",
                  fig.corner_checks, fig.worst_corner);
    ck.note(line);
    std::snprintf(line, sizeof line,
                  "Bfr domain: %ld points vs Bfr::Surface at its own (face, u, v): worst position %.3g, worst "
                  "derivative %.3g x diagonal (%s)",
                  fig.bfr_points, fig.worst_pos, fig.worst_deriv, fig.worst_deriv_where.c_str());
    ck.note(line);
    return ck.finish();
}
